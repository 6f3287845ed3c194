#!/usr/bin/python3
"""Plots of a `gearfem helical` run: helical.png.

Usage: MPLBACKEND=Agg /usr/bin/python3 scripts/plot_helical.py <output folder>
Reads helical.csv and slices.csv (docs/helical.md). Panels, for the first torque: the STE and the
face load factor K_Hbeta over the cycle; the map of the load per unit face width over the face
(z) and the cycle (position); the root stress per slice over the cycle. Written to a temporary
name and renamed into place. Exit 1 with a one-line message when a table is missing or unreadable.
"""
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def table(path):
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    if not rows:
        raise ValueError("no rows")
    return rows


def main(argv):
    if len(argv) != 2 or argv[1] in ("-h", "--help"):
        print(__doc__.strip())
        return 0 if len(argv) == 2 else 2
    folder = argv[1]
    try:
        pos = table(os.path.join(folder, "helical.csv"))
        sl = table(os.path.join(folder, "slices.csv"))
    except (OSError, ValueError) as e:
        print(f"plot_helical.py: cannot read the tables of {folder}: {e}", file=sys.stderr)
        return 1
    T = float(pos[0]["torque_Nm"])
    pos = [r for r in pos if float(r["torque_Nm"]) == T]
    sl = [r for r in sl if float(r["torque_Nm"]) == T]
    n_pos = len(pos)
    z = sorted({float(r["z_mm"]) for r in sl})
    load = np.zeros((len(z), n_pos))
    root = np.zeros((len(z), n_pos))
    zi = {v: i for i, v in enumerate(z)}
    for r in sl:
        p = int(r["position"])
        if p < n_pos:
            load[zi[float(r["z_mm"])], p] = float(r["load_N_per_mm"])
            root[zi[float(r["z_mm"])], p] = max(float(r["root_stress_pinion_MPa"]), float(r["root_stress_gear_MPa"]))
    fig, ax = plt.subplots(2, 2, figsize=(12, 7.5))
    x = np.arange(n_pos)
    ax[0, 0].plot(x, [float(r["ste_um"]) for r in pos], "o-", ms=3)
    ax[0, 0].set_ylabel("STE [um]")
    ax[0, 0].set_title(f"STE over the cycle at {T:g} N m")
    ax[0, 1].plot(x, [float(r["k_h_beta"]) for r in pos], "o-", ms=3, color="C3")
    ax[0, 1].set_ylabel("K_Hbeta = max w / mean w [-]")
    ax[0, 1].set_title("face load factor")
    extent = [-0.5, n_pos - 0.5, z[0], z[-1]]
    im = ax[1, 0].imshow(load, aspect="auto", origin="lower", extent=extent, cmap="viridis")
    fig.colorbar(im, ax=ax[1, 0], label="load per unit face width [N/mm]")
    ax[1, 0].set_ylabel("z [mm]")
    ax[1, 0].set_title("load over the face and the cycle")
    im = ax[1, 1].imshow(root, aspect="auto", origin="lower", extent=extent, cmap="magma")
    fig.colorbar(im, ax=ax[1, 1], label="root stress, larger gear [MPa]")
    ax[1, 1].set_title("root stress per slice")
    for a in ax.flat:
        a.set_xlabel("position over one pitch")
        a.grid(alpha=0.3)
    fig.tight_layout()
    tmp = os.path.join(folder, ".helical.png.tmp.png")
    fig.savefig(tmp, dpi=100)
    os.replace(tmp, os.path.join(folder, "helical.png"))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
