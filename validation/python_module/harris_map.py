#!/usr/bin/python3
"""A Harris map scripted in Python on one condensed cycle (docs/python.md), against the batch study
of validation/harris_map (the same pair, cycle and reliefs through `gearfem batch`).

    harris_map.py OUT [--batch-dir DIR]

Builds the cycle of inputs/harris_map.prm without relief (full Parker pair, 25 mm bores, 40
positions) at the batch's build torque and range (141.4 N m, 20-1000 N m: the geometric middle
of the study's torques), as a one-rank batch builds it from its first design (no relief), re-solves 20 long linear relief amounts (0.75-15 um over 6.7 mm on both gears) at the
study's 12 torques, and writes harris_python.csv (amount, torque, p-p STE) and figures.json
(the build, the map's wall time, its minima). With --batch-dir, the long-relief minima are
compared with that study's batch.csv.
"""
import argparse, json, os, sys, time

import numpy as np

import gearfem

SRC = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")


def harris_map(out):
    t0 = time.perf_counter()
    study = gearfem.read_input(os.path.join(SRC, "inputs", "harris_map.prm"),
                               set={"Condense/Build torque": float(np.sqrt(20.0 * 1000.0)),
                                    "Condense/Torque range": "20, 1000", "Solve/Plots": False,
                                    "Gear 1/Tip relief": "none", "Gear 2/Tip relief": "none"})
    torques = [float(t) for t in study.get("Solve/Torques").split(",")]
    cycle = gearfem.condense(study)
    t_build = time.perf_counter() - t0
    amounts = np.round(np.arange(1, 21) * 0.75, 2)
    rows, t1 = [], time.perf_counter()
    for i, ca in enumerate(amounts):
        r = cycle.solve(torques=torques, relief={"Gear 1/Tip relief": "linear", "Gear 2/Tip relief": "linear",
                                                 "Gear 1/Tip relief amount": ca, "Gear 2/Tip relief amount": ca,
                                                 "Gear 1/Tip relief length": 6.7, "Gear 2/Tip relief length": 6.7})
        T, ste = r.sweep["torque [N m]"], r.sweep["STE [um]"]
        for t in torques:
            s = ste[T == t]
            rows.append((ca, t, s.max() - s.min()))
        print(f"[{i + 1}/{len(amounts)}] C_a {ca} um: {len(T)} positions", flush=True)
    t_map = time.perf_counter() - t1
    rows = np.array(rows)
    np.savetxt(os.path.join(out, "harris_python.csv"), rows, delimiter=",",
               header="relief amount [um],torque [N m],p-p STE [um]", comments="")
    minima = {}
    for ca in amounts:
        m = rows[rows[:, 0] == ca]
        k = int(np.argmin(m[:, 2]))
        minima[f"{ca:g}"] = [float(m[k, 1]), float(m[k, 2])]
    fig = {"build_seconds": t_build, "map_seconds": t_map, "total_seconds": t_build + t_map,
           "positions": int(len(amounts) * len(torques) * cycle.positions), "minima": minima}
    json.dump(fig, open(os.path.join(out, "figures.json"), "w"), indent=1)
    print(f"Harris map: {len(amounts)} reliefs x {len(torques)} torques x {cycle.positions} positions, "
          f"cycle build {t_build:.1f} s, map {t_map:.1f} s, total {t_build + t_map:.1f} s")
    return fig


def batch_minima(batch_dir):
    """Minimum p-p STE over the torques of each long-relief design of batch.csv."""
    import csv
    out = {}
    rows = list(csv.DictReader(open(os.path.join(batch_dir, "batch.csv"))))
    key = "STE peak-to-peak [um]"
    for d in ("long_03", "long_06", "long_09", "long_12", "long_15"):
        r = [x for x in rows if x["id [text]"] == d]
        k = int(np.argmin([float(x[key]) for x in r]))
        out[str(int(d[-2:]))] = [float(r[k]["torque [N m]"]), float(r[k][key])]
    return out


if __name__ == "__main__":
    ap = argparse.ArgumentParser()
    ap.add_argument("out")
    ap.add_argument("--batch-dir")
    a = ap.parse_args()
    os.makedirs(a.out, exist_ok=True)
    fig = harris_map(a.out)
    if a.batch_dir:
        ref = batch_minima(a.batch_dir)
        fig["batch_minima"] = ref
        json.dump(fig, open(os.path.join(a.out, "figures.json"), "w"), indent=1)
        for ca, (t, v) in ref.items():
            pt, pv = fig["minima"][ca]
            print(f"C_a {ca} um: Python minimum {pv:.5f} um at {pt} N m; batch {v:.5f} um at {t} N m "
                  f"({(pv - v) / v * 100:+.4f} %)")
