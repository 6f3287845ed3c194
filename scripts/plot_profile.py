#!/usr/bin/python3
"""Plot a `gearfem profile` run: both gears meshing at the pitch point (pinion position
phi1 = 0), the line of action T1-T2 with the points A-E, the base circles, and a zoom on the
mesh zone.

Usage: plot_profile.py OUTPUT_DIR
Reads OUTPUT_DIR/profile_gear1.csv, profile_gear2.csv and pair.csv (written by
`gearfem profile`, columns documented in docs/geometry.md) and writes OUTPUT_DIR/profile.png
atomically (temporary name in the same folder, then os.replace).
"""
import csv
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def read_pair(path):
    values = {}
    with open(path) as f:
        for row in csv.DictReader(f):
            values[row["quantity"]] = float(row["value"])
    return values


def read_profile(path):
    data = np.genfromtxt(path, delimiter=",", skip_header=1)
    return data[:, 0], data[:, 1], data[:, 5]


def placed(x, y, cx, cy, angle_deg):
    a = math.radians(angle_deg)
    c, s = math.cos(a), math.sin(a)
    return cx + c * x - s * y, cy + s * x + c * y


def main():
    out = sys.argv[1]
    pair = read_pair(os.path.join(out, "pair.csv"))
    fig, axes = plt.subplots(1, 2, figsize=(14, 7))
    colors = {1: "tab:blue", 2: "tab:orange"}
    for i in (1, 2):
        x, y, _ = read_profile(os.path.join(out, f"profile_gear{i}.csv"))
        px, py = placed(x, y, pair[f"gear {i} centre x"], pair[f"gear {i} centre y"],
                        pair[f"gear {i} angle at C"])
        px, py = np.append(px, px[0]), np.append(py, py[0])
        for ax in axes:
            ax.plot(px, py, color=colors[i], lw=0.8, label=f"gear {i} (z = {int(pair[f'z{i}'])})")
            t = np.linspace(0, 2 * np.pi, 721)
            rb = pair[f"base radius {i}"]
            rw = pair[f"working pitch radius {i}"]
            cx, cy = pair[f"gear {i} centre x"], pair[f"gear {i} centre y"]
            ax.plot(cx + rb * np.cos(t), cy + rb * np.sin(t), "--", color=colors[i], lw=0.6)
            ax.plot(cx + rw * np.cos(t), cy + rw * np.sin(t), ":", color="gray", lw=0.5)
    names = ["T1", "A", "B", "C", "D", "E", "T2"]
    lx = [pair[f"{n} x"] for n in ("T1", "T2")]
    ly = [pair[f"{n} y"] for n in ("T1", "T2")]
    for ax in axes:
        ax.plot(lx, ly, "k-", lw=0.8, label="line of action")
        for n in names:
            ax.plot(pair[f"{n} x"], pair[f"{n} y"], "ko" if n in "ABCDE" else "k^", ms=4)
            ax.annotate(n, (pair[f"{n} x"], pair[f"{n} y"]), textcoords="offset points",
                        xytext=(4, 4), fontsize=9)
        ax.set_aspect("equal")
        ax.set_xlabel("x [mm]")
        ax.set_ylabel("y [mm]")
    a = pair["centre distance"]
    axes[0].set_title(f"pair at the pitch point, a = {a:.3f} mm, "
                      f"eps = {pair['transverse contact ratio']:.3f}")
    axes[0].legend(loc="upper right", fontsize=8)
    # Zoom on the mesh zone: a box around the line of action A..E.
    ex = [pair[f"{n} x"] for n in "AE"]
    ey = [pair[f"{n} y"] for n in "AE"]
    m = pair["module"]
    axes[1].set_xlim(min(ex) - 3 * m, max(ex) + 3 * m)
    axes[1].set_ylim(min(ey) - 3 * m, max(ey) + 3 * m)
    axes[1].set_title("mesh zone: base circles (dashed), working pitch circles (dotted)")
    fig.tight_layout()
    target = os.path.join(out, "profile.png")
    tmp = os.path.join(out, ".profile.png.tmp.png")
    fig.savefig(tmp, dpi=130)
    os.replace(tmp, target)


if __name__ == "__main__":
    main()
