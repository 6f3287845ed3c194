#!/usr/bin/python3
"""Compares gearfem with CalculiX on the planet-ring pair (README.md): STE and the ring's root
stress at the same positions and torques, plus the placement (recomputed geometry, unloaded
gaps), coverage, load sharing, the pinion's root stress, ccx's own equilibrium and the wall
and CPU times of both programs measured in the same run. Writes table.md (tracked, no
timings), results/timing.md, comparison.png; ends with `calculix_internal: PASS` or `FAIL`.

Matched rotation, as in validation/calculix_peer: ccx is given gearfem's pinion rotation
dtheta at each (position, torque) and returns the support reaction T1_ccx. ccx's STE at
gearfem's torque T1 follows from its own load exponent between the two torque steps,
n = ln(T_b/T_a) / ln(dtheta_b/dtheta_a): dtheta_ccx(T1) = dtheta (T1/T1_ccx)^(1/n). The same
difference through gearfem's tangent stiffness, (T1 - T1_ccx)/(r_b1 k_tangent), is reported
next to it. ccx's root stresses are scaled by T1/T1_ccx.

Usage: check.py --out results --table table.md --plot comparison.png
"""
import argparse
import json
import math
import os
import re
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "lib"))
from vcheck import Checks, load_shares, read_csv, save_figure, write_if_changed  # noqa: E402

CASE = "calculix_internal"
TOL_STE = 0.01            # |STE ccx / gearfem - 1|, every position and torque
TOL_ROOT_RING = 0.03      # |ring root stress ccx / gearfem - 1|
TOL_GAP_UM = 0.05         # unloaded gap of the tooth-0 pair on the path A-E [um]
TOL_EQUILIBRIUM = 5e-3    # ccx: contact moment about O1 against the support reaction
TOL_GEOMETRY = 1e-4       # recomputed a and eps_alpha against gearfem's log (its 6 digits)


def parse_args():
    """The command line: --out, --table, --plot."""
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--out", required=True, help="results folder of run_peer.py")
    ap.add_argument("--table", required=True, help="table.md to write (tracked, no timings)")
    ap.add_argument("--plot", required=True, help="comparison.png to write")
    return ap.parse_args()


def load(out):
    """The geometry and the CSV files of run_peer.py in `out`, with the positions, torques and kappas
    they contain and the gearfem (G) and ccx (C) rows by key."""
    geo = json.load(open(f"{out}/geometry.json"))
    gs = read_csv(f"{out}/gearfem/sweep.csv")
    gp = read_csv(f"{out}/gearfem/pairs.csv")
    cs = read_csv(f"{out}/ccx_sweep.csv")
    cp = read_csv(f"{out}/ccx_pairs.csv")
    tm = read_csv(f"{out}/timing.csv")
    gaps = read_csv(f"{out}/unloaded_gaps.csv")
    rb1 = geo["rb1"]
    R = geo["roll"]
    torques = sorted({r["torque"] for r in gs})
    positions = sorted({int(r["position"]) for r in gs})
    roll = {int(r["position"]): r["roll angle"] for r in gs}
    point = {int(r["position"]): int(r["point (0 none; 1 A; 2 B; 3 C; 4 D; 5 E)"]) for r in gs}
    G = {(r["torque"], int(r["position"])): r for r in gs}
    kappas = sorted({r["kappa"] for r in cs}, reverse=True)
    kref = kappas[0]
    C = {(r["kappa"], r["torque_gearfem"], int(r["position"])): r for r in cs}
    return dict(geo=geo, gp=gp, cp=cp, tm=tm, gaps=gaps, rb1=rb1, R=R, torques=torques, positions=positions,
                roll=roll, point=point, G=G, kappas=kappas, kref=kref, C=C)


def check_geometry(c, out, geo, R, positions, roll, point):
    """The pair: the geometry recomputed in Python against gearfem's own figures."""
    log = open(f"{out}/gearfem_solve.log").read()
    m = re.search(r"a ([0-9.]+) mm, contact ratio ([0-9.]+)", log)
    if m:
        c.rel("centre distance a, involute formulas (Python) against gearfem", geo["a"], float(m.group(1)),
              TOL_GEOMETRY, "gearfem solve log (6 digits)", " mm")
        c.rel("contact ratio eps_alpha, Python against gearfem", geo["eps_alpha"], float(m.group(2)), TOL_GEOMETRY,
              "gearfem solve log (6 digits)")
    else:
        c.true("gearfem's log states a and the contact ratio", False, "missing", "solve log", "gearfem_solve.log")
    c.abs("zero backlash: s_w1 + s_w2 - p_w (Python)", geo["backlash_arc"] * 1e3, 0.0, 1e-6,
          "docs/internal-gears.md: Centre distance = 0", " um")
    flagged = {point[p]: roll[p] for p in positions if point[p]}
    for name, code in (("B", 2), ("D", 4)):
        c.abs(f"gearfem flags the position at Python's {name} as {name}", flagged.get(code, float("nan")), R[name],
              1e-5, "sweep.csv point column", " deg")


