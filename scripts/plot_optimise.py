#!/usr/bin/python3
"""Plot a `gearfem optimise` run (seed 003): 1/R along the path for the involute, the
sinusoid, the start and the optimum (curvature.png), the pinion flanks (profiles.png), and
the best feasible objective against evaluations for each method (convergence.png).

Usage: plot_optimise.py OUTPUT_DIR
Reads OUTPUT_DIR/curvature.csv, profiles.csv and optimise.csv (docs/optimise.md) and writes
the PNG files atomically (temporary name in the same folder, then os.replace).
"""
import csv
import os
import sys
from collections import defaultdict

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def read(path, key):
    data = defaultdict(lambda: defaultdict(list))
    with open(path) as f:
        for row in csv.DictReader(f):
            for k, v in row.items():
                if k != key:
                    data[row[key]][k].append(float(v))
    return data


def save(fig, path):
    tmp = path + ".tmp.png"
    fig.savefig(tmp, dpi=130, bbox_inches="tight")
    plt.close(fig)
    os.replace(tmp, path)


def main(d):
    styles = {"involute": "k-", "sinusoid": "b--", "start": "g:", "optimum": "r-"}
    cur = read(os.path.join(d, "curvature.csv"), "design")
    fig, ax = plt.subplots(figsize=(7, 4.5))
    for name, c in cur.items():
        ax.plot(c["normalised position [-]"], c["1/R [1/mm]"], styles.get(name, "-"), label=name)
    ax.set_xlabel("position along the sampled range (0 = start, 1 = end) [-]\n"
                  "(involute, case 2: pinion radius SAP to tip; sinusoid, case 1: rack u crest to trough)")
    ax.set_ylabel("equivalent curvature 1/R [1/mm]")
    ax.set_ylim(bottom=min(0.0, ax.get_ylim()[0]))
    ax.grid(True, alpha=0.3)
    ax.legend()
    save(fig, os.path.join(d, "curvature.png"))

    prof = read(os.path.join(d, "profiles.csv"), "design")
    fig, ax = plt.subplots(figsize=(5, 6))
    for name, c in prof.items():
        ax.plot(c["x [mm]"], c["y [mm]"], styles.get(name, "-"), label=name)
    ax.set_aspect("equal")
    ax.set_xlabel("x [mm] (pinion frame, tooth axis +y)")
    ax.set_ylabel("y [mm]")
    ax.grid(True, alpha=0.3)
    ax.legend()
    save(fig, os.path.join(d, "profiles.png"))

    hist = read(os.path.join(d, "optimise.csv"), "method")
    fig, ax = plt.subplots(figsize=(7, 4.5))
    for name, h in hist.items():
        ax.plot(h["evaluation"], h["best feasible [1/mm]"], label=name)
    ax.set_xscale("log")
    ax.set_xlabel("design evaluations (finite differences included)")
    ax.set_ylabel("best feasible objective [1/mm]")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend()
    save(fig, os.path.join(d, "convergence.png"))


if __name__ == "__main__":
    main(sys.argv[1])
