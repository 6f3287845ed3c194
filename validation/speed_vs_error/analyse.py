#!/usr/bin/env python3
"""Metrics, errors against the converged reference, tables and Pareto plots of the
speed-against-error study (README.md). Reads results/<pair>/<rung>/ of study.py.

    analyse.py [--out results]   -> results/metrics.csv, results/table.md,
                                    results/which_model.md, results/pareto_<metric>.png

Metrics per rung and torque: mean STE, peak-to-peak STE, the amplitudes of the first three
mesh-order harmonics of STE (DFT over one pitch; their errors relative to the reference's
first-harmonic amplitude), mean mesh stiffness (secant, per face
width), max root stress (pinion and gear, the worse error of the two), max Hertzian
pressure (FE: the largest recovered flank-to-flank p_max over the cycle). The error of a
rung is its largest relative error over the three torques. Time: wall time of one
40-position cycle (FE: contact + post of the sweep / torques; analytical: the library's
own timing of the evaluation), set-up (FE: mesh, assembly, factorisation), peak memory.
"""
import argparse
import csv
import json
import math
import os
import re
import sys

import numpy as np

from pairs import CONDENSED, ANALYTICAL, PAIRS, fe_candidates

HERE = os.path.dirname(os.path.abspath(__file__))
METRICS = [("mean_ste", "mean STE"), ("pp_ste", "peak-to-peak STE"), ("h1", "STE harmonic 1"),
           ("h2", "STE harmonic 2"), ("h3", "STE harmonic 3"), ("mean_k", "mean mesh stiffness"),
           ("root_stress", "max root stress"), ("p_max", "max Hertzian pressure")]


def read_csv(path):
    with open(path) as f:
        r = csv.reader(f)
        head = [re.sub(r" \[.*\]$", "", h.strip()) for h in next(r)]
        rows = [[float(x) for x in row] for row in r if row]
    return {h: np.array([row[i] for row in rows]) for i, h in enumerate(head)}


def ste_metrics(ste):
    """mean, p-p and the amplitudes of mesh orders 1..3 of one pitch of uniformly sampled STE."""
    x = np.asarray(ste, dtype=float)
    X = np.fft.rfft(x) / len(x)
    amp = [2 * abs(X[k]) if k < len(X) else float("nan") for k in (1, 2, 3)]
    return dict(mean_ste=x.mean(), pp_ste=x.max() - x.min(), h1=amp[0], h2=amp[1], h3=amp[2])


def read_cost(d):
    c = {}
    p = os.path.join(d, "cost.txt")
    if os.path.exists(p):
        for line in open(p):
            k, v = line.split()
            c[k] = float(v)
    return c


def fe_metrics(d, pair):
    """{torque: metrics}, cost of a gearfem solve rung."""
    s = read_csv(os.path.join(d, "out", "sweep.csv"))
    res = {}
    for T in pair["torques"]:
        m = np.isclose(s["torque"], T)
        r = ste_metrics(s["STE"][m])
        r["mean_k"] = s["k_secant per width"][m].mean()
        r["root_stress_1"] = s["root stress pinion"][m].max()
        r["root_stress_2"] = s["root stress gear"][m].max()
        r["p_max"] = s["p_max"][m].max()
        res[T] = r
    run = json.load(open(os.path.join(d, "out", "run.json")))
    c = run["cost"]
    n = len(pair["torques"])
    # CPU time (the machine is shared: wall time is reported, CPU time is what is compared).
    cost = dict(cycle=c["cpu_sweep_seconds"] / n, setup=c["cpu_setup_seconds"], memory=c["peak_memory_mb"],
                dofs=c["dofs"], wall_cycle=(c["contact_seconds"] + c["post_seconds"]) / n,
                wall_setup=c.get("setup_seconds", float("nan")))
    if "error_estimate" in run:
        cost["error_estimate"] = run["error_estimate"]
    return res, cost


def condensed_metrics(d, pair):
    """A condensed rung: the re-solve's metrics; its cycle is the re-solve's CPU time, its set-up
    the `gearfem condense` run's (meshing, factorising and condensing the cycle)."""
    res, cost = fe_metrics(d, pair)
    c = read_cost(d)
    cost["setup"] = c.get("condense_cpu", float("nan"))
    cost["wall_setup"] = c.get("condense_wall", float("nan"))
    cost["memory"] = max(c.get("condense_rss_mb", 0.0), c.get("rss_mb", 0.0))
    return res, cost


