#!/usr/bin/python3
"""Resonance and jump frequencies, contact loss and the sweep plot of the Parker-pair runs.

Usage: analyse.py <out.png> <title> <run folder>...   (folders named *<T>Nm, each with sweep.csv)
"""
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

out, title, folders = sys.argv[1], sys.argv[2], sys.argv[3:]
fig, ax = plt.subplots(figsize=(8, 4.5))
for d in folders:
    with open(os.path.join(d, "sweep.csv"), newline="") as f:
        rows = [[float(v) for v in r] for r in list(csv.reader(f))[1:] if r]
    name = os.path.basename(d.rstrip("/"))
    up = [r for r in rows if r[0] == 1]
    down = [r for r in rows if r[0] == -1]
    peak_up = max(up, key=lambda r: r[3])
    peak_down = max(down, key=lambda r: r[3])
    iu = max(range(1, len(up)), key=lambda i: up[i][3] - up[i - 1][3])
    idn = max(range(1, len(down)), key=lambda i: down[i - 1][3] - down[i][3])
    loss = [r for r in rows if r[7] > 0]

    def ranges(pts):
        """Contiguous mesh-frequency ranges [Hz] of the points with contact loss."""
        out, cur = [], None
        for r in sorted(pts, key=lambda r: r[2]):
            if r[7] > 0:
                cur = [r[2], r[2]] if cur is None else [cur[0], r[2]]
            elif cur is not None:
                out.append(cur)
                cur = None
        if cur is not None:
            out.append(cur)
        return ", ".join(f"{a:.0f}-{b:.0f}" for a, b in out) or "none"
    clamps = sum(r[11] for r in rows)
    print(f"{name}: peak RMS DTE up {peak_up[3]:.2f} um at {peak_up[2]:.0f} Hz, down "
          f"{peak_down[3]:.2f} um at {peak_down[2]:.0f} Hz; largest jump up (up sweep) at "
          f"{up[iu][2]:.0f} Hz (+{up[iu][3] - up[iu - 1][3]:.2f} um), jump down (down sweep) at "
          f"{down[idn][2]:.0f} Hz (-{down[idn - 1][3] - down[idn][3]:.2f} um); contact loss at "
          f"{len(loss)}/{len(rows)} points"
          + (f" ({min(r[2] for r in loss):.0f}-{max(r[2] for r in loss):.0f} Hz)" if loss else "")
          + f"; table clamps {clamps:.0f}")
    print(f"  contact loss, up sweep: {ranges(up)} Hz; down sweep: {ranges(down)} Hz; "
          f"max K_v up {max(r[6] for r in up):.2f}, down {max(r[6] for r in down):.2f}")
    line, = ax.plot([r[2] for r in up], [r[3] for r in up], "-", label=f"{name} up")
    ax.plot([r[2] for r in down], [r[3] for r in down], "--", color=line.get_color(),
            label=f"{name} down")
ax.set_xlabel("mesh frequency [Hz]")
ax.set_ylabel("RMS DTE [um]")
ax.set_title(title)
ax.grid(True, alpha=0.3)
ax.legend(fontsize=8)
tmp = os.path.join(os.path.dirname(os.path.abspath(out)), ".tmp_" + os.path.basename(out))
fig.savefig(tmp, dpi=120, bbox_inches="tight")
os.replace(tmp, out)
