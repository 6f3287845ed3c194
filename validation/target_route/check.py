"""Solve/Target's condensed route against the full FE route of the same choice (README.md).

Runs inputs/target_torque_sweep.prm as it is (auto: ten torques, the condensed route) and
with `Solve/Target route = full FE`, Plots off, each twice in a row (process CPU from os.wait4,
the smaller kept), then checks the route each took, that both deliver the same level, the
condensed results against the full ones over every torque and position, the condensation
error the run measured on itself against those differences, the estimates, and the CPU.
"""
import argparse
import csv
import json
import math
import os
import shutil
import subprocess
import sys

from vcheck import Checks

TORQUES = 10
TOL_DIFF = 1e-3       # condensed vs full: within 0.1 % (docs/model-choice.md, "The condensed cycle")
RATIO = (0.5, 2.0)    # measured on the run / the true condensation error (validation/error_estimate's bounds)
MAX_CPU_RATIO = 0.7   # the route pays: auto CPU / full FE CPU


def run(gearfem, prm, out, log):
    shutil.rmtree(out, ignore_errors=True)
    os.makedirs(out)
    with open(log, "w") as f:
        p = subprocess.Popen([gearfem, "solve", prm, "--output-dir", out], stdout=f, stderr=subprocess.STDOUT)
        _, status, ru = os.wait4(p.pid, 0)
    return os.waitstatus_to_exitcode(status), ru.ru_utime + ru.ru_stime


def table(path):
    with open(path) as f:
        rows = list(csv.reader(f))
    head = [h.split(" [")[0] for h in rows[0]]
    return {h: [float(r[i]) for r in rows[1:]] for i, h in enumerate(head)}


def by_torque(t):
    out = {}
    for i, T in enumerate(t["torque"]):
        out.setdefault(T, []).append(i)
    return out


def differences(a, b):
    """The condensation's error of what the run reports, from b (condensed) against a (full FE),
    the largest over all torques: the cycle mean of the STE, its p-p, the largest root stress
    (the larger of the two gears' errors)."""
    e = {"mean": 0.0, "pp": 0.0, "root": 0.0}
    for T, rows in by_torque(a).items():
        ste_a = [a["STE"][i] for i in rows]
        ste_b = [b["STE"][i] for i in rows]
        mean_a = sum(ste_a) / len(ste_a)
        e["mean"] = max(e["mean"], abs(sum(ste_b) / len(ste_b) - mean_a) / mean_a)
        pp_a = max(ste_a) - min(ste_a)
        e["pp"] = max(e["pp"], abs((max(ste_b) - min(ste_b)) - pp_a) / pp_a)
        for g in ("root stress pinion", "root stress gear"):
            ra = max(a[g][i] for i in rows)
            e["root"] = max(e["root"], abs(max(b[g][i] for i in rows) - ra) / ra)
    return e


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--gearfem", required=True)
    ap.add_argument("--input", required=True)
    ap.add_argument("--out", required=True)
    a = ap.parse_args()
    c = Checks("target_route", a.out)
    text = open(a.input).read()
    variants = {"auto": "subsection Solve\n  set Plots = false\nend\n",
                "full": "subsection Solve\n  set Plots = false\n  set Target route = full FE\nend\n"}
    res = {}
    for name, extra in variants.items():
        prm = os.path.join(a.out, f"{name}.prm")
        with open(prm, "w") as f:
            f.write(text + extra)
        cpu, rc = [], 0
        for k in range(2):
            rc, t = run(a.gearfem, prm, os.path.join(a.out, name), os.path.join(a.out, f"{name}.log"))
            cpu.append(t)
            print(f"[{len(res) * 2 + k + 1}/4] {name}: exit {rc}, {t:.2f} s CPU", flush=True)
            if rc:
                break
        res[name] = dict(rc=rc, cpu=min(cpu))
        c.true(f"{name}: gearfem solve exit status", rc == 0, rc, 0, "a finished run")
        if rc == 0:
            res[name]["run"] = json.load(open(os.path.join(a.out, name, "run.json")))["model_choice"]
            res[name]["sweep"] = table(os.path.join(a.out, name, "sweep.csv"))
    if any(r["rc"] for r in res.values()):
        sys.exit(c.finish())
    auto, full = res["auto"]["run"], res["full"]["run"]
    c.true("auto: route", auto["route"]["name"] == "condensed cycle", auto["route"]["name"], "condensed cycle",
           f"model_choice::plan_route: {TORQUES} torques over 100-340 N m pay for the build from 8")
    c.true("full: route", full["route"]["name"] == "full FE", full["route"]["name"], "full FE",
           "Solve/Target route = full FE")
    c.true("same delivered level (h_contact, DoFs)",
           auto["chosen"]["h_contact_mm"] == full["chosen"]["h_contact_mm"] and auto["chosen"]["dofs"] == full["chosen"]["dofs"],
           f'{auto["chosen"]["h_contact_mm"]:.4g} mm / {auto["chosen"]["dofs"]}',
           f'{full["chosen"]["h_contact_mm"]:.4g} mm / {full["chosen"]["dofs"]}', "the route comes after the choice")
    sa, sb = res["full"]["sweep"], res["auto"]["sweep"]
    c.true("rows", len(sa["STE"]) == len(sb["STE"]) == 40 * TORQUES, len(sb["STE"]), 40 * TORQUES, "10 torques x 40 positions")
    d = differences(sa, sb)
    measured = auto["route"]["condensation_error"]
    for q, key, label in (("mean", "mean_ste", "mean STE"), ("pp", "pp_ste", "p-p STE"),
                          ("root", "root_stress", "max root stress")):
        c.at_most(f"condensed vs full FE, {label} (the largest over the ten torques)", 100 * d[q], 100 * TOL_DIFF,
                  "the condensation's accuracy within a factor 2 of its scenes' loads (docs/model-choice.md)", " %")
        m = measured.get(key)
        r = m / d[q] if m is not None and d[q] > 0 else float("nan")
        c.within(f"condensation error measured on the run / its true value, {label}", r, RATIO[0], RATIO[1],
                 f"measured {100 * m:.4f} %, true {100 * d[q]:.4f} % (the condensed run against the full one); the run "
                 "solves the full FE where the STE, the root stresses and p_max peak at the lowest and highest torque"
                 if m is not None else "missing")
    for name in ("auto", "full"):
        r = res[name]["run"]
        c.true(f"{name}: the target met", r["met"], r["met"], True, "gearfem's own verdict on its estimates")
    for key in ("mean_ste", "pp_ste", "root_stress"):
        ea, ef, m = auto["estimate"][key], full["estimate"][key], measured[key]
        c.abs(f"auto estimate - full estimate, {key} (the measured condensation error, plus the p-p's swept ripple)",
              100 * (ea - ef), 100 * m, 100 * max(m, 2e-4) if key == "pp_ste" else 1e-6,
              "the estimates differ by the added condensation error (the p-p also by the condensed sweep's ripple)", " %")
    ratio = res["auto"]["cpu"] / res["full"]["cpu"]
    c.at_most("CPU auto (condensed) / full FE", ratio, MAX_CPU_RATIO,
              f'{res["auto"]["cpu"]:.2f} s / {res["full"]["cpu"]:.2f} s, the smaller of two runs each', "")
    sys.exit(c.finish())


if __name__ == "__main__":
    main()