def rate_metrics(d, pair, iso):
    """Analytical rungs from `gearfem rate`: mesh_cycle.csv, or the ISO 6336 rows."""
    log = open(os.path.join(d, "rate.log")).read()
    b = pair["face_width"]
    res = {}
    if iso:
        rows = {}
        with open(os.path.join(d, "out", "rating.csv")) as f:
            r = csv.reader(f)
            head = next(r)
            for row in r:
                rows[(row[0], row[2])] = [float(v) for v in row[5:]]
        c = rows[("ISO 6336", "c_gamma_alpha")][0]
        rb1 = 0.5 * pair["module"] * pair["teeth"][0] * math.cos(math.radians(20.0))
        for i, T in enumerate(pair["torques"]):
            F = T * 1e3 / rb1
            res[T] = dict(mean_ste=F / (b * c), mean_k=c, root_stress_1=rows[("ISO 6336", "sigma_F01")][i],
                          root_stress_2=rows[("ISO 6336", "sigma_F02")][i], p_max=rows[("ISO 6336", "sigma_H1")][i])
        ms = float(re.search(r"ratings \(.*\) in ([\d.e+-]+) ms", log).group(1))
    else:
        t = read_csv(os.path.join(d, "out", "mesh_cycle.csv"))
        for T in pair["torques"]:
            m = np.isclose(t["pinion torque"], T)
            r = ste_metrics(t["loaded STE"][m])
            r["mean_k"] = t["mesh stiffness"][m].mean() / b
            res[T] = r
        ms = float(re.search(r"mesh cycle \(.*\): \d+ positions x \d+ torques in ([\d.e+-]+) ms", log).group(1))
    cost = dict(cycle=ms * 1e-3 / len(pair["torques"]), setup=0.0, memory=read_cost(d).get("rss_mb", float("nan")))
    return res, cost


def calibrated_metrics(d, pair, ref_cost):
    t = read_csv(os.path.join(d, "out", "calibration.csv"))
    b = pair["face_width"]
    rb1 = 0.5 * pair["module"] * pair["teeth"][0] * math.cos(math.radians(20.0))
    res = {}
    for T in pair["torques"]:
        m = np.isclose(t["torque"], T)
        r = ste_metrics(t["STE held out"][m])
        r["mean_k"] = np.mean(T * 1e3 / rb1 / t["STE held out"][m]) / b
        res[T] = r
    log = open(os.path.join(d, "calibrate.log")).read()
    ms = float(re.search(r"calibrated model: 40-position cycle in ([\d.e+-]+) ms", log).group(1))
    # Set-up: the fit (the calibrate run) plus the reference FE it is trained on (two torques).
    setup = read_cost(d).get("wall", float("nan")) + ref_cost["setup"] + 2 * ref_cost["cycle"]
    return res, dict(cycle=ms * 1e-3, setup=setup, memory=read_cost(d).get("rss_mb", float("nan")))


def collect(out):
    """{pair: {rung: (label, group, {T: metrics}, cost)}}"""
    data = {}
    for key, pair in PAIRS.items():
        pd = os.path.join(out, key)
        if not os.path.isdir(pd):
            continue
        data[key] = {}
        for name, (label, group, _) in fe_candidates(pair).items():
            d = os.path.join(pd, name)
            if not os.path.exists(os.path.join(d, "done")):
                continue
            if group == "reference check":
                run = json.load(open(os.path.join(d, "out", "run.json")))
                data[key][name] = (label, group, {}, dict(run["cost"], error_estimate=run.get("error_estimate"),
                                                          cycle=float("nan"), setup=float("nan"),
                                                          memory=run["cost"]["peak_memory_mb"]))
            else:
                data[key][name] = (label, group) + fe_metrics(d, pair)
        for name, (label, group, _) in CONDENSED.items():
            d = os.path.join(pd, name)
            if os.path.exists(os.path.join(d, "done")):
                data[key][name] = (label, group) + condensed_metrics(d, pair)
        for name, (label, group) in ANALYTICAL.items():
            d = os.path.join(pd, name)
            if not os.path.exists(os.path.join(d, "done")):
                continue
            if name == "calibrated":
                if "ref" in data[key]:
                    data[key][name] = (label, group) + calibrated_metrics(d, pair, data[key]["ref"][3])
            else:
                data[key][name] = (label, group) + rate_metrics(d, pair, name == "iso6336")
    return data


