#!/usr/bin/python3
"""Kahraman & Singh (1990) reference set: checks of the sweeps (README.md, "Checks").

Usage: check.py <RK4 sweep.csv> <DOPRI5 rtol 1e-12 sweep.csv> --out <results dir>
Columns of sweep.csv: direction (1 up, -1 down), Omega, -, RMS x, ..., contact loss fraction
(index 7), back contact fraction (index 8)."""
import argparse
import csv
import sys

from vcheck import Checks

KS = "Kahraman & Singh 1990 (VALIDATION.md, README)"


def read(path):
    with open(path, newline="") as f:
        return [[float(v) for v in r] for r in list(csv.reader(f))[1:] if r]


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("rk4")
    ap.add_argument("reference")
    ap.add_argument("--out")
    args = ap.parse_args()
    c = Checks("kahraman_singh", args.out)
    a, b = read(args.rk4), read(args.reference)
    c.true("same speeds in both sweeps", len(a) == len(b) and all(x[:2] == y[:2] for x, y in zip(a, b)),
           f"{len(a)} / {len(b)} points", "equal", "sweep_rk4.prm, sweep_reference.prm")
    diff = max(abs(x[3] - y[3]) / y[3] for x, y in zip(a, b)) if a and len(a) == len(b) else None
    c.at_most("max relative RMS difference, RK4 128 steps/period vs DOPRI5 rtol 1e-12", diff, 1e-3,
              "VALIDATION.md: integrator against a tight-tolerance reference; dynamics convergence requirement 1e-3")
    up, down = [r for r in b if r[0] == 1], [r for r in b if r[0] == -1]
    iu = max(range(1, len(up)), key=lambda i: up[i][3] - up[i - 1][3])
    idn = max(range(1, len(down)), key=lambda i: down[i - 1][3] - down[i][3])
    w_up, w_down = up[iu][1], down[idn][1]
    c.within("jump up of the up sweep (Omega)", w_up, 0.8, 1.0,
             KS + ": softening primary resonance, jump near Omega 1 and below it")
    c.true("hysteresis: jump down of the down sweep below the jump up", w_down < w_up,
           f"{w_down:.3f} < {w_up:.3f}", "down < up", KS + " (softening: the branches split)")
    sup = [r for r in up if 0.45 <= r[1] <= 0.55]
    k = max(range(len(sup)), key=lambda i: sup[i][3]) if sup else None
    c.true("superharmonic: interior RMS maximum of the up sweep in Omega [0.45, 0.55]",
           k is not None and 0 < k < len(sup) - 1, f"Omega {sup[k][1]:.3f}" if sup else "no points",
           "near Omega 0.5 (±10 %)", KS)
    single = sum(1 for r in b if r[7] > 0 and r[8] == 0)
    none = sum(1 for r in b if r[7] == 0 and r[8] == 0)
    double = sum(1 for r in b if r[8] > 0)
    c.at_least("points with single-sided impacts (contact loss, no back contact)", single, 1, KS)
    c.at_least("points without impact", none, 1, KS)
    c.info("points with double-sided impacts", double, "—", "not expected at F_m = 0.1 (README)")
    return c.finish()


if __name__ == "__main__":
    sys.exit(main())
