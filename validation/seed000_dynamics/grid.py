#!/usr/bin/python3
"""Search for the period doubling of Gkimisis 2019 case 2 (20 N m, 1200 rpm): a grid of
initial pinion speed n0 1100-1300 rpm x input torque 15-25 N m, for the analytical-table law
and the Ricker law, with the thesis' ramp and start (100 ms ramp, x(0) = 0, 1 s), two
readings of its initial conditions:
  kinematic: the pair starts at n0 with kinematic speeds (eq. 5.2 read as intended);
  thesis:    eq. 5.2 as the listing codes it, i.e. run at its settled speed n0 (1+r^4)/(1+r^2);
and two integrations:
  thesis: RK4, dt = 1e-5 s, no event location (the listing);
  ours:   RK4, 256 steps per mesh period, event location.
Period = the multiplicity of gearfem's steady-state detection (0: not periodic within 1 s);
modulation = max |x(t+T) - x(t)| / peak-to-peak over the record (T the mesh period).

Usage: grid.py <gearfem> <out dir> <case2 file> <figure.png>   (writes <out>/grid.csv)
"""
import csv
import re
import os
import sys

import numpy as np

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from thesis_runs import read_prm, run, thesis_setup, thesis_speed, variant  # noqa: E402

SPEEDS = [1100 + 25 * i for i in range(9)]
TORQUES = [15, 17.5, 20, 22.5, 25]
LAWS = (("analytical table", "table"), ("Ricker", "Ricker"))


INTEGRATIONS = ("thesis", "ours")


def setup(base, ic, integ, n0, law, torque):
    if ic == "thesis":
        text = thesis_setup(base, n0, law=law, torque=torque)
    else:
        f_mesh = 32 * n0 / 60
        text = variant(base, law=law, torque=torque, speed=n0, ramp_ms=100, rest=True,
                       steps=round(1e5 / f_mesh), event=False, periods=round(f_mesh))
    if integ == "ours":
        text = text.replace("set Event location = false", "set Event location = true")
        text = variant(text, steps=256)
    return text


def modulation(folder):
    """max |x(t+T) - x(t)| / peak-to-peak of the recorded DTE (response.csv, 64 samples/period)."""
    with open(os.path.join(folder, "response.csv")) as f:
        x = np.array([float(r[2]) for r in list(csv.reader(f))[1:] if r])
    n = 64
    return float(np.abs(x[n:] - x[:-n]).max() / max(x.max() - x.min(), 1e-300))


def main():
    gearfem, out, case, png = sys.argv[1:5]
    base = read_prm(case)
    rows = []
    for law, tag in LAWS:
        for ic in ("kinematic", "thesis"):
            for integ in INTEGRATIONS:
                for T in TORQUES:
                    for n0 in SPEEDS:
                        folder = os.path.join(out, "grid", f"{tag}_{ic}_{integ}_{T:g}Nm_{n0}rpm")
                        fig, _ = run(gearfem, setup(base, ic, integ, n0, law, T), folder, plots=False)
                        rows.append({"law": tag, "ICs": ic, "integration": integ, "torque [N m]": T,
                                     "n0 [rpm]": n0,
                                     "run speed [rpm]": thesis_speed(n0) if ic == "thesis" else n0,
                                     "period": fig["period"], "settled": fig["settled"],
                                     "loss": fig["loss"], "rms [um]": fig["rms"],
                                     "modulation": modulation(folder)})
                p2 = [f"{r['n0 [rpm]']} rpm/{r['torque [N m]']:g} N m" for r in rows
                      if r["law"] == tag and r["ICs"] == ic and r["integration"] == integ and r["period"] == 2]
                print(f"{tag} law, {ic} ICs, {integ} integration: period 2 at {', '.join(p2) or 'no grid point'}")
    with open(os.path.join(out, "grid.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0]))
        w.writeheader()
        w.writerows(rows)
    # Every period-2 point of the listing's fixed step again at half the step: a property of the
    # model stays, an artefact of the integration goes.
    half = []
    for r in rows:
        if r["integration"] != "thesis" or r["period"] != 2:
            continue
        law = next(name for name, tag in LAWS if tag == r["law"])
        text = setup(base, r["ICs"], "thesis", r["n0 [rpm]"], law, r["torque [N m]"])
        steps = int(re.search(r"set Steps per period\s*=\s*(\d+)", text).group(1))
        folder = os.path.join(out, "grid_half_step", f"{r['law']}_{r['ICs']}_{r['torque [N m]']:g}Nm_{r['n0 [rpm]']}rpm")
        fig, _ = run(gearfem, variant(text, steps=2 * steps), folder, plots=False)
        half.append({"law": r["law"], "ICs": r["ICs"], "torque [N m]": r["torque [N m]"], "n0 [rpm]": r["n0 [rpm]"],
                     "steps per period": 2 * steps, "period": fig["period"], "modulation": modulation(folder)})
        print(f"half step: {r['law']} law, {r['ICs']} ICs, {r['n0 [rpm]']} rpm / {r['torque [N m]']:g} N m: "
              f"period {fig['period']}")
    with open(os.path.join(out, "grid_half_step.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=["law", "ICs", "torque [N m]", "n0 [rpm]", "steps per period", "period",
                                          "modulation"])
        w.writeheader()
        w.writerows(half)
    fig, axes = plt.subplots(2, 4, figsize=(17, 7), sharex=True, sharey=True)
    marks = {1: ("o", "tab:blue"), 2: ("s", "tab:red"), 3: ("^", "tab:green"), 4: ("D", "tab:purple"),
             0: ("x", "k")}
    for i, (law, tag) in enumerate(LAWS):
        for j, (ic, integ) in enumerate((a, b) for a in ("kinematic", "thesis") for b in INTEGRATIONS):
            ax = axes[i][j]
            for r in (r for r in rows if r["law"] == tag and r["ICs"] == ic and r["integration"] == integ):
                p = int(r["period"] or 0)
                m, col = marks.get(p, ("x", "k"))
                ax.scatter(r["n0 [rpm]"], r["torque [N m]"], marker=m, s=60, c=col,
                           edgecolors=("k" if (r["loss"] or 0) > 0 else "none") if p else None,
                           linewidths=1.2)
            ax.set_title(f"{tag} law, {ic} ICs, {integ} integration", fontsize=9)
            ax.grid(True, alpha=0.3)
            if i == 1:
                ax.set_xlabel("initial pinion speed n0 [rpm]" + (" (run at 2.96 n0)" if ic == "thesis" else ""))
            if j == 0:
                ax.set_ylabel("input torque [N m]")
    handles = [plt.Line2D([], [], ls="", marker=m, color=c, label=f"period {p}" if p else "not periodic")
               for p, (m, c) in marks.items()]
    handles.append(plt.Line2D([], [], ls="", marker="o", mfc="w", mec="k", label="black edge: contact loss"))
    fig.legend(handles=handles, loc="lower center", ncol=6, fontsize=8)
    fig.suptitle("Gkimisis 2019 case 2: period of the steady state (thesis ramp 100 ms, x(0)=0, 1 s; thesis "
                 "integration RK4 dt 1e-5 s without event location, ours RK4 256/period with event location)",
                 fontsize=10)
    fig.tight_layout(rect=(0, 0.05, 1, 0.96))
    tmp = os.path.join(os.path.dirname(os.path.abspath(png)), ".tmp_" + os.path.basename(png))
    fig.savefig(tmp, dpi=110)
    os.replace(tmp, png)


if __name__ == "__main__":
    main()