def rel_error(m, r, metric):
    """Largest relative error over the torques (None where the rung has no such output)."""
    errs = []
    for T, rv in r.items():
        mv = m.get(T, {})
        if metric == "root_stress":
            if "root_stress_1" not in mv:
                return None
            errs += [abs(mv[f"root_stress_{i}"] / rv[f"root_stress_{i}"] - 1) for i in (1, 2)]
        else:
            if metric not in mv or mv[metric] is None or not np.isfinite(mv[metric]):
                return None
            # Harmonic amplitudes relative to the reference's first harmonic: a higher
            # harmonic can be nearly zero (FZG type C: 0.035 um of order 2 at 94 N m).
            den = rv["h1"] if metric in ("h1", "h2", "h3") else rv[metric]
            errs.append(abs(mv[metric] - rv[metric]) / abs(den))
    return max(errs) if errs else None


def errors(data):
    """{pair: {rung: {metric: error}}} against each pair's reference."""
    e = {}
    for key, rungs in data.items():
        if "ref" not in rungs:
            continue
        ref = rungs["ref"][2]
        e[key] = {name: {m: rel_error(v[2], ref, m) for m, _ in METRICS} for name, v in rungs.items()
                  if v[1] != "reference check"}
    return e


def pareto_front(points):
    """Indices of the points (time, error) that no faster point beats in error."""
    order = sorted(range(len(points)), key=lambda i: (points[i][0], points[i][1]))
    front, best = [], float("inf")
    for i in order:
        if points[i][1] < best:
            front.append(i)
            best = points[i][1]
    return front


def fmt_err(v):
    return "–" if v is None else f"{100 * v:.3g}"


def fmt_t(v):
    if v is None or not np.isfinite(v):
        return "–"
    return f"{v:.3g}"


def write_table(data, err, path):
    lines = ["# Speed against error", "",
             "Errors are the largest relative errors [%] over the three torques against the reference "
             "(full gears, Q2, Lagrange, h_contact 0.05 mm, h_fillet 0.15 mm). `cycle`: CPU time of one "
             "40-position cycle [s] (the machine was shared; the wall time of the FE sweep is in the next "
             "column); `set-up`: CPU time of parsing, meshing, assembly and factorisation [s] (calibrated: "
             "the fit plus the reference FE of the two training torques; condensed: the `gearfem condense` run); "
             "memory: peak resident set [MB]. "
             "Harmonic errors are relative to the reference's first-harmonic amplitude. "
             "Analytical rungs: the library's own timing of the evaluation (wall, in-process). "
             "`–`: the rung has no such output.", ""]
    for key, rungs in data.items():
        if key not in err:
            continue
        lines += [f"## {PAIRS[key]['title']}, T1 = " + " / ".join(f"{t:g}" for t in PAIRS[key]['torques']) + " N m",
                  "", "| model | DoFs | cycle CPU [s] | cycle wall [s] | set-up CPU [s] | memory [MB] | " +
                  " | ".join(label for _, label in METRICS) + " |",
                  "|---|---|---|---|---|---|" + "---|" * len(METRICS)]
        for name, (label, group, res, cost) in rungs.items():
            if group in ("modelling choice", "reference check"):
                continue
            lines.append(f"| {label} | {int(cost['dofs']) if 'dofs' in cost else '–'} | {fmt_t(cost['cycle'])} | "
                         f"{fmt_t(cost.get('wall_cycle'))} | "
                         f"{fmt_t(cost['setup'])} | {fmt_t(cost['memory'])} | " +
                         " | ".join(fmt_err(err[key][name][m]) for m, _ in METRICS) + " |")
        ref = rungs["ref"][2]
        lines += ["", "Reference values (per torque): " + "; ".join(
            f"{T:g} N m: mean STE {r['mean_ste']:.4g} um, p-p {r['pp_ste']:.4g} um, harmonics "
            f"{r['h1']:.3g} / {r['h2']:.3g} / {r['h3']:.3g} um, k {r['mean_k']:.4g} N/(mm um), root "
            f"{r['root_stress_1']:.4g} / {r['root_stress_2']:.4g} MPa, p_max {r['p_max']:.4g} MPa"
            for T, r in ref.items()), ""]
        ee = rungs["ref_check"][3].get("error_estimate") if "ref_check" in rungs else None
        if ee:
            worst = {}
            for smp in ee.get("samples", []):
                for q, v in smp.items():
                    if isinstance(v, dict) and "relative" in v:
                        worst[q] = max(worst.get(q, 0.0), abs(v["relative"]))
            lines += ["Reference error estimate (`Solve/Error estimate`, run `ref_check`: 3 positions at the middle torque re-solved with "
                      f"h halved, {ee.get('fine_dofs', '?')} DoFs, Richardson order 2), largest relative error: "
                      + ", ".join(f"{q} {100 * v:.3g} %" for q, v in worst.items()), ""]
        if "plane_strain" in rungs and "full_default" in rungs:
            ps, pd = rungs["plane_strain"][2], rungs["full_default"][2]
            diff = {m: max(abs(ps[T][m] / pd[T][m] - 1) for T in pd) for m in ("mean_ste", "pp_ste", "mean_k")}
            lines += ["Plane strain against plane stress (a modelling choice, not an error; default mesh): "
                      + ", ".join(f"{lab} {100 * diff[m]:.3g} %" for m, lab in
                                  (("mean_ste", "mean STE"), ("pp_ste", "p-p STE"), ("mean_k", "mean stiffness"))), ""]
    tmp = path + ".tmp"
    open(tmp, "w").write("\n".join(lines) + "\n")
    os.replace(tmp, path)


