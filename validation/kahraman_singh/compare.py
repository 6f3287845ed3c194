#!/usr/bin/python3
"""Compare the RK4 and the rtol-1e-12 DOPRI5 Kahraman-Singh sweeps; report the jump
frequencies, the superharmonic peak and the maximum RMS difference; plot ks_sweep.png.

Usage: compare.py <rk4 sweep.csv> <reference sweep.csv> <out.png>
"""
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def read(path):
    with open(path, newline="") as f:
        rows = list(csv.reader(f))[1:]
    return [[float(v) for v in r] for r in rows if r]


def branch(rows, direction):
    return [r for r in rows if r[0] == direction]


def jumps(rows):
    up, down = branch(rows, 1), branch(rows, -1)
    ju = max(range(1, len(up)), key=lambda i: up[i][3] - up[i - 1][3])
    jd = max(range(1, len(down)), key=lambda i: down[i - 1][3] - down[i][3])
    return up[ju][1], down[jd][1]


a, b = read(sys.argv[1]), read(sys.argv[2])
assert len(a) == len(b)
diff = max(abs(x[3] - y[3]) / y[3] for x, y in zip(a, b))
wu, wd = jumps(b)
sup = [r for r in branch(b, 1) if 0.4 <= r[1] <= 0.6]
peak = max(sup, key=lambda r: r[3])
impacts = [r for r in b if r[7] > 0]
print(f"jump up (up sweep) at Omega = {wu:.3f}; jump down (down sweep) at Omega = {wd:.3f}")
print(f"superharmonic peak at Omega = {peak[1]:.3f}, RMS x = {peak[3]:.4f}")
print(f"points with contact loss: {len(impacts)}/{len(b)}; with back contact: "
      f"{sum(1 for r in b if r[8] > 0)}")
print(f"max relative RMS difference RK4 vs DOPRI5 rtol 1e-12 over {len(a)} points: {diff:.2e}")
fig, ax = plt.subplots(figsize=(7, 4))
for rows, label, style in ((b, "DOPRI5 rtol 1e-12", "-"), (a, "RK4 128 steps/period", "o")):
    for d, name in ((1, "up"), (-1, "down")):
        br = branch(rows, d)
        ax.plot([r[1] for r in br], [r[3] for r in br], style, ms=3,
                label=f"{label}, {name}")
ax.set_xlabel("Omega [-]")
ax.set_ylabel("RMS x [-]")
ax.set_title("Kahraman & Singh (1990) reference set: zeta 0.05, F_m 0.1")
ax.grid(True, alpha=0.3)
ax.legend(fontsize=7)
tmp = os.path.join(os.path.dirname(os.path.abspath(sys.argv[3])), ".tmp_" + os.path.basename(sys.argv[3]))
fig.savefig(tmp, dpi=120, bbox_inches="tight")
os.replace(tmp, sys.argv[3])
