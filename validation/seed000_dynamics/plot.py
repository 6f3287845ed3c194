#!/usr/bin/python3
"""Contact-state histories and DTE of the Gkimisis 2019 Table 1 cases (one panel per case).

Usage: plot.py <out.png> <run folder>...   (each folder holds response.csv of gearfem dynamics)
"""
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

out, folders = sys.argv[1], sys.argv[2:]
fig, axes = plt.subplots(len(folders), 1, figsize=(8, 2.2 * len(folders)), sharex=False)
for ax, d in zip(axes, folders):
    with open(os.path.join(d, "response.csv"), newline="") as f:
        rows = [[float(v) for v in r] for r in list(csv.reader(f))[1:] if r]
    t = [(r[0] - rows[0][0]) * 1e3 for r in rows]
    ax.plot(t, [r[2] for r in rows], "b-", lw=0.8)
    ax.set_ylabel("DTE [um]", color="b")
    ax2 = ax.twinx()
    ax2.plot(t, [r[5] for r in rows], "r-", lw=0.6)
    ax2.set_ylim(-1.5, 1.5)
    ax2.set_ylabel("s", color="r")
    loss = sum(1 for r in rows if r[5] != 1) / len(rows)
    ax.set_title(f"{os.path.basename(d)}: contact-loss fraction {loss:.3f}", fontsize=9)
    ax.grid(True, alpha=0.3)
axes[-1].set_xlabel("time in the steady-state record [ms]")
fig.tight_layout()
tmp = os.path.join(os.path.dirname(os.path.abspath(out)), ".tmp_" + os.path.basename(out))
fig.savefig(tmp, dpi=110)
os.replace(tmp, out)
