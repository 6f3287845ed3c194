#!/usr/bin/env python3
"""STE smoothness of gearfem solve (README.md): the demo pair at 200 N m over
40 positions from A; RMS and largest residual of a cubic fit to the STE over the double-pair
zone (-5.9 ... -1.3 deg), in % of the mean STE. The reference is the smoothness of the exact
STE itself (a smooth function of the roll angle inside the double-pair zone), so the residual
is the discretisation ripple. Prints one line per (h_contact, Gap) and the wall time.

Usage: smoothness.py --gearfem BIN [--h 0.1 0.08] [--gap integrated node] [--out DIR]"""
import argparse
import csv
import os
import subprocess
import time

import numpy as np


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--gearfem", required=True)
    ap.add_argument("--base", default=os.path.join(os.path.dirname(__file__), "..", "..", "inputs", "demo_fixed_mesh.prm"))
    ap.add_argument("--h", type=float, nargs="+", default=[0.1, 0.08])
    ap.add_argument("--gap", nargs="+", default=["integrated", "node"])
    ap.add_argument("--out", default=os.path.join(os.path.dirname(__file__), "results", "smoothness"))
    a = ap.parse_args()
    base = open(a.base).read()
    print("| h_contact [mm] | Gap | RMS [%] | max [%] | mean STE [um] | wall [s] |")
    print("|---|---|---|---|---|---|")
    for h in a.h:
        for gap in a.gap:
            d = os.path.join(a.out, f"h{h:g}_{gap}")
            os.makedirs(d, exist_ok=True)
            prm = os.path.join(d, "case.prm")
            with open(prm, "w") as f:
                f.write(base + f"subsection Mesh\n  set h_contact = {h}\nend\n"
                        f"subsection Contact\n  set Gap = {gap}\nend\n"
                        "subsection Solve\n  set VTU = none\n  set Plots = false\nend\n")
            t0 = time.time()
            subprocess.run([a.gearfem, "solve", prm, "--output-dir", d], stdout=subprocess.DEVNULL, check=True)
            wall = time.time() - t0
            phi, ste = [], []
            with open(os.path.join(d, "sweep.csv")) as f:
                for r in csv.DictReader(f):
                    phi.append(float(r["roll angle [deg]"]))
                    ste.append(float(r["STE [um]"]))
            phi, ste = np.array(phi), np.array(ste)
            m = (phi >= -5.9) & (phi <= -1.3)
            res = ste[m] - np.polyval(np.polyfit(phi[m], ste[m], 3), phi[m])
            mean = ste[m].mean()
            print(f"| {h:g} | {gap} | {100 * np.sqrt(np.mean(res ** 2)) / mean:.3f} | "
                  f"{100 * np.abs(res).max() / mean:.3f} | {mean:.4f} | {wall:.1f} |", flush=True)


if __name__ == "__main__":
    main()
