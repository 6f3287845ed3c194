#!/usr/bin/python3
"""The Python module's speed and its Harris map (README.md).

References: the C++ re-solve of the same work, timed by the library inside the same Python
process (route::run's cost record: contact, post and output seconds); the batch study of the
same pair, cycle and reliefs (`gearfem batch inputs/harris_map.prm`, validation/harris_map);
the issue's bounds for time (1 ms per position, 1.5x the C++ re-solve, 15 s for the map,
0.3 s for the CLI's condensed run).
"""
import argparse, json, os, subprocess, sys, time

import numpy as np

import gearfem
from vcheck import Checks

SRC = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")


def resolve_speed(c):
    """10 torques x 40 positions on the demo's cycle, the smallest of five calls."""
    demo = gearfem.read_input(os.path.join(SRC, "inputs", "demo_fixed_mesh.prm"), set={"Solve/Plots": False})
    cycle = gearfem.condense(demo)
    torques = list(np.linspace(100.0, 400.0, 10))
    wall, cpp = [], []
    for _ in range(5):
        t = time.perf_counter()
        r = cycle.solve(torques=torques)
        wall.append(time.perf_counter() - t)
        cost = r.run["cost"]
        cpp.append(cost["contact_seconds"] + cost["post_seconds"] + cost["output_seconds"])
    n = len(r.sweep["STE [um]"])
    w, k = min(wall), min(cpp)
    print(f"re-solve from Python: {w * 1e3:.1f} ms for {n} positions ({w / n * 1e3:.3f} ms each), "
          f"C++ re-solve {k * 1e3:.1f} ms ({w / k:.2f}x)")
    c.true("positions re-solved", n == 400, n, 400, "10 torques x 40 positions")
    c.at_most("Python re-solve per position, wall", w / n * 1e3, 1.0, "issue bound", " ms")
    c.at_most("Python call / C++ re-solve of the same work", w / k, 1.5, "issue bound", "x")
    return cycle


def cli_fixed_cost(c, gearfem_exe, out):
    """`gearfem solve --condensed` with plots off on the demo (the smallest of three runs)."""
    cdir = os.path.join(out, "demo_cycle")
    subprocess.run([gearfem_exe, "condense", os.path.join(SRC, "inputs", "demo_fixed_mesh.prm"), "--output-dir", cdir],
                   check=True, capture_output=True)
    prm = os.path.join(out, "demo_no_plots.prm")
    with open(prm, "w") as f:
        f.write(open(os.path.join(SRC, "inputs", "demo_fixed_mesh.prm")).read() + "\nsubsection Solve\n  set Plots = false\nend\n")
    times, start = [], []
    for _ in range(3):
        t = time.perf_counter()
        subprocess.run([gearfem_exe, "solve", prm, "--condensed", os.path.join(cdir, "condensed.h5"),
                        "--output-dir", os.path.join(out, "demo_on_cycle")], check=True, capture_output=True)
        times.append(time.perf_counter() - t)
        t = time.perf_counter()
        subprocess.run([gearfem_exe, "--version"], check=True, capture_output=True)
        start.append(time.perf_counter() - t)
    print(f"gearfem solve --condensed (demo, 40 positions, plots off): {min(times):.3f} s wall; "
          f"gearfem --version alone {min(start):.3f} s")
    c.at_most("gearfem solve --condensed, demo, plots off, wall", min(times), 0.3, "issue bound", " s")
    c.info("of which the start of the executable (gearfem --version)", min(start), "—",
           "dynamic linking of deal.II and its ~200 libraries (README.md)")


def harris(c, out):
    fig = json.load(open(os.path.join(out, "harris", "figures.json")))
    c.at_most("Harris map 20 x 12 x 40 on one cycle, build included, wall", fig["total_seconds"], 15.0,
              "issue bound", " s")
    for ca, (t, v) in sorted(fig["batch_minima"].items(), key=lambda kv: float(kv[0])):
        pt, pv = fig["minima"][ca]
        c.true(f"C_a {ca} um: torque of the minimum", pt == t, pt, t, "gearfem batch, validation/harris_map")
        c.rel(f"C_a {ca} um: minimum p-p STE", pv, v, 1e-3, "gearfem batch, validation/harris_map", " um")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--gearfem", required=True)
    ap.add_argument("--out", required=True)
    a = ap.parse_args()
    c = Checks("python_module", a.out)
    harris(c, a.out)
    resolve_speed(c)
    cli_fixed_cost(c, a.gearfem, a.out)
    return c.finish()


if __name__ == "__main__":
    sys.exit(main())
