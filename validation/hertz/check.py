#!/usr/bin/python3
"""Hertz line contact: FE p0 and a against Johnson's closed form (README.md, "Checks").

Usage: check.py <validate_hertz output> --table <tracked convergence.md> --out <results dir>
The closed form is computed here from the case data of README.md, independently of
lib/contact/hertz.cc."""
import argparse
import math
import sys

from vcheck import Checks, num, read_md_tables, strip_columns, write_if_changed

F, B = 10e3, 10e-3  # total normal force [N], thickness [m]
CASES = {  # name in the table: R1, R2 [m], E1, E2 [Pa], nu1, nu2, plane strain?
    "equal, plane stress": (20e-3, 20e-3, 210e9, 210e9, 0.3, 0.3, False),
    "equal, plane strain": (20e-3, 20e-3, 210e9, 210e9, 0.3, 0.3, True),
    "R2 35 mm, E2 110 GPa, plane stress": (20e-3, 35e-3, 210e9, 110e9, 0.3, 0.34, False),
    "R2 35 mm, E2 110 GPa, plane strain": (20e-3, 35e-3, 210e9, 110e9, 0.3, 0.34, True),
}
TOL_P0, TOL_A, TOL_METHODS = 0.015, 0.03, 0.005
JOHNSON = "Johnson 1985 §4.3 closed form"


def johnson(R1, R2, E1, E2, nu1, nu2, strain):
    """Half-width a [mm] and peak pressure p0 [MPa] of a line contact (Johnson 1985, §4.3)."""
    w = F / B
    R = R1 * R2 / (R1 + R2)
    if strain:
        inv = (1 - nu1 ** 2) / E1 + (1 - nu2 ** 2) / E2
    else:
        inv = 1 / E1 + 1 / E2
    a = math.sqrt(4 * w * R * inv / math.pi)
    return a * 1e3, 2 * w / (math.pi * a) / 1e6


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("log")
    ap.add_argument("--status", type=int, default=0, help="exit status of validate_hertz")
    ap.add_argument("--table")
    ap.add_argument("--out")
    args = ap.parse_args()
    with open(args.log) as f:
        lines = [line.rstrip("\n") for line in f]
    rows = [line for line in lines if line.startswith("|")]
    if args.table:
        write_if_changed(args.table, "\n".join(strip_columns(rows)) + "\n")
    c = Checks("hertz", args.out)
    c.true("validate_hertz exit status (its own ratio asserts)", args.status == 0, f"exit {args.status}",
           "exit 0", "tests/unit/contact/validate_hertz.cc")
    tables = read_md_tables(args.log)
    if not tables:
        c.true("convergence table present", False, "missing", "24 rows", "validate_hertz output")
        return c.finish()
    head, body = tables[0]
    col = {h: i for i, h in enumerate(head)}
    p0_by = {}
    for name, (R1, R2, E1, E2, nu1, nu2, strain) in CASES.items():
        a_ref, p0_ref = johnson(R1, R2, E1, E2, nu1, nu2, strain)
        seen = 0
        for r in body:
            if r[col["case"]] != name or r[col["h"]] == "a/4":
                continue  # the requirement holds from h = a/8 on (README)
            seen += 1
            label = f"{name}, {r[col['method']]}, h {r[col['h']]}"
            p0 = num(r[col["p0 fit [MPa]"]])
            a = num(r[col["a fit [mm]"]])
            p0_by[(name, r[col["method"]], r[col["h"]])] = p0
            c.rel(f"p0, {label}", p0, round(p0_ref, 2), TOL_P0, JOHNSON, " MPa")
            c.rel(f"a, {label}", a, round(a_ref, 5), TOL_A, JOHNSON, " mm")
        c.true(f"rows for {name}", seen == 4, f"{seen} rows", "4 (2 methods x a/8, a/16)", "validate_hertz.cc")
    for (name, method, h), p0 in sorted(p0_by.items()):
        if method == "penalty" and (name, "lagrange", h) in p0_by:
            c.rel(f"p0 penalty/Lagrange, {name}, h {h}", p0, p0_by[(name, "lagrange", h)], TOL_METHODS,
                  "contact-solver requirement: the two methods agree within 0.5 %", " MPa")
    return c.finish()


if __name__ == "__main__":
    sys.exit(main())
