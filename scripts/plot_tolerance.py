#!/usr/bin/python3
"""Histograms of a `gearfem tolerance` study: tolerance.png.

Usage: MPLBACKEND=Agg /usr/bin/python3 scripts/plot_tolerance.py <output folder>
Reads samples.csv (docs/deviations.md): one panel per figure (p-p STE, mesh orders 1-3, the
largest non-mesh order, peak root stress of each gear, peak pressure), one histogram per torque,
with the 5/50/95 % percentiles marked. Written to a temporary name and renamed into place. Exit 1
with a one-line message when samples.csv is missing or unreadable.
"""
import csv
import os
import re
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

UNIT = re.compile(r"\s*\[[^\]]*\]\s*$")
FIGURES = ["p-p STE", "mesh order 1", "mesh order 2", "mesh order 3", "largest non-mesh order",
           "max root stress pinion", "max root stress gear", "max pressure"]


def main(argv):
    if len(argv) != 2 or argv[1] in ("-h", "--help"):
        print(__doc__.strip())
        return 0 if len(argv) == 2 else 2
    folder = argv[1]
    try:
        with open(os.path.join(folder, "samples.csv"), newline="") as f:
            rows = [r for r in csv.reader(f) if r]
        header = [h.strip() for h in rows[0]]
        names = [UNIT.sub("", h) for h in header]
        data = np.array([[float(v) for v in r] for r in rows[1:]], dtype=float)
        if data.size == 0:
            raise ValueError("no samples")
    except (OSError, ValueError, IndexError) as e:
        print(f"plot_tolerance.py: cannot read {folder}/samples.csv: {e}", file=sys.stderr)
        return 1
    col = {n: i for i, n in enumerate(names)}
    fig, axes = plt.subplots(2, 4, figsize=(14, 6.5))
    torques = sorted(set(data[:, col["torque"]]))
    for ax, name in zip(axes.flat, FIGURES):
        i = col[name]
        for T in torques:
            v = data[data[:, col["torque"]] == T, i]
            ax.hist(v, bins=max(5, min(40, len(v) // 10)), alpha=0.6, label=f"{T:g} N m")
            for p in (5, 50, 95):
                ax.axvline(np.percentile(v, p), color="k", lw=0.6, ls=":" if p != 50 else "-")
        ax.set_title(header[i], fontsize=9)
        ax.grid(alpha=0.3)
    axes.flat[0].legend(fontsize=8)
    fig.suptitle(f"Tolerance study: {int(len(data) / max(1, len(torques)))} samples (percentiles 5/50/95 % marked)")
    fig.tight_layout()
    tmp = os.path.join(folder, ".tolerance.png.tmp.png")
    fig.savefig(tmp, dpi=100)
    os.replace(tmp, os.path.join(folder, "tolerance.png"))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
