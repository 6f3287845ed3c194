#!/usr/bin/python3
"""Single tooth under ISO tip load: FE against ISO 6336-3 method B (README.md, "Checks").

Usage: check.py <results.csv> --status <exit of validate_single_tooth> --out <results dir>
The `iso` column is F_t/(b m) Y_Fa Y_Sa of lib/rating/iso6336 (ISO 6336-3 formulas on the
30-degree construction, unit-tested against the standard's closed form to 1e-6)."""
import argparse
import os
import sys

from vcheck import Checks, read_csv

CASES = [(19, 0.0), (50, 0.0), (100, 0.0), (50, 0.5)]


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("csv")
    ap.add_argument("--status", type=int, required=True)
    ap.add_argument("--out")
    args = ap.parse_args()
    c = Checks("single_tooth_root_stress", args.out)
    c.true("validate_single_tooth exit status (its own asserts)", args.status == 0, f"exit {args.status}", "exit 0",
           "tests/unit/fem/validate_single_tooth.cc")
    rows = read_csv(args.csv) if os.path.exists(args.csv) else []
    for z, x in CASES:
        lv = sorted((r for r in rows if r["z"] == z and abs(r["x"] - x) < 1e-12), key=lambda r: r["level"])
        name = f"z {z}, x {x:+g}"
        if len(lv) != 3:
            c.true(f"{name}: 3 mesh levels", False, f"{len(lv)} levels", "3", "validate_single_tooth.cc")
            continue
        c.rel(f"{name}: FE peak fillet stress (Richardson) vs ISO sigma_F0", lv[2]["richardson"], lv[2]["iso"], 0.10,
              "VALIDATION.md: ISO 6336-3 method B, within about ±10 % (tip load)", " MPa")
        c.rel(f"{name}: FE peak, level 2 vs level 1", lv[2]["fe peak"], lv[1]["fe peak"], 0.02,
              "mesh convergence: uniform refinement changes the peak < 2 %", " MPa")
    return c.finish()


if __name__ == "__main__":
    sys.exit(main())
