#!/usr/bin/python3
"""Gkimisis 2019 Table 1 cases against the thesis (README.md, "Checks").

Usage: check.py --out <results dir>
Reads results/<case>.log and results/ricker/<case>.log (gearfem dynamics console) and
results/profile.log (gearfem profile of inputs/seed000_32_60.prm)."""
import argparse
import os
import re
import sys

from vcheck import Checks

THESIS = "Gkimisis 2019 ch. 4, Table 1 cases (SEEDS.md)"
# case: (thesis outcome: contact loss?, what the thesis says)
CASES = {
    "case1_5Nm_600rpm": (False, "no contact loss"),
    "case2_20Nm_1200rpm": (True, "contact loss with period doubling"),
    "case3_40Nm_1200rpm": (False, "no contact loss"),
    "case4_20Nm_1200rpm_a+1mm": (True, "contact loss every period"),
}
# Known disagreements (README "Measured"): reported, not pass criteria.
KNOWN = {("table", "case4_20Nm_1200rpm_a+1mm"), ("Ricker", "case3_40Nm_1200rpm"),
         ("Ricker", "case4_20Nm_1200rpm_a+1mm")}


def figures(log):
    """Contact-loss fraction and period (in mesh periods) from a dynamics console log."""
    with open(log) as f:
        text = f.read()
    loss = re.search(r"contact loss fraction \[-\] = ([-+0-9.eE]+)", text)
    period = re.search(r"period \[[^\]]*\] = ([0-9.eE+-]+)", text)
    return (float(loss.group(1)) if loss else None, float(period.group(1)) if period else None)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--out", required=True)
    args = ap.parse_args()
    c = Checks("seed000_dynamics", args.out)
    for law, folder in (("table", args.out), ("Ricker", os.path.join(args.out, "ricker"))):
        for case, (loss_expected, text) in CASES.items():
            loss, period = figures(os.path.join(folder, case + ".log"))
            name = f"{law} law, {case}: contact loss"
            measured = None if loss is None else f"fraction {loss:g}, period {period:g}"
            if (law, case) in KNOWN:
                c.info(name, measured, text, "known disagreement, README (not tuned to the thesis)")
            else:
                c.true(name, loss is not None and (loss > 0) == loss_expected, measured,
                       "loss" if loss_expected else "no loss", THESIS)
            if case == "case2_20Nm_1200rpm":
                c.info(f"{law} law, {case}: period doubling", f"period {period}", "2 (thesis)",
                       "not reproduced (period 1), README")
    with open(os.path.join(args.out, "profile.log")) as f:
        text = f.read()
    eps = re.search(r"contact ratio\s*(?:eps_alpha\s*)?[=:]?\s*([0-9.]+)", text)
    rb1 = re.search(r"gear 1: .*?\brb ([0-9.]+)", text)
    c.within("Table 1 pair: contact ratio", float(eps.group(1)) if eps else None, 1.72, 1.73,
             "Gkimisis 2019 Table 1: 1.72-1.73 (SEEDS.md)")
    c.abs("Table 1 pair: base radius R_g1", float(rb1.group(1)) if rb1 else None, 45.105, 0.0005,
          "Gkimisis 2019 Table 1: 45.105 mm (SEEDS.md), rounded to 0.001 mm", " mm")
    return c.finish()


if __name__ == "__main__":
    sys.exit(main())
