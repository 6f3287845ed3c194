#!/usr/bin/python3
"""theta1(t) of the NTUA tooth-mass thesis' case: gearfem with the thesis' K (after the
overwrite and as intended) beside the thesis' own code (numpy replica), and gearfem's
Weber/Cornell k(theta); first 4 ms (thesis Figs. 4.4/4.8) and the 25-period record.

Usage: plot.py <out.png> <results dir>
"""
import csv
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from thesis_model import model_solve  # noqa: E402


def gearfem(folder):
    with open(os.path.join(folder, "response.csv"), newline="") as f:
        rows = [[float(v) for v in r] for r in list(csv.reader(f))[1:] if r]
    return [r[0] * 1e3 for r in rows], [r[6] for r in rows]


out, res = sys.argv[1], sys.argv[2]
fig, axes = plt.subplots(2, 1, figsize=(9, 7))
t_end = 25 / (20 * 160 / (2 * math.pi)) * 1e3
for ax, t_max in zip(axes, (4.0, t_end)):
    for name, ow, style in (("overwrite", True, "b-"), ("intended", False, "r-")):
        t, a = gearfem(os.path.join(res, f"thesis_k_{name}"))
        ax.plot([x for x in t if x <= t_max], [y for x, y in zip(t, a) if x <= t_max], style, lw=0.6,
                label=f"gearfem, thesis K ({'after the overwrite' if ow else 'as intended'})")
        tt, th1, _, _ = model_solve(overwrite=ow, tmax=t_max * 1e-3, n=int(t_max * 1000))
        ax.plot(tt * 1e3, th1 * 1e6, style[0] + ":", lw=0.8, label=f"thesis' model_solve ({name})")
    t, a = gearfem(os.path.join(res, "weber_k"))
    ax.plot([x for x in t if x <= t_max], [y for x, y in zip(t, a) if x <= t_max], "g-", lw=0.5,
            label="gearfem, Weber/Cornell k(theta)")
    ax.set_xlabel("time [ms]")
    ax.set_ylabel("pinion vibration angle theta1 [urad]")
    ax.grid(True, alpha=0.3)
axes[0].set_title("NTUA tooth-mass thesis case, 160 rad/s, from rest: first 4 ms")
axes[1].set_title("25 mesh periods (49.1 ms)")
axes[0].legend(fontsize=7, loc="upper right")
fig.tight_layout()
fig.savefig(out, dpi=110)
