#!/usr/bin/python3
"""Plot of a `gearfem solve` hunting cycle with manufacturing deviations: hunting.png.

Usage: MPLBACKEND=Agg /usr/bin/python3 scripts/plot_hunting.py <output folder>
Reads sweep.csv and spectrum.csv (docs/deviations.md). Top: the STE over the pinion rotation
(in revolutions) per torque, the form an NVH engineer compares with a transmission-error rig.
Bottom: the order spectrum of the STE (orders of the pinion rotation, log amplitude), with the
mesh orders marked. Written to a temporary name and renamed into place. Exit 1 with a one-line
message when an input is missing or unreadable.
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


def read(path):
    with open(path, newline="") as f:
        rows = [r for r in csv.reader(f) if r]
    names = [UNIT.sub("", h.strip()) for h in rows[0]]
    data = np.array([[float(v) for v in r] for r in rows[1:]], dtype=float)
    return {n: data[:, i] for i, n in enumerate(names)}


def main(argv):
    if len(argv) != 2 or argv[1] in ("-h", "--help"):
        print(__doc__.strip())
        return 0 if len(argv) == 2 else 2
    folder = argv[1]
    try:
        sweep = read(os.path.join(folder, "sweep.csv"))
        spec = read(os.path.join(folder, "spectrum.csv"))
    except (OSError, ValueError, IndexError, KeyError) as e:
        print(f"plot_hunting.py: cannot read the hunting results in {folder}: {e}", file=sys.stderr)
        return 1
    fig, (ax1, ax2) = plt.subplots(2, 1, figsize=(10, 7.5))
    roll = sweep["roll angle"]
    for T in sorted(set(sweep["torque"])):
        m = sweep["torque"] == T
        ax1.plot((roll[m] - roll[m][0]) / 360.0, sweep["STE"][m], lw=0.8, label=f"{T:g} N m")
        s = spec["torque"] == T
        ax2.semilogy(spec["order pinion"][s][1:], np.maximum(spec["amplitude"][s][1:], 1e-6), lw=0.8,
                     label=f"{T:g} N m")
    ax1.set_xlabel("pinion rotation [rev]")
    ax1.set_ylabel("STE [um]")
    ax1.set_title("Static transmission error over the cycle, with the deviations")
    ax1.grid(alpha=0.3)
    ax1.legend(fontsize=8)
    ax2.set_xlabel("order of the pinion rotation [-]")
    ax2.set_ylabel("amplitude [um]")
    ax2.set_title("Order spectrum of the STE (mesh orders dotted)")
    top = spec["order pinion"].max() if len(spec["order pinion"]) else 1
    ax2.grid(alpha=0.3, which="both")
    ax2.legend(fontsize=8)
    lim = ax2.get_xlim()
    # Mesh orders: spectrum.csv's "mesh harmonic" is the order over z1.
    nz = spec["mesh harmonic"] > 0
    if np.any(nz):
        z1 = float(np.median(spec["order pinion"][nz] / spec["mesh harmonic"][nz]))
        for h in range(1, int(top / z1) + 1):
            ax2.axvline(h * z1, color="k", ls=":", lw=0.6)
    ax2.set_xlim(0, min(lim[1], top))
    tmp = os.path.join(folder, ".hunting.png.tmp.png")
    fig.tight_layout()
    fig.savefig(tmp, dpi=110)
    os.replace(tmp, os.path.join(folder, "hunting.png"))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
