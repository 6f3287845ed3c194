#!/usr/bin/python3
"""Plots of a `gearfem dynamics` run: sweep.png, spectrum.png, phase.png, portraits.png.

Usage: /usr/bin/python3 scripts/plot_dynamics.py <output folder> [title]
Reads response.csv, poincare.csv, spectrum.csv, sweep.csv and portrait_<k>_response.csv /
portrait_<k>_poincare.csv (those that exist). Every
PNG is written to a temporary name in the same folder and renamed into place.
"""
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def read(path):
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    header = rows[0]
    cols = list(zip(*[[float(v) for v in r] for r in rows[1:] if r]))
    return header, [list(c) for c in cols]


def save(fig, path):
    tmp = os.path.join(os.path.dirname(path), "." + os.path.basename(path) + ".tmp.png")
    fig.savefig(tmp, dpi=120, bbox_inches="tight")
    plt.close(fig)
    os.replace(tmp, path)


def main():
    d = sys.argv[1]
    title = sys.argv[2] if len(sys.argv) > 2 else os.path.basename(os.path.abspath(d))
    sweep = os.path.join(d, "sweep.csv")
    if os.path.exists(sweep):
        h, c = read(sweep)
        fig, (a1, a2) = plt.subplots(2, 1, figsize=(7, 6), sharex=True)
        for direction, style, label in ((1, "o-", "up"), (-1, "x--", "down")):
            idx = [i for i, v in enumerate(c[0]) if v == direction]
            f = [c[2][i] for i in idx]
            a1.plot(f, [c[3][i] for i in idx], style, ms=3, label=label + " sweep")
            a2.plot(f, [c[7][i] for i in idx], style, ms=3, label=label)
        a1.set_ylabel(h[3])
        a1.legend()
        a1.grid(True, alpha=0.3)
        a1.set_title(title)
        a2.set_ylabel(h[7])
        a2.set_xlabel(h[2])
        a2.grid(True, alpha=0.3)
        save(fig, os.path.join(d, "sweep.png"))
    spectrum = os.path.join(d, "spectrum.csv")
    if os.path.exists(spectrum):
        h, c = read(spectrum)
        fig, ax = plt.subplots(figsize=(7, 4))
        ax.semilogy(c[1][1:], [max(v, 1e-300) for v in c[2][1:]], "-")
        ax.set_xlim(0, min(8, max(c[1])))
        ax.set_xlabel("order (frequency / mesh frequency)")
        ax.set_ylabel(h[2])
        ax.set_title(title + ": spectrum of the steady-state record")
        ax.grid(True, which="both", alpha=0.3)
        save(fig, os.path.join(d, "spectrum.png"))
    response = os.path.join(d, "response.csv")
    if os.path.exists(response):
        h, c = read(response)
        fig, (a1, a2) = plt.subplots(1, 2, figsize=(11, 4))
        a1.plot(c[2], c[3], "-", lw=0.7, label="trajectory")
        poincare = os.path.join(d, "poincare.csv")
        if os.path.exists(poincare):
            hp, cp = read(poincare)
            n = len(cp[0])
            k = max(0, n - 32)
            a1.plot(cp[1][k:], cp[2][k:], "r.", ms=6, label="Poincare (per mesh period)")
        a1.set_xlabel(h[2])
        a1.set_ylabel(h[3])
        a1.legend(fontsize=8)
        a1.set_title("phase portrait")
        a1.grid(True, alpha=0.3)
        a2.plot(c[0], c[2], "-", lw=0.8)
        a2b = a2.twinx()
        a2b.plot(c[0], c[5], "g-", lw=0.6, alpha=0.6)
        a2b.set_ylabel("contact state s (1 / 0 / -1)", color="g")
        a2b.set_ylim(-1.5, 1.5)
        a2.set_xlabel(h[0])
        a2.set_ylabel(h[2])
        a2.set_title(title + ": time response")
        a2.grid(True, alpha=0.3)
        save(fig, os.path.join(d, "phase.png"))
    portraits = []
    k = 1
    while os.path.exists(os.path.join(d, f"portrait_{k}_response.csv")):
        portraits.append(k)
        k += 1
    if portraits:
        n = len(portraits)
        cols = min(n, 3)
        rows = (n + cols - 1) // cols
        fig, axes = plt.subplots(rows, cols, figsize=(4.2 * cols, 3.6 * rows), squeeze=False)
        for ax, k in zip(axes.flat, portraits):
            h, c = read(os.path.join(d, f"portrait_{k}_response.csv"))
            ks = "[rad]" in h[1]
            # speed from the nominal mesh position: deg/s -> rpm, or Omega (dimensionless)
            speed = c[1][-1] / c[0][-1] if c[0][-1] else 0.0
            label = f"Omega = {speed:.4g}" if ks else f"{speed / 6:.4g} rpm"
            ax.plot(c[2], c[3], "-", lw=0.6)
            hp, cp = read(os.path.join(d, f"portrait_{k}_poincare.csv"))
            m = len(cp[0])
            ax.plot(cp[1][max(0, m - 32):], cp[2][max(0, m - 32):], "r.", ms=6)
            ax.set_title(f"{title}: {label}", fontsize=9)
            ax.set_xlabel(h[2])
            ax.set_ylabel(h[3])
            ax.grid(True, alpha=0.3)
        for ax in list(axes.flat)[n:]:
            ax.axis("off")
        fig.tight_layout()
        save(fig, os.path.join(d, "portraits.png"))


if __name__ == "__main__":
    main()
