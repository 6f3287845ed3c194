#!/usr/bin/python3
"""Plot a tip-relief `gearfem optimise` run (Optimise/Problem = tip relief): the STE over one
mesh cycle at each torque for no relief, the start, the optimum and (if run) the best grid
point (relief.png); and the optimiser's objective against FE evaluations beside the grid's
(relief_history.png); with Tip relief/Check torques, the peak-to-peak STE against torque of
no relief, the robust optimum, the single-load optima and the grid's best (relief_robust.png).

Usage: plot_relief.py OUTPUT_DIR
Reads OUTPUT_DIR/ste.csv, optimise.csv and robust.csv if present (docs/optimise.md) and writes
the PNG files
atomically (temporary name in the same folder, then os.replace).
"""
import csv
import os
import sys
from collections import defaultdict

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def save(fig, path):
    tmp = path + ".tmp.png"
    fig.savefig(tmp, dpi=130, bbox_inches="tight")
    plt.close(fig)
    os.replace(tmp, path)


def main(d):
    curves = defaultdict(lambda: defaultdict(lambda: ([], [])))
    torques = []
    with open(os.path.join(d, "ste.csv")) as f:
        for row in csv.DictReader(f):
            t = float(row["torque [N m]"])
            if t not in torques:
                torques.append(t)
            x, y = curves[t][row["design"]]
            x.append(float(row["cycle fraction"]))
            y.append(float(row["STE [um]"]))
    styles = {"no relief": "k-", "start": "g:", "optimum": "r-", "grid best": "b--"}
    n = len(torques)
    fig, axes = plt.subplots(1, n, figsize=(4.2 * n + 0.8, 4), squeeze=False)
    for ax, t in zip(axes[0], torques):
        for name, (x, y) in curves[t].items():
            pp = max(y) - min(y)
            style = styles.get(name, ":" if name.startswith("optimum at") else "-")
            ax.plot(x + [1.0], y + [y[0]], style, marker=".", ms=3,
                    label=f"{name} (p-p {pp:.2f} um)")
        ax.set_title(f"T1 = {t:g} N m")
        ax.set_xlabel("mesh cycle from A [-]")
        ax.grid(True, alpha=0.3)
        ax.legend(fontsize=7, loc="upper center", bbox_to_anchor=(0.5, -0.14), ncol=2)  # below: no curve hidden
    axes[0][0].set_ylabel("STE [um]")
    fig.suptitle("Static transmission error before and after the tip-relief optimisation")
    save(fig, os.path.join(d, "relief.png"))

    runs = defaultdict(lambda: ([], []))
    with open(os.path.join(d, "optimise.csv")) as f:
        for row in csv.DictReader(f):
            x, y = runs[row["run"]]
            x.append(int(row["evaluation"]))
            y.append(float(row["best [um]"]))
    fig, ax = plt.subplots(figsize=(6, 4))
    for name, (x, y) in runs.items():
        ax.step(x, y, where="post", label=name)
    ax.set_xlabel("FE evaluations (one sweep of the cycle at every torque each)")
    ax.set_ylabel("best objective so far [um]")
    ax.grid(True, alpha=0.3)
    ax.legend()
    save(fig, os.path.join(d, "relief_history.png"))
    if os.path.exists(os.path.join(d, "robust.csv")):
        plot_robust(d, torques)


def plot_robust(d, study_torques):
    """p-p STE against torque per design (robust.csv); the study torques marked."""
    curves = defaultdict(lambda: ([], []))
    with open(os.path.join(d, "robust.csv")) as f:
        for row in csv.DictReader(f):
            if row["ok"] != "1":
                continue  # a failed sweep has no figure
            x, y = curves[row["design"]]
            x.append(float(row["torque [N m]"]))
            y.append(float(row["p-p [um]"]))
    styles = {"no relief": "k-", "optimum": "r-", "grid best": "b--"}
    fig, ax = plt.subplots(figsize=(8.5, 4.2))
    for name, (x, y) in curves.items():
        xy = sorted(zip(x, y))
        label = "robust optimum (worst of the study torques)" if name == "optimum" else name
        ax.plot([a for a, _ in xy], [b for _, b in xy], styles.get(name, "-."), marker="o", ms=4, label=label)
    for t in study_torques:
        ax.axvline(t, color="grey", lw=0.8, ls=":")
    ax.set_xlabel("pinion torque T1 [N m] (dotted: the study torques)")
    ax.set_ylabel("peak-to-peak STE [um]")
    ax.set_ylim(bottom=0)
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=7, loc="center left", bbox_to_anchor=(1.01, 0.5))
    ax.set_title("Single-load against robust tip relief over a torque range")
    save(fig, os.path.join(d, "relief_robust.png"))


if __name__ == "__main__":
    main(sys.argv[1])
