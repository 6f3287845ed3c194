#!/usr/bin/python3
"""Plots of a `gearfem gearbox` run: gearbox_damage.png (Miner damage per member and mode,
bars, log scale), scuffing_path.png (flash temperature and specific film thickness along
the path of contact of the worst scuffing bin) and gearbox_sn.png (stress against cycles:
the S-N line of each stage's material per mode, and the spectrum bins of every member as
points at (load cycles per spectrum, stress); filled points do damage).

Usage: MPLBACKEND=Agg /usr/bin/python3 scripts/plot_gearbox.py <output folder>
Reads gearbox_life.csv, scuffing_path.csv and gearbox_sn.csv; columns are found by header name (the
" [unit]" suffix stripped). Each PNG is written to a temporary name and renamed into place.
Exits with status 1 and a one-line message when a file is missing.
"""
import csv
import math
import os
import re
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

UNIT = re.compile(r"\s*\[[^\]]*\].*$")


def read(path):
    with open(path, newline="") as f:
        rows = [r for r in csv.reader(f) if r and not r[0].startswith("#")]
    head = [UNIT.sub("", h).strip() for h in rows[0]]
    return [dict(zip(head, r)) for r in rows[1:]]


def save(fig, path):
    tmp = path + ".tmp.png"
    fig.savefig(tmp, dpi=120, bbox_inches="tight")
    plt.close(fig)
    os.replace(tmp, path)


def sn_line(c, n):
    """Stress of the S-N curve at n cycles [MPa] (fatigue.h: semi-log or the ISO life factor)."""
    s_n, N_ref = float(c["sigma_n"]), float(c["N_ref"])
    if c["curve (0 semi-log; 1 ISO)"] in ("0", "0.0"):
        return s_n + float(c["B"]) * math.log10(n / N_ref) if n < N_ref else s_n
    N_s, Y_s = float(c["N_static"]), float(c["Y_static"])
    if n >= N_ref:
        return s_n
    if n <= N_s:
        return s_n * Y_s
    return s_n * Y_s ** (math.log10(n / N_ref) / math.log10(N_s / N_ref))


def plot_sn(out):
    rows = read(os.path.join(out, "gearbox_sn.csv"))
    modes = ["contact", "bending"]
    fig, axes = plt.subplots(1, 2, figsize=(12, 4.8))
    for ax, mode in zip(axes, modes):
        sel = [r for r in rows if r["mode"] == mode and float(r["cycles per spectrum"]) > 0]
        stages = sorted({r["stage"] for r in sel})
        n_all = [float(r["cycles per spectrum"]) for r in sel]
        lo, hi = (min(n_all) / 10, max(n_all) * 10) if n_all else (1e3, 1e10)
        for k, st in enumerate(stages):
            c = next(r for r in sel if r["stage"] == st)
            grid = [lo * (hi / lo) ** (i / 200) for i in range(201)]
            ax.plot(grid, [sn_line(c, n) for n in grid], color=f"C{k}", lw=1.5,
                    label=f"{st} S-N line (sigma_n {float(c['sigma_n']):g} MPa)")
            members = sorted({(r["member"], r["load"]) for r in sel if r["stage"] == st})
            for j, (m, load) in enumerate(members):
                pts = [r for r in sel if r["stage"] == st and r["member"] == m and r["load"] == load]
                x = [float(r["cycles per spectrum"]) for r in pts]
                y = [float(r["stress"]) for r in pts]
                dmg = [float(r["n/N"]) > 0 for r in pts]
                mk = "osD^v<>"[j % 7]
                ax.scatter(x, y, marker=mk, s=18, edgecolors=f"C{k}",
                           facecolors=[f"C{k}" if d else "none" for d in dmg],
                           label=f"{st} {m} ({load})")
        ax.set_xscale("log")
        ax.set_xlabel("load cycles per spectrum (bins) / cycles to failure (lines)")
        ax.set_ylabel(f"{mode} stress [MPa]")
        ax.set_title(f"{mode}: S-N lines and spectrum bins (filled: damaging)")
        ax.legend(fontsize=5.5, loc="best")
    save(fig, os.path.join(out, "gearbox_sn.png"))


def main():
    out = sys.argv[1]
    try:
        life = read(os.path.join(out, "gearbox_life.csv"))
        path = read(os.path.join(out, "scuffing_path.csv"))
    except OSError as e:
        print(f"plot_gearbox: {e}", file=sys.stderr)
        return 1
    labels = [f"{r['stage']} {r['member']} {r['mode']}\n{r['load']}" for r in life]
    D = [float(r["damage D"]) for r in life]
    fig, ax = plt.subplots(figsize=(10, 4.5))
    floor = 1e-12
    ax.bar(range(len(D)), [max(d, floor) for d in D], color=["C3" if d > 0 else "0.8" for d in D])
    ax.set_yscale("log")
    ax.axhline(1.0, color="k", lw=0.8, ls="--")
    ax.set_xticks(range(len(D)))
    ax.set_xticklabels(labels, rotation=75, fontsize=7)
    ax.set_ylabel("Miner damage D per spectrum (grey: none)")
    ax.set_title("Damage per member and mode")
    save(fig, os.path.join(out, "gearbox_damage.png"))

    x = [float(r["roll angle"]) for r in path]
    fig, ax = plt.subplots(figsize=(7, 4))
    ax.plot(x, [float(r["theta_fl"]) for r in path], "C3-o", ms=3, label="flash temperature [K]")
    ax.set_xlabel("roll angle of the pinion [deg]")
    ax.set_ylabel("flash temperature [K]")
    ax2 = ax.twinx()
    ax2.plot(x, [float(r["lambda"]) for r in path], "C0-s", ms=3, label="lambda [-]")
    ax2.set_ylabel("specific film thickness lambda [-]")
    ax.set_title("AGMA 925 along the path of contact (worst bin)")
    save(fig, os.path.join(out, "scuffing_path.png"))
    try:
        plot_sn(out)
    except OSError as e:
        print(f"plot_gearbox: {e}", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
