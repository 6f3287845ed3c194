#!/usr/bin/env python3
"""Checks of the robust tip-relief optimisation (README.md). Reads results/study
(optimise.csv, ste.csv, summary.md), results/solve_gap and results/solve_exact (sweep.csv)
and ends with `tip_relief_optimisation: PASS (n checks)` or FAIL (exit 1).

References, each independent of the optimiser:
  - the Harris-map grid over the same box, evaluated on the same cached model: the optimum
    must be no worse than its best point (issue 15, section 4);
  - the unrelieved pair: a relief is only worth having if it lowers the objective;
  - load sharing (validation/harris_map/README.md): with the same linear relief on both
    gears, a relief no longer than half the double-contact zone, (eps - 1) p_b / 2, leaves an
    unrelieved pair at the middle of the zone and cannot lower the peak-to-peak STE below the
    unrelieved pair's; so an optimum below it must be longer than that;
  - `gearfem solve` of the written optimum.prm (gap route): the same STE as the optimiser's
    evaluation (optimum.prm is the optimised design);
  - the optimum re-meshed with its relief (Micro-geometry = geometry, an independent
    discretisation): peak-to-peak STE within 1 % of the mean STE of the gap route's (at
    h_contact 0.2 mm two meshes of the same gear differ by 0.75 %, validation/micro_geometry),
    and still below half the unrelieved peak-to-peak."""
import argparse
import csv
import math
import os
import sys

from vcheck import Checks

ap = argparse.ArgumentParser()
ap.add_argument("--out", required=True)
a = ap.parse_args()
c = Checks("tip_relief_optimisation", a.out)
study = os.path.join(a.out, "study")

rows = list(csv.DictReader(open(os.path.join(study, "optimise.csv"))))
opt = [r for r in rows if not r["run"].startswith("grid")]
grid = [r for r in rows if r["run"].startswith("grid")]
ok = lambda r: r["ok"] == "1"
best_opt = min((r for r in opt if ok(r)), key=lambda r: float(r["objective [um]"]))
best_grid = min((r for r in grid if ok(r)), key=lambda r: float(r["objective [um]"]))
f_opt, f_grid = float(best_opt["objective [um]"]), float(best_grid["objective [um]"])
torques = [k.split("p-p at ")[1].split(" N m")[0] for k in rows[0] if k.startswith("p-p at ")]

ste = {}
for r in csv.DictReader(open(os.path.join(study, "ste.csv"))):
    ste.setdefault((r["design"], r["torque [N m]"]), []).append(float(r["STE [um]"]))
pp = lambda v: max(v) - min(v)
f_none = max(pp(ste[("no relief", t)]) for t in torques)

# Pair data for the load-sharing bound: Parker pair, standard addendum.
z, m, alpha = 50, 3.0, math.radians(20)
rb, ra, aw = 0.5 * z * m * math.cos(alpha), 0.5 * z * m + m, z * m
pb = math.pi * m * math.cos(alpha)
eps = (2 * math.sqrt(ra ** 2 - rb ** 2) - aw * math.sin(alpha)) / pb
half_zone = 0.5 * (eps - 1) * pb

src_grid = "issue 15 §4: no worse than the best Harris-map grid point (same model)"
c.at_most("optimum objective [um] vs best grid point " + f"({best_grid['C_a [um]']} um, {best_grid['L [mm]']} mm)",
          f_opt, f_grid * (1 + 1e-9), src_grid)
c.at_most("optimum objective / no relief", f_opt / f_none, 0.5, "a relief must pay: below half the unrelieved")
c.within("optimum C_a [um] in the box", float(best_opt["C_a [um]"]), 0.0, 20.0, "Tip relief/Minimum, Maximum amount")
c.within("optimum L [mm] in the box", float(best_opt["L [mm]"]), 1.0, 10.0, "Tip relief/Minimum, Maximum length")
c.at_least("optimum L [mm] vs (eps - 1) p_b / 2", float(best_opt["L [mm]"]), half_zone,
           "load sharing: a shorter relief cannot lower p-p below the unrelieved")
c.at_most("optimiser FE evaluations", len(opt), 31, "Optimiser/Max evaluations (+ the start)")
c.true("every evaluation converged", all(ok(r) for r in rows), f"{sum(ok(r) for r in rows)}/{len(rows)}", "all",
       "no solver failure in the box")

# optimum.prm through gearfem solve: the gap route again, and the exact (re-meshed) route.
def sweep(name):
    out = {}
    for r in csv.DictReader(open(os.path.join(a.out, name, "sweep.csv"))):
        out.setdefault(f"{float(r['torque [N m]']):g}", []).append(float(r["STE [um]"]))
    return out

gap, exact = sweep("solve_gap"), sweep("solve_exact")
for t in torques:
    o = ste[("optimum", t)]
    c.abs(f"solve optimum.prm (gap): p-p STE at {t} N m [um]", pp(gap[t]), pp(o), 1e-4 * max(o),
          "the optimiser's evaluation of the optimum")
    mean = sum(exact[t]) / len(exact[t])
    c.abs(f"optimum re-meshed with its relief: p-p STE at {t} N m [um]", pp(exact[t]), pp(o), 1e-2 * mean,
          "gap vs geometry route: 1 % of mean STE at h_contact 0.2 mm, where two meshes of the same gear "
          "already differ by 0.75 % (validation/micro_geometry/README.md; 0.5 % needs h 0.1 mm)")
    c.at_most(f"optimum re-meshed: p-p STE at {t} N m / no relief", pp(exact[t]) / pp(ste[("no relief", t)]), 0.5,
              "the optimum is not an artefact of the gap idealisation")

text = open(os.path.join(a.out, "study.log")).read()
c.true("progress lines with i/N and ETA", "ETA" in text, "ETA" in text, "present", "project rule")
nan = any("nan" in open(os.path.join(study, f)).read().lower() for f in ("optimise.csv", "ste.csv", "summary.md"))
c.true("no NaN written", not nan, not nan, "True", "project rule")
c.info("best grid objective [um]", f_grid, "-", f"{len(grid)} FE evaluations")
c.info("optimum objective [um]", f_opt, "-", f"{len(opt)} FE evaluations, at C_a {best_opt['C_a [um]']} um, "
       f"L {best_opt['L [mm]']} mm")
for t in torques:
    c.info(f"optimum p-p STE at {t} N m [um]", pp(ste[("optimum", t)]), f"no relief {pp(ste[('no relief', t)]):.4g}",
           "a min-max optimum balances the torques")
c.info("optimum L strictly inside the box", 1.0 < float(best_opt["L [mm]"]) < 10.0, "-", "interior minimum")
c.info("no relief objective [um]", f_none, "-", "worst p-p over the torques")
sys.exit(c.finish())
