"""A Harris map of the demo pair from a Python loop on one condensed cycle (docs/python.md)."""
import numpy as np

import gearfem

demo = gearfem.read_input("inputs/demo_fixed_mesh.prm", set={"Solve/Plots": False,
                                                              "Condense/Torque range": "50, 800"})
cycle = gearfem.condense(demo)  # the FE once over the 40 positions: a few seconds
torques = np.geomspace(50, 800, 12)
amounts = np.arange(0, 21, 2.0)  # linear tip relief on both gears [um], over 4 mm
pp = np.zeros((len(amounts), len(torques)))
for i, ca in enumerate(amounts):
    relief = {} if ca == 0 else {"Gear 1/Tip relief": "linear", "Gear 2/Tip relief": "linear",
                                 "Gear 1/Tip relief amount": ca, "Gear 2/Tip relief amount": ca,
                                 "Gear 1/Tip relief length": 4, "Gear 2/Tip relief length": 4}
    r = cycle.solve(torques=torques, relief=relief)
    T, ste = r.sweep["torque [N m]"], r.sweep["STE [um]"]
    pp[i] = [np.ptp(ste[T == t]) for t in torques]
for ca, row in zip(amounts, pp):
    k = int(np.argmin(row))
    print(f"C_a {ca:4.1f} um: smallest p-p STE {row[k]:.3f} um at {torques[k]:.0f} N m")