def check_gaps(c, gaps, R):
    """Unloaded gaps: the tooth-0 pair while it is on the path A..E (calculix_peer's placement check),
    any pair on the path, and the neighbouring pairs off it."""
    on0 = [g for g in gaps if int(g["pinion_tooth"]) == 0 and R["A"] <= g["path_roll_deg"] <= R["E"]]
    w0 = max(on0, key=lambda g: g["unloaded_gap_um"])
    c.at_most(f"unloaded gap of the tooth 0 pair, every position (worst at {w0['roll_deg']:+.3f} deg)",
              w0["unloaded_gap_um"], TOL_GAP_UM, "placement: drive flanks touch without load", " um")
    onp = [g for g in gaps if R["A"] <= g["path_roll_deg"] <= R["E"]]
    wp = max(onp, key=lambda g: g["unloaded_gap_um"])
    c.info(f"largest unloaded gap of any tooth pair on the path A-E (pair {int(wp['pinion_tooth'])}/"
           f"{int(wp['gear_tooth'])} at {wp['roll_deg']:+.3f} deg, pinion radius {wp['radius_pinion_mm']:.2f} mm)",
           f"{wp['unloaded_gap_um']:.3f} um", "0", "README: the .msh vertices of gearfem mesh")
    nb = [g for g in gaps if not (R["A"] <= g["path_roll_deg"] <= R["E"]) and g["unloaded_gap_um"] < 50]
    if nb:
        c.info("unloaded gaps of the neighbouring pairs off the path within 50 um (ccx contact pairs)",
               ", ".join(f"{g['unloaded_gap_um']:.2f}" for g in sorted(nb, key=lambda g: g["roll_deg"])) + " um",
               "—", "README: conformal mesh")


def check_coverage(c, R, torques, positions, roll, kref, C):
    """Coverage: positions and torques compared, transitions B and D and the ends A and E reached."""
    rolls = [roll[p] for p in positions]
    n_ccx = sum(1 for p in positions if all((kref, t, p) in C for t in torques))
    c.at_least(f"positions compared (gearfem and ccx kappa {kref:g}, both torques)", n_ccx, 8,
               "peer-comparison requirement")
    c.at_least("torques", len(torques), 2, "peer-comparison requirement")
    near = lambda x, d: any(abs(r - x) <= d for r in rolls)
    c.true("transitions B and D among the positions, and both within 0.5 deg of A and of E",
           near(R["B"], 1e-4) and near(R["D"], 1e-4) and near(R["A"], 0.5) and near(R["E"], 0.5),
           f"{min(rolls):+.3f}..{max(rolls):+.3f} deg", "A %+.3f, B %+.3f, D %+.3f, E %+.3f deg"
           % (R["A"], R["B"], R["D"], R["E"]), "peer-comparison requirement")


def make_ccx_at(C, torques, G, rb1):
    """ccx_at(kappa, t, p): ccx's row at gearfem's torque t and position p, with its load exponent n,
    STE at t (by n and via gearfem's k_tangent) and root stresses scaled by T1/T1_ccx; None if ccx
    has no such row."""
    def ccx_at(kappa, t, p):
        r = C.get((kappa, t, p))
        if r is None:
            return None
        ra, rb = C[(kappa, torques[0], p)], C[(kappa, torques[-1], p)]
        n = math.log(rb["T1_reaction"] / ra["T1_reaction"]) / math.log(rb["dtheta_urad"] / ra["dtheta_urad"])
        scale = t / r["T1_reaction"]
        th = r["dtheta_urad"] * scale ** (1 / n)
        g = G[(t, p)]
        ste_kt = g["STE"] + (t - r["T1_reaction"]) / (rb1 * 1e-3) / g["k_tangent"] * 1e6  # um
        return dict(r, n=n, ste=th * 1e-6 * rb1 * 1e3, ste_kt=ste_kt, scale=scale,
                    root_p=r["root_pinion"] * scale, root_g=r["root_gear"] * scale)
    return ccx_at