QUESTIONS = [("mean STE within 2 %", ["mean_ste"], 0.02), ("mean mesh stiffness within 2 %", ["mean_k"], 0.02),
             ("peak-to-peak STE within 2 %", ["pp_ste"], 0.02), ("peak-to-peak STE within 10 %", ["pp_ste"], 0.10),
             ("first STE harmonic within 5 %", ["h1"], 0.05), ("STE harmonics 1-3 within 10 %", ["h1", "h2", "h3"], 0.10),
             ("mean and p-p STE within 1 %", ["mean_ste", "pp_ste"], 0.01),
             ("root stress within 3 %", ["root_stress"], 0.03), ("root stress within 10 %", ["root_stress"], 0.10),
             ("max Hertzian pressure within 5 %", ["p_max"], 0.05), ("max Hertzian pressure within 10 %", ["p_max"], 0.10)]


def which_model(data, err, path):
    """The cheapest rung (by cycle + set-up time, worst over the pairs) that answers each question."""
    pairs = [k for k in err]
    names = [n for n in data[pairs[0]] if n != "ref" and data[pairs[0]][n][1] not in ("modelling choice", "reference check")]
    lines = ["# Which model for which question", "",
             "Generated by validation/speed_vs_error/analyse.py from the study's runs. A rung answers a "
             "question when its error meets the bound on every torque of every pair (" +
             ", ".join(PAIRS[k]["title"] for k in pairs) + "). Cost: set-up + one 40-position cycle, "
             "the largest over the pairs.", "",
             "| question | cheapest rung | its cost [s] | its worst error [%] | next rungs that answer it |",
             "|---|---|---|---|---|"]
    for q, ms, tol in QUESTIONS:
        ok = []
        for n in names:
            if not all(n in err[k] for k in pairs):
                continue
            es = [err[k][n][m] for k in pairs for m in ms]
            if any(e is None for e in es) or max(es) > tol:
                continue
            cost = max(data[k][n][3]["cycle"] + data[k][n][3]["setup"] for k in pairs)
            ok.append((cost, n, max(es)))
        ok.sort()
        if ok:
            c, n, e = ok[0]
            nxt = ", ".join(f"{data[pairs[0]][m][0]} ({cc:.3g} s)" for cc, m, _ in ok[1:3])
            lines.append(f"| {q} | {data[pairs[0]][n][0]} | {c:.3g} | {100 * e:.3g} | {nxt or '–'} |")
        else:
            lines.append(f"| {q} | none below the reference | – | – | – |")
    lines += ["", "## The default of `gearfem solve` (requirement: a cheaper FE model that meets STE within 1 % "
              "on all three pairs becomes the default)", ""]
    d = "full_default"
    if all(d in err[k] for k in pairs):
        de = max(err[k][d][m] for k in pairs for m in ("mean_ste", "pp_ste"))
        lines.append(f"Today's default (full gears, Q2, h_contact m/30): worst mean/p-p STE error {100 * de:.3g} %.")
        cheaper = []
        for n in names:
            if n == d or not data[pairs[0]][n][1].startswith("FE") or not all(n in err[k] for k in pairs):
                continue
            if any(data[k][n][3]["cycle"] + data[k][n][3]["setup"] >= data[k][d][3]["cycle"] + data[k][d][3]["setup"]
                   for k in pairs):
                continue
            e = max(err[k][n][m] for k in pairs for m in ("mean_ste", "pp_ste"))
            cheaper.append((e, n))
        for e, n in sorted(cheaper):
            lines.append(f"- cheaper on every pair: {data[pairs[0]][n][0]}: worst mean/p-p STE error {100 * e:.3g} %"
                         + (" (meets 1 %)" if e <= 0.01 else ""))
    tmp = path + ".tmp"
    open(tmp, "w").write("\n".join(lines) + "\n")
    os.replace(tmp, path)


