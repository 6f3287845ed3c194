#!/usr/bin/python3
"""Error estimate against the true error (README.md, "Checks").

Usage: check.py --estimate <estimate run.json> --reference H:<sweep.csv> [--reference ...]
                --h H --table <table.md>
The true error of the run's level-h value Q_h is Q_ref - Q_h, with Q_ref the solve at the
same roll angle on a finer mesh (independent runs of gearfem solve at the sample positions).
The finest reference is the pass criterion; the others (the requirement's 0.05 mm) are reported as
info rows. The estimate is the `error` of run.json (Richardson from h and h/2, assumed order p)."""
import argparse
import json
import math
import sys

from vcheck import Checks, read_csv

QUANTITIES = [("STE_um", "STE", "um", "STE"), ("root_stress_pinion_MPa", "root stress pinion", "MPa", "root stress pinion"),
              ("root_stress_gear_MPa", "root stress gear", "MPa", "root stress gear"), ("p_max_MPa", "p_max", "MPa", "p_max")]
FACTOR = 2.0  # error-estimate requirement: within a factor of 2 of the true error
FLOOR = 5e-4  # resolution floor, relative to Q_h (README: non-monotone changes below it)


def reference_value(rows, roll, torque, column):
    m = [r for r in rows if abs(r["roll angle"] - roll) < 1e-6 and r["torque"] == torque]
    return m[0][column] if len(m) == 1 else None


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--estimate", required=True)
    ap.add_argument("--reference", action="append", required=True, help="H:sweep.csv")
    ap.add_argument("--h", type=float, required=True)
    ap.add_argument("--table")
    a = ap.parse_args()
    c = Checks("error_estimate")
    e = json.load(open(a.estimate))["error_estimate"]
    refs = sorted(((float(x.split(":", 1)[0]), read_csv(x.split(":", 1)[1])) for x in a.reference), reverse=True)
    h_true = refs[-1][0]
    p = e["order"]
    head = " | ".join(f"Q(h {h:g})" for h, _ in refs)
    ratios = " | ".join(f"est / (Q(h {h:g}) - Q_h)" for h, _ in refs)
    lines = [f"Demo (inputs/demo_fixed_mesh.prm), h_contact {a.h:g} mm; refined level {e['h_contact_fine_mm']:g} mm; references "
             + ", ".join(f"{h:g}" for h, _ in refs) + f" mm (fine sizes scaled alike); assumed order p = {p:g}. "
             f"True error = Q(h {h_true:g}) - Q_h.", "",
             f"| T1 [N m] | sample | roll [deg] | quantity | Q_h | Q_h/2 | {head} | true error | estimate | {ratios} |",
             "|---|---|---|---|---|---|" + "---|" * len(refs) + "---|---|" + "---|" * len(refs)]
    for s in e["samples"]:
        T, roll = s["torque_Nm"], s["roll_deg"]
        label0 = f"{s['zone']} ({s['point']}), {T:g} N m"
        for key, name, unit, column in QUANTITIES:
            q = s[key]
            label = f"{name}, {label0}"
            c.true(f"{label}: finite", all(math.isfinite(q[k]) for k in ("h", "h_over_r", "error", "relative")),
                   "finite", "finite", "project rule: never NaN")
            vals = [reference_value(rows, roll, T, column) for _, rows in refs]
            if any(v is None for v in vals):
                c.true(f"{label}: reference rows", False, "missing", "one row per reference", "reference runs")
                continue
            est = q["error"]
            rat = [est / (v - q["h"]) if v != q["h"] else math.inf for v in vals]
            true = vals[-1] - q["h"]
            lines.append(f"| {T:g} | {s['zone']} {s['point']} | {roll:.4f} | {name} [{unit}] | {q['h']:.5g} | "
                         f"{q['h_over_r']:.5g} | " + " | ".join(f"{v:.5g}" for v in vals) + f" | {true:+.3g} | "
                         f"{est:+.3g} | " + " | ".join(f"{r:.3g}" for r in rat) + " |")
            floor = FLOOR * abs(q["h"])
            if abs(true) > floor:
                c.within(f"{label}: estimate / true error ({est:+.3g} / {true:+.3g} {unit})", rat[-1], 1 / FACTOR,
                         FACTOR, f"error-estimate requirement: within a factor 2 of Q(h {h_true:g}) - Q_h")
            else:  # both below the resolution floor: the estimate must say "negligible" too
                c.at_most(f"{label}: |estimate| while |true error| {abs(true):.2g} {unit} < floor {floor:.2g}",
                          abs(est), FACTOR * floor, "README: resolution floor 0.05 % of Q_h", f" {unit}")
            for (h, _), v, r in zip(refs[:-1], vals[:-1], rat[:-1]):
                if abs(v - q["h"]) > floor:
                    c.info(f"{label}: estimate / (Q(h {h:g}) - Q_h)", round(r, 3), "[0.5, 2]",
                           f"the requirement's reference; it sees 1 - ({h:g}/{a.h:g})^p of the error (README)")
    sweep, setup, cost = e["run_sweep_seconds"], e["run_setup_seconds"], e["seconds_setup"] + e["seconds_solve"]
    lines += ["", f"Cost (one run): run set-up {setup:.1f} s + sweep {sweep:.1f} s; estimate {cost:.1f} s = refined "
              f"set-up {e['seconds_setup']:.1f} s ({e['fine_dofs']} DoFs) + 6 sample solves on two levels "
              f"{e['seconds_solve']:.1f} s; estimate / (set-up + sweep) = {cost / (sweep + setup):.2f}, "
              f"estimate / sweep = {cost / sweep:.2f}"]
    c.info("cost: estimate / (run set-up + sweep)", round(cost / (sweep + setup), 3), "—",
           f"{cost:.1f} s against {sweep + setup:.1f} s, measured in one run")
    text = "\n".join(lines) + "\n"
    print(text)
    if a.table:
        with open(a.table, "w") as f:
            f.write(text)
    return c.finish()


if __name__ == "__main__":
    sys.exit(main())
