#!/usr/bin/python3
"""Speed against error of the dynamic mesh-force laws on Gkimisis 2019 case 2 (20 N m,
1200 rpm, 5 ms ramp), beside the thesis' Table 3 (MATLAB, 1 s at dt = 1/60000 s, RK4:
geometric model 710.6 s, semi-analytical 23.6 s, 30x).

Each law runs with RK4 at 94 steps per mesh period (dt = 1/60160 s, the integer nearest
1/60000 s) and event location, plots off, never declared settled (so all of it is
integrated). Time per simulated second = (wall of a 10 s run - wall of a 1-period run, the
set-up: process start, table generation or file read) / 10, best of `REPEAT` (a 1 s run
integrates in well under the set-up time, too short to time alone). Error = the RMS DTE of
the last 32 mesh periods of a 1 s run (640 mesh periods) against
  (a) the same law at 8x the steps (752 per period): the time-step error;
  (b) the FE-exact table at 752 steps per period (the reference of the comparison: the
      FE-exact T(theta, delta) of the condensed cycle, fe_table_32_60.prm): the model error.

Usage: timing.py <gearfem> <out dir> <case2 file> <FE table .h5>   (writes <out>/timing.csv)
"""
import csv
import os
import sys

from thesis_runs import read_prm, run, variant  # noqa: E402

STEPS, FINE, PERIODS, REPEAT = 94, 752, 640, 3
SECONDS = 10  # timing runs
LAWS = (("analytical table", "table"), ("Ricker", "Ricker"), ("table file", "FE table"))


def setup(base, law, table, steps, periods):
    extra = [("Mesh force", "Table file", table)] if law == "table file" else []
    if periods < 32:
        extra.append(("Analysis", "Recorded periods", str(periods)))
    return variant(base, law=law, steps=steps, periods=periods, never_settle=True, extra=extra)


def main():
    gearfem, out, case, table = sys.argv[1:5]
    base = read_prm(case)
    folder = os.path.join(out, "timing")
    res = {}
    for law, tag in LAWS:
        key = tag.replace(" ", "_")
        walls, walls0 = [], []
        fig, _ = run(gearfem, setup(base, law, table, STEPS, PERIODS), os.path.join(folder, key), plots=False)
        for i in range(REPEAT):
            _, w = run(gearfem, setup(base, law, table, STEPS, SECONDS * PERIODS), os.path.join(folder, key + "_10s"),
                       plots=False)
            _, w0 = run(gearfem, setup(base, law, table, STEPS, 1), os.path.join(folder, key + "_setup"), plots=False)
            walls.append(w)
            walls0.append(w0)
        ref, _ = run(gearfem, setup(base, law, table, FINE, PERIODS), os.path.join(folder, key + "_fine"), plots=False)
        with open(os.path.join(folder, key + ".log")) as f:
            clamps = "outside its range" in f.read()
        res[tag] = {"law": tag, "wall 1 s + set-up [s]": (min(walls) - min(walls0)) / SECONDS + min(walls0),
                    "set-up [s]": min(walls0),
                    "integration per simulated s [s]": max(min(walls) - min(walls0), 1e-6) / SECONDS,
                    "RMS DTE [um]": fig["rms"], "RMS DTE fine [um]": ref["rms"],
                    "loss": fig["loss"], "fn [Hz]": fig["fn"], "table clamped": clamps}
        print(f"{tag}: 1 s integrated in {res[tag]['integration per simulated s [s]']:.4f} s (set-up "
              f"{min(walls0):.3f} s), RMS DTE {fig['rms']:.6g} um, "
              f"fine {ref['rms']:.6g} um")
    fe_ref = res["FE table"]["RMS DTE fine [um]"]
    rows = []
    for tag, r in res.items():
        r["step error [%]"] = 100 * (r["RMS DTE [um]"] / r["RMS DTE fine [um]"] - 1)
        r["error vs FE reference [%]"] = 100 * (r["RMS DTE [um]"] / fe_ref - 1)
        rows.append(r)
    r_tab, r_ric = res["table"], res["Ricker"]
    ratio = r_tab["integration per simulated s [s]"] / r_ric["integration per simulated s [s]"]
    print(f"integration time, table law / Ricker law = {ratio:.3g} (thesis, MATLAB: 710.6/23.6 = 30.1)")
    with open(os.path.join(out, "timing.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0]))
        w.writeheader()
        w.writerows(rows)


if __name__ == "__main__":
    main()