def plots(data, err, out):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    markers = {"FE mesh": "o", "FE element": "s", "FE method": "D", "FE sector": "^", "analytical": "v",
               "calibrated": "*", "FE condensed": "P"}
    pairs = [k for k in err]
    for m, label in METRICS:
        fig, axes = plt.subplots(1, len(pairs), figsize=(5.2 * len(pairs), 4.6), squeeze=False)
        for ax, key in zip(axes[0], pairs):
            pts, names = [], []
            for name, (lab, group, _, cost) in data[key].items():
                if name == "ref" or group in ("modelling choice", "reference check") or err[key][name][m] is None:
                    continue
                e = err[key][name][m]
                pts.append((max(cost["cycle"], 1e-6), max(e, 1e-6)))
                names.append((name, lab, group))
            front = set(pareto_front(pts))
            for i, ((t, e), (name, lab, group)) in enumerate(zip(pts, names)):
                ax.loglog(t, 100 * e, markers.get(group, "o"), ms=9 if i in front else 6,
                          mfc="C3" if i in front else "none", mec="C3" if i in front else "C0")
                ax.annotate(name, (t, 100 * e), fontsize=6.5, xytext=(3, 3), textcoords="offset points")
            fp = sorted(pts[i] for i in front)
            if fp:
                ax.loglog([p[0] for p in fp], [100 * p[1] for p in fp], "-", color="C3", lw=0.8, label="Pareto front")
            ax.set_title(PAIRS[key]["title"], fontsize=9)
            ax.set_xlabel("CPU time per 40-position cycle [s]")
            ax.set_ylabel(f"error of {label} [%]")
            ax.grid(True, which="both", alpha=0.3)
            if fp:
                ax.legend(fontsize=7)
        fig.suptitle(f"{label}: error vs CPU time (filled red: Pareto front)", fontsize=10)
        fig.tight_layout()
        tmp = os.path.join(out, f".pareto_{m}.tmp.png")
        fig.savefig(tmp, dpi=110)
        plt.close(fig)
        os.replace(tmp, os.path.join(out, f"pareto_{m}.png"))


def write_metrics_csv(data, err, path):
    tmp = path + ".tmp"
    with open(tmp, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["pair", "rung", "cycle [s]", "setup [s]", "memory [MB]"] + [f"error {m} [-]" for m, _ in METRICS])
        for key in err:
            for name, (_, _, _, cost) in data[key].items():
                if name not in err[key]:  # ref_check: no metrics of its own
                    continue
                w.writerow([key, name, f"{cost['cycle']:.6g}", f"{cost['setup']:.6g}", f"{cost['memory']:.6g}"] +
                           ["" if err[key][name][m] is None else f"{err[key][name][m]:.6g}" for m, _ in METRICS])
    os.replace(tmp, path)


def write_summary(data, err, path):
    """One row per rung: its worst error over the pairs and the range of its CPU costs."""
    pairs = list(err)
    lines = ["| model | cycle CPU [s] | set-up CPU [s] | " + " | ".join(l for _, l in METRICS) + " |",
             "|---|---|---|" + "---|" * len(METRICS)]
    for n, v in data[pairs[0]].items():
        if n == "ref" or v[1] in ("modelling choice", "reference check") or not all(n in err[k] for k in pairs):
            continue
        cyc = [data[k][n][3]["cycle"] for k in pairs]
        st = [data[k][n][3]["setup"] for k in pairs]
        worst = []
        for m, _ in METRICS:
            es = [err[k][n][m] for k in pairs]
            worst.append("–" if any(e is None for e in es) else f"{100 * max(es):.3g}")
        lines.append(f"| {v[0]} | {min(cyc):.3g}–{max(cyc):.3g} | {min(st):.3g}–{max(st):.3g} | " + " | ".join(worst) + " |")
    tmp = path + ".tmp"
    open(tmp, "w").write("\n".join(lines) + "\n")
    os.replace(tmp, path)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--out", default=os.path.join(HERE, "results"))
    a = ap.parse_args()
    data = collect(a.out)
    err = errors(data)
    if not err:
        print("analyse: no pair with a finished reference in", a.out)
        return 1
    write_metrics_csv(data, err, os.path.join(a.out, "metrics.csv"))
    write_table(data, err, os.path.join(a.out, "table.md"))
    which_model(data, err, os.path.join(a.out, "which_model.md"))
    write_summary(data, err, os.path.join(a.out, "summary.md"))
    plots(data, err, a.out)
    print("analyse: wrote metrics.csv, table.md, which_model.md and pareto_<metric>.png in", a.out)
    return 0


if __name__ == "__main__":
    sys.exit(main())
