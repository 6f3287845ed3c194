"""A small design study on tip relief and torque, each design on the demo's one cycle, with the
results kept as CSV like `gearfem solve` writes them (docs/python.md)."""
import itertools, os

import numpy as np

import gearfem

demo = gearfem.read_input("inputs/demo_fixed_mesh.prm", set={"Solve/Plots": False})
cycle = gearfem.condense(demo)
rows = []
for ca, length, torque in itertools.product([5, 10, 15], [2, 4], [100, 200, 340]):
    r = cycle.solve(torques=[torque], relief={"Gear 1/Tip relief": "linear", "Gear 1/Tip relief amount": ca,
                                              "Gear 1/Tip relief length": length})
    s = r.sweep
    rows.append((ca, length, torque, np.ptp(s["STE [um]"]), s["p_max [MPa]"].max(),
                 s["root stress pinion [MPa]"].max()))
os.makedirs("results/python_study", exist_ok=True)
np.savetxt("results/python_study/study.csv", np.array(rows), delimiter=",", comments="",
           header="C_a [um],length [mm],torque [N m],p-p STE [um],p_max [MPa],root stress pinion [MPa]")
best = min(rows, key=lambda r: r[3])
print(f"{len(rows)} designs; smallest p-p STE {best[3]:.3f} um: C_a {best[0]} um over {best[1]} mm at {best[2]} N m")
