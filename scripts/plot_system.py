#!/usr/bin/python3
"""Plots of a run on the shafts (`gearfem helical` with System/Coupling = shafts, or `gearfem
system`): system.png.

Usage: MPLBACKEND=Agg /usr/bin/python3 scripts/plot_system.py <output folder>
Reads shafts.csv, bearings.csv and misalignment.csv (docs/system-deflection.md). Panels: the
shafts' radial deflection along each shaft at every torque; the bearings' radial reactions; the
mismatch the shafts give along the face (mean over the cycle) per torque and stage. Written to a
temporary name and renamed into place. Exit 1 with a one-line message when a table is missing or
unreadable.
"""
import math
import os
import sys
from collections import defaultdict

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from plot_helical import table  # noqa: E402  (the same tables' reader)


def main(argv):
    if len(argv) != 2 or argv[1] in ("-h", "--help"):
        print(__doc__.strip())
        return 0 if len(argv) == 2 else 2
    d = argv[1]
    try:
        shafts = table(os.path.join(d, "shafts.csv"))
        bearings = table(os.path.join(d, "bearings.csv"))
        mis = table(os.path.join(d, "misalignment.csv"))
    except (OSError, ValueError, KeyError) as e:
        print(f"plot_system.py: {d}: {e}", file=sys.stderr)
        return 1
    fig, ax = plt.subplots(1, 3, figsize=(15, 4.2))
    torques = sorted({float(r["torque_Nm"]) for r in shafts})
    for T in torques:
        by = defaultdict(list)
        for r in shafts:
            if float(r["torque_Nm"]) == T:
                by[int(r["shaft"])].append((float(r["z_mm"]), math.hypot(float(r["u_x_um"]), float(r["u_y_um"]))))
        for s, pts in sorted(by.items()):
            pts.sort()
            ax[0].plot([p[0] for p in pts], [p[1] for p in pts], ".-", label=f"shaft {s + 1}, {T:g} N m")
    ax[0].set_xlabel("z along the shaft [mm]")
    ax[0].set_ylabel("radial deflection [um]")
    ax[0].set_title("shafts (at their nodes)")
    ax[0].legend(fontsize=7)
    names = [r["bearing"] for r in bearings if float(r["torque_Nm"]) == torques[-1]]
    radial = [math.hypot(float(r["F_x_N"]), float(r["F_y_N"])) / 1e3 for r in bearings
              if float(r["torque_Nm"]) == torques[-1]]
    ax[1].barh(range(len(names)), radial)
    ax[1].set_yticks(range(len(names)))
    ax[1].set_yticklabels(names, fontsize=7)
    ax[1].set_xlabel(f"radial reaction [kN] at {torques[-1]:g} N m")
    ax[1].set_title("bearings")
    acc = defaultdict(lambda: defaultdict(list))
    for r in mis:
        key = (r.get("stage", ""), float(r["torque_Nm"]))
        acc[key][float(r["z_mm"])].append(float(r["mismatch_um"]))
    for (stage, T), zs in sorted(acc.items()):
        z = sorted(zs)
        ax[2].plot(z, [sum(zs[k]) / len(zs[k]) for k in z], "o-", ms=3,
                   label=(f"stage {stage}, " if stage else "") + f"{T:g} N m")
    ax[2].set_xlabel("z over the face [mm]")
    ax[2].set_ylabel("mismatch from the shafts [um]")
    ax[2].set_title("mismatch along the face (mean over the cycle)")
    ax[2].legend(fontsize=7)
    fig.tight_layout()
    out = os.path.join(d, "system.png")
    tmp = out + ".tmp.png"
    fig.savefig(tmp, dpi=100)
    os.replace(tmp, out)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
