#!/usr/bin/python3
"""Plots of a `gearfem gearbox` run: gearbox_damage.png (Miner damage per member and mode,
bars, log scale) and scuffing_path.png (flash temperature and specific film thickness along
the path of contact of the worst scuffing bin).

Usage: MPLBACKEND=Agg /usr/bin/python3 scripts/plot_gearbox.py <output folder>
Reads gearbox_life.csv and scuffing_path.csv; columns are found by header name (the
" [unit]" suffix stripped). Each PNG is written to a temporary name and renamed into place.
Exits with status 1 and a one-line message when a file is missing.
"""
import csv
import os
import re
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

UNIT = re.compile(r"\s*\[[^\]]*\].*$")


def read(path):
    with open(path, newline="") as f:
        rows = [r for r in csv.reader(f) if r and not r[0].startswith("#")]
    head = [UNIT.sub("", h).strip() for h in rows[0]]
    return [dict(zip(head, r)) for r in rows[1:]]


def save(fig, path):
    tmp = path + ".tmp.png"
    fig.savefig(tmp, dpi=120, bbox_inches="tight")
    plt.close(fig)
    os.replace(tmp, path)


def main():
    out = sys.argv[1]
    try:
        life = read(os.path.join(out, "gearbox_life.csv"))
        path = read(os.path.join(out, "scuffing_path.csv"))
    except OSError as e:
        print(f"plot_gearbox: {e}", file=sys.stderr)
        return 1
    labels = [f"{r['stage']} {r['member']} {r['mode']}\n{r['load']}" for r in life]
    D = [float(r["damage D"]) for r in life]
    fig, ax = plt.subplots(figsize=(10, 4.5))
    floor = 1e-12
    ax.bar(range(len(D)), [max(d, floor) for d in D], color=["C3" if d > 0 else "0.8" for d in D])
    ax.set_yscale("log")
    ax.axhline(1.0, color="k", lw=0.8, ls="--")
    ax.set_xticks(range(len(D)))
    ax.set_xticklabels(labels, rotation=75, fontsize=7)
    ax.set_ylabel("Miner damage D per spectrum (grey: none)")
    ax.set_title("Damage per member and mode")
    save(fig, os.path.join(out, "gearbox_damage.png"))

    x = [float(r["roll angle"]) for r in path]
    fig, ax = plt.subplots(figsize=(7, 4))
    ax.plot(x, [float(r["theta_fl"]) for r in path], "C3-o", ms=3, label="flash temperature [K]")
    ax.set_xlabel("roll angle of the pinion [deg]")
    ax.set_ylabel("flash temperature [K]")
    ax2 = ax.twinx()
    ax2.plot(x, [float(r["lambda"]) for r in path], "C0-s", ms=3, label="lambda [-]")
    ax2.set_ylabel("specific film thickness lambda [-]")
    ax.set_title("AGMA 925 along the path of contact (worst bin)")
    save(fig, os.path.join(out, "scuffing_path.png"))
    return 0


if __name__ == "__main__":
    sys.exit(main())