def comparison_table(geo, torques, positions, roll, point, G, gp, cp, kref, ccx_at):
    """The lines of table.md (one table per torque) and, per quantity, the worst difference as
    (value, torque, roll angle)."""
    label = {0: "", 1: "A", 2: "B", 3: "C", 4: "D", 5: "E"}
    lines = ["# gearfem against CalculiX: planet z 28 in ring z 74 (seed 001 stage 1), plane stress",
             "",
             "Generated by `validation/calculix_internal/run.sh` (check.py). ccx (CPS8, surface-to-surface",
             f"penalty, kappa {kref:g}) at gearfem's pinion rotation; its STE brought to gearfem's torque by its own",
             "load exponent n between the two torques (as validation/calculix_peer); the column 'via k_t' converts",
             "the torque difference with gearfem's tangent mesh stiffness instead. Differences are ccx/gearfem - 1.",
             "Root stress: peak sigma_1 on the drive (tension-side) fillets of the loaded teeth; ccx's nodal values",
             "scaled by T1/T1_ccx. Load shares: pinion tooth/ring tooth = share, pairs above 0.001.",
             ""]
    worst = {}

    def keep(key, v, t, r):
        if key not in worst or abs(v) > abs(worst[key][0]):
            worst[key] = (v, t, r)

    for t in torques:
        lines += [f"## T1 = {t:g} N m", "",
                  "| roll [deg] | point | STE gearfem [um] | STE ccx [um] | dSTE [%] | dSTE via k_t [%] | n ccx | "
                  "T1_ccx/T1 - 1 at same rotation [%] | load shares gearfem | load shares ccx | "
                  "ring root gearfem / ccx [MPa] | d [%] | pinion root gearfem / ccx [MPa] | d [%] |",
                  "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
        for p in positions:
            g, x = G[(t, p)], ccx_at(kref, t, p)
            if x is None:
                continue
            dste, dkt = x["ste"] / g["STE"] - 1, x["ste_kt"] / g["STE"] - 1
            drg = x["root_g"] / g["root stress gear"] - 1
            drp = x["root_p"] / g["root stress pinion"] - 1
            sg, sc = load_shares(gp, "torque", t, p), load_shares(cp, "torque_gearfem", t, p, kref)
            fmt = lambda d: ", ".join(f"{(i if i <= 14 else i - 28):d}/{(j if j <= 37 else j - 74):d} = {v:.3f}"
                                      for (i, j), v in sorted(d.items()) if v > 1e-3) or "-"
            ds = max([abs(sc.get(k, 0) - sg.get(k, 0)) for k in set(sg) | set(sc)] or [0])
            keep("ste", dste, t, roll[p])
            keep("ste_kt", dkt, t, roll[p])
            keep("root_g", drg, t, roll[p])
            keep("root_p", drp, t, roll[p])
            keep("share", ds, t, roll[p])
            keep("eq", x["T1_contact_moment"] / x["T1_reaction"] - 1, t, roll[p])
            keep("t2", abs(x["T2"]) * geo["z1"] / (x["T1_reaction"] * geo["z2"]) - 1, t, roll[p])
            lines.append(f"| {roll[p]:+.4f} | {label[point[p]]} | {g['STE']:.3f} | {x['ste']:.3f} | {dste * 100:+.2f} | "
                         f"{dkt * 100:+.2f} | {x['n']:.3f} | {(x['T1_reaction'] / t - 1) * 100:+.2f} | {fmt(sg)} | "
                         f"{fmt(sc)} | {g['root stress gear']:.1f} / {x['root_g']:.1f} | {drg * 100:+.2f} | "
                         f"{g['root stress pinion']:.1f} / {x['root_p']:.1f} | {drp * 100:+.2f} |")
        lines.append("")
    return lines, worst


def check_worst(c, worst):
    """The worst differences over all positions and torques: STE and ring root stress against their
    limits, ccx's equilibrium, and the rest reported."""
    def w(key):
        v, t, r = worst[key]
        return v, f"worst: {t:g} N m, {r:+.3f} deg"

    v, where = w("ste")
    c.at_most(f"|STE ccx/gearfem - 1|, all positions and torques ({where})", abs(v), TOL_STE,
              "requirement: two FE codes, same mesh, matched rotation")
    v, where = w("root_g")
    c.at_most(f"|ring root stress ccx/gearfem - 1|, all positions and torques ({where})", abs(v), TOL_ROOT_RING,
              "requirement: tension-side fillet peak sigma_1")
    v, where = w("ste_kt")
    c.info(f"STE difference through gearfem's tangent stiffness ({where})", f"{v * 100:+.2f} %", "—",
           "the same torque difference, converted linearly")
    v, where = w("root_p")
    c.info(f"pinion root stress ccx/gearfem - 1 ({where})", f"{v * 100:+.2f} %", "—", "reported")
    v, where = w("share")
    c.info(f"|load share ccx - gearfem|, largest ({where})", f"{v:.4f}", "—", "reported")
    v, where = w("eq")
    c.at_most(f"ccx equilibrium |M_contact/T1_reaction - 1| ({where})", abs(v), TOL_EQUILIBRIUM, "statics (ccx's own)")
    v, where = w("t2")
    c.info(f"ccx ring moment T2 z1/(T1 z2) - 1 ({where})", f"{v * 100:+.2f} %", "—",
           "frictionless: T2/T1 = r_b2/r_b1 when one line of action carries the load")


def check_penalty(c, kappas, torques, positions, roll, ccx_at):
    """Penalty sensitivity: ccx's STE of the last kappa against the first (when a second kappa ran)."""
    if len(kappas) > 1:
        pen = []
        for t in torques:
            for p in positions:
                xs = [ccx_at(k, t, p) for k in kappas]
                if all(xx is not None for xx in xs):
                    pen.append((xs[-1]["ste"] / xs[0]["ste"] - 1, t, roll[p]))
        if pen:
            v = max(pen, key=lambda q: abs(q[0]))
            c.info(f"ccx STE kappa {kappas[-1]:g} / kappa {kappas[0]:g} - 1 (worst: {v[1]:g} N m, {v[2]:+.3f} deg)",
                   f"{v[0] * 100:+.2f} %", "—", "penalty sensitivity")


def timing_report(c, out, tm, torques, positions, kappas):
    """Timing, one run on the same machine: the time ratios as checks, then results/timing.md written
    and printed."""
    g_row = [r for r in tm if int(r["position"]) == -1][0]
    npos = len(positions)
    timing = ["| program | runs | positions x torques | wall [s] | CPU [s] | wall per position [s] | CPU per position [s] |",
              "|---|---|---|---|---|---|---|",
              f"| gearfem solve (mesh, assembly, factorisation, all positions) | 1 | {npos} x {len(torques)} | "
              f"{g_row['wall_s']:.1f} | {g_row['cpu_s']:.1f} | {g_row['wall_s'] / npos:.2f} | {g_row['cpu_s'] / npos:.2f} |"]
    ratio_line = []
    for k in kappas:
        rows = [r for r in tm if r["kappa"] == k and int(r["position"]) >= 0]
        wl, cpu = sum(r["wall_s"] for r in rows), sum(r["cpu_s"] for r in rows)
        timing.append(f"| ccx, kappa {k:g} (one run per position, both torques as two steps) | {len(rows)} | "
                      f"{len(rows)} x {len(torques)} | {wl:.1f} | {cpu:.1f} | {wl / len(rows):.2f} | {cpu / len(rows):.2f} |")
        rw = (g_row["wall_s"] / npos) / (wl / len(rows))
        rc = (g_row["cpu_s"] / npos) / (cpu / len(rows))
        ratio_line.append(f"\ngearfem / ccx (kappa {k:g}), time per position (both torques; gearfem's set-up included): "
                          f"wall {rw:.4f} ({1 / rw:.0f}x faster), CPU {rc:.4f} ({1 / rc:.0f}x faster)")
        c.info(f"time ratio gearfem/ccx (kappa {k:g}) per position, wall | CPU", f"{rw:.4f} | {rc:.4f}", "—",
               "measured in this run (timing.md)")
    c.true("both programs timed in this run", g_row["wall_s"] > 0 and all(r["wall_s"] > 0 for r in tm),
           "yes", "wall > 0", "run_peer.py")
    text = "\n".join(timing + ratio_line) + "\n"
    with open(f"{out}/timing.md.tmp", "w") as f:
        f.write(text)
    os.replace(f"{out}/timing.md.tmp", f"{out}/timing.md")
    print(text)


def main():
    """Runs the checks, writes timing.md, table.md and the plot, exits with the verdict."""
    a = parse_args()
    out = a.out
    c = Checks(CASE, out)
    d = load(out)
    geo, R, torques, positions, roll = d["geo"], d["R"], d["torques"], d["positions"], d["roll"]
    kappas, kref, G = d["kappas"], d["kref"], d["G"]
    check_geometry(c, out, geo, R, positions, roll, d["point"])
    check_gaps(c, d["gaps"], R)
    check_coverage(c, R, torques, positions, roll, kref, d["C"])
    ccx_at = make_ccx_at(d["C"], torques, G, d["rb1"])
    lines, worst = comparison_table(geo, torques, positions, roll, d["point"], G, d["gp"], d["cp"], kref, ccx_at)
    check_worst(c, worst)
    check_penalty(c, kappas, torques, positions, roll, ccx_at)
    timing_report(c, out, d["tm"], torques, positions, kappas)
    write_if_changed(a.table, "\n".join(lines) + "\n")
    plot(a.plot, torques, positions, roll, G, d["gp"], d["cp"], kref, ccx_at, R)
    sys.exit(c.finish())


def plot(path, torques, positions, roll, G, gp, cp, kref, ccx_at, R):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(2, 2, figsize=(12, 8))
    cols = ["C0", "C3", "C2"]
    for i, t in enumerate(torques):
        ps = [p for p in positions if ccx_at(kref, t, p) is not None]
        r = [roll[p] for p in ps]
        x = [ccx_at(kref, t, p) for p in ps]
        ax[0, 0].plot(r, [G[(t, p)]["STE"] for p in ps], "-", color=cols[i], label=f"gearfem {t:g} N m")
        ax[0, 0].plot(r, [q["ste"] for q in x], "o", mfc="none", color=cols[i], label=f"ccx {t:g} N m")
        ax[0, 1].plot(r, [(q["ste"] / G[(t, p)]["STE"] - 1) * 100 for q, p in zip(x, ps)], "o-", color=cols[i],
                      label=f"STE {t:g} N m")
        ax[0, 1].plot(r, [(q["root_g"] / G[(t, p)]["root stress gear"] - 1) * 100 for q, p in zip(x, ps)], "s--",
                      mfc="none", color=cols[i], label=f"ring root stress {t:g} N m")
        ax[1, 0].plot(r, [load_shares(gp, "torque", t, p).get((0, 0), 0) for p in ps], "-", color=cols[i],
                      label=f"gearfem {t:g} N m")
        ax[1, 0].plot(r, [load_shares(cp, "torque_gearfem", t, p, kref).get((0, 0), 0) for p in ps], "o", mfc="none",
                      color=cols[i], label="ccx")
        ax[1, 1].plot(r, [G[(t, p)]["root stress gear"] for p in ps], "-", color=cols[i], label=f"gearfem ring {t:g} N m")
        ax[1, 1].plot(r, [q["root_g"] for q in x], "s", mfc="none", color=cols[i], label="ccx ring")
        ax[1, 1].plot(r, [G[(t, p)]["root stress pinion"] for p in ps], ":", color=cols[i], label=f"gearfem pinion {t:g} N m")
        ax[1, 1].plot(r, [q["root_p"] for q in x], "^", mfc="none", color=cols[i], label="ccx pinion")
    for lim in (1, -1):
        ax[0, 1].axhline(lim, color="0.5", lw=0.8, ls="--")
    for lim in (3, -3):
        ax[0, 1].axhline(lim, color="0.8", lw=0.8, ls=":")
    for a_, yl in zip(ax.flat, ["STE [um]", "ccx/gearfem - 1 [%] (limits: STE 1 %, ring root 3 %)",
                                "load share, pinion tooth 0 / ring tooth 0 [-]",
                                "root stress (max sigma_1, drive fillets) [MPa]"]):
        a_.set_xlabel("pinion roll angle [deg]")
        a_.set_ylabel(yl)
        for k in ("A", "B", "D", "E"):
            a_.axvline(R[k], color="0.7", lw=0.8)
        a_.legend(fontsize=7)
        a_.grid(alpha=0.3)
    fig.suptitle("Planet z 28 in ring z 74: gearfem (Lagrange) against CalculiX 2.20 (CPS8, penalty), same meshes")
    save_figure(fig, path, dpi=110)


if __name__ == "__main__":
    main()
