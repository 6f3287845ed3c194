"""calibration.png: FE STE against the analytical model before and after calibration over
the mesh cycle, one panel per torque. Usage: plot_calibration.py <output_dir>."""
import csv
import os
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt


def main():
    if len(sys.argv) < 2:
        print("usage: plot_calibration.py <output_dir>", file=sys.stderr)
        return 2
    d = sys.argv[1]
    path = os.path.join(d, "calibration.csv")
    if not os.path.exists(path):
        print("plot_calibration.py: %s missing" % path, file=sys.stderr)
        return 1
    with open(path) as f:
        rows = list(csv.reader(f))
    head = [h.split(" [")[0] for h in rows[0]]
    data = [dict(zip(head, map(float, r))) for r in rows[1:]]
    torques = sorted({r["torque"] for r in data})
    fig, axes = plt.subplots(len(torques), 1, figsize=(8, 2.8 * len(torques)), sharex=True, squeeze=False)
    for ax, T in zip(axes[:, 0], torques):
        rs = sorted((r for r in data if r["torque"] == T), key=lambda r: r["roll angle"])
        x = [r["roll angle"] for r in rs]
        ax.plot(x, [r["STE FE"] for r in rs], "k.-", label="FE (gearfem solve)")
        ax.plot(x, [r["STE before"] for r in rs], "C0--", label="analytical, uncalibrated")
        ax.plot(x, [r["STE after"] for r in rs], "C3-", label="analytical, calibrated")
        ax.set_ylabel("STE [um]")
        ax.set_title("T1 = %g N m" % T)
        ax.grid(alpha=0.3)
    axes[0, 0].legend(fontsize=8)
    axes[-1, 0].set_xlabel("pinion roll angle [deg] (0 at C)")
    fig.tight_layout()
    tmp = os.path.join(d, ".calibration.png.tmp.png")
    fig.savefig(tmp, dpi=120)
    os.replace(tmp, os.path.join(d, "calibration.png"))
    return 0


if __name__ == "__main__":
    sys.exit(main())
