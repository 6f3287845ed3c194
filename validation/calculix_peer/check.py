#!/usr/bin/python3
"""Compares gearfem with CalculiX (README.md): STE, mesh stiffness, load sharing and root
stress at the same positions, ccx's penalty sensitivity, ccx's own equilibrium, and the wall
and CPU times of both programs measured in the same run. Writes table.md (tracked, no
timings), results/timing.md, comparison.png; ends with `calculix_peer: PASS` or `FAIL`.

Matched rotation: ccx is given gearfem's pinion rotation dtheta at each (position, torque)
and returns the bore reaction T1_ccx. At the same rotation the secant mesh stiffness ratio is
T1_ccx / T1. ccx's STE at gearfem's torque T1 follows from its own load exponent between the
two torque steps, n = ln(T_b/T_a) / ln(dtheta_b/dtheta_a): dtheta_ccx(T1) =
dtheta (T1/T1_ccx)^(1/n) (a local power law; the correction is a few per cent of a few per
cent). Root stresses of ccx are scaled by T1/T1_ccx (linear in the load to first order).
"""
import argparse
import math
import os
import sys

import numpy as np

from vcheck import Checks, load_shares, read_csv, save_figure, write_if_changed

RB1 = 33.8289343483  # pinion base radius [mm] (gearfem profile inputs/fzg_c.prm)
B_ROLL, D_ROLL = -5.9828, 6.1126  # transitions on the pinion roll angle [deg] (same output)

# Tolerances (README.md, "Pass criteria"): differences between two FE codes on the same mesh,
# away from the transitions and at the transition positions (tip-corner contact)
TOL_STE, TOL_STE_TRANSITION = 0.005, 0.005
TOL_SHARE = 0.01            # load share, absolute
TOL_ROOT = 0.02             # peak fillet sigma_1 per gear
TOL_EQUILIBRIUM = 2e-3      # ccx: contact moment about O1 against the bore reaction
TOL_PENALTY = 0.03          # ccx: STE shift between kappa 3 and 30 (a sanity bound; README)


def parse_args():
    """Command line: output directory, table.md and plot paths."""
    ap = argparse.ArgumentParser()
    ap.add_argument("--out", required=True)
    ap.add_argument("--table", required=True)
    ap.add_argument("--plot", required=True)
    return ap.parse_args()


def load(out):
    """Reads the gearfem and ccx results of one run and indexes them by (torque, position) and
    (kappa, torque, position)."""
    gs = read_csv(f"{out}/gearfem/sweep.csv")
    gp = read_csv(f"{out}/gearfem/pairs.csv")
    cs = read_csv(f"{out}/ccx_sweep.csv")
    cp = read_csv(f"{out}/ccx_pairs.csv")
    tm = read_csv(f"{out}/timing.csv")

    torques = sorted({r["torque"] for r in gs})
    positions = sorted({int(r["position"]) for r in gs})
    roll = {int(r["position"]): r["roll angle"] for r in gs}
    G = {(r["torque"], int(r["position"])): r for r in gs}
    F = {}
    if os.path.exists(f"{out}/gearfem_fine/sweep.csv"):
        F = {(r["torque"], int(r["position"])): r for r in read_csv(f"{out}/gearfem_fine/sweep.csv")}
    kappas = sorted({r["kappa"] for r in cs}, reverse=True)
    kref = kappas[0]
    C = {(r["kappa"], r["torque_gearfem"], int(r["position"])): r for r in cs}
    return dict(gs=gs, gp=gp, cp=cp, tm=tm, torques=torques, positions=positions, roll=roll, G=G, F=F,
                kappas=kappas, kref=kref, C=C)


def check_slab(c, out):
    """ccx's plane stress (slab_check.py): the thin slab the decks use, against Timoshenko."""
    if os.path.exists(f"{out}/slab_check.csv"):
        sl = read_csv(f"{out}/slab_check.csv")
        thin, thick = sl[0], sl[-1]
        c.rel(f"ccx CPS8 cantilever, slab {thin['thickness_mm']:g} mm: tip deflection", thin["tip_deflection_mm"],
              thin["timoshenko_plane_stress_mm"], 0.005, "Timoshenko beam, plane stress", " mm")
        c.info(f"ccx CPS8 cantilever, thickness {thick['thickness_mm']:g} mm, against plane strain",
               f"{(thick['tip_deflection_mm'] / thick['timoshenko_plane_strain_mm'] - 1) * 100:+.2f} %", "—",
               "why the decks use a thin slab (README)")
    else:
        c.true("ccx plane-stress slab check ran", False, "missing", "results/slab_check.csv", "slab_check.py")


def check_coverage(c, torques, positions, roll, kappas, kref, C):
    """Coverage: what the peer-comparison requirement asks for."""
    rolls = np.array([roll[p] for p in positions])
    both_sides = lambda x: bool(((rolls < x) & (rolls > x - 0.5)).any() and ((rolls > x) & (rolls < x + 0.5)).any())
    c.at_least("positions over one pitch (gearfem and ccx, kappa %g)" % kref,
               sum(1 for p in positions if (kref, torques[0], p) in C), 9, "peer-comparison requirement")
    c.true("both transitions bracketed within 0.5 deg (B, D)", both_sides(B_ROLL) and both_sides(D_ROLL),
           f"{rolls.min():.2f}..{rolls.max():.2f} deg", "B -5.98, D +6.11 deg", "peer-comparison requirement")
    c.at_least("torques", len(torques), 2, "peer-comparison requirement")
    c.at_least("ccx penalty factors", len(kappas), 2, "peer-comparison requirement")


def make_ccx_at(C, torques):
    """Returns ccx_at(kappa, t, p): ccx's figures at gearfem's torque t (None where ccx has no
    result)."""
    def ccx_at(kappa, t, p):
        r = C.get((kappa, t, p))
        if r is None:
            return None
        ra, rb = C[(kappa, torques[0], p)], C[(kappa, torques[-1], p)]
        n = math.log(rb["T1_reaction"] / ra["T1_reaction"]) / math.log(rb["dtheta_urad"] / ra["dtheta_urad"])
        scale = t / r["T1_reaction"]
        th = r["dtheta_urad"] * scale ** (1 / n)
        return dict(r, n=n, ste=th * 1e-6 * RB1 * 1e3, k_ratio_rot=r["T1_reaction"] / t, scale=scale,
                    root_p=r["root_pinion"] * scale, root_g=r["root_gear"] * scale)
    return ccx_at


def comparison_tables(torques, positions, roll, G, F, gp, cp, kref, ccx_at):
    """Header and one comparison table per torque; returns the table lines and the worst
    differences per (quantity, away/transition) with their torque and roll angle."""
    lines = ["# gearfem against CalculiX: FZG type C, plane stress, gearfem's default mesh",
             "",
             "Generated by `validation/calculix_peer/run.sh` (check.py); ccx at matched rotation, its STE",
             f"brought to gearfem's torque by its own load exponent; ccx penalty factor {kref:g} unless stated.",
             "Differences are ccx/gearfem - 1. Transition positions (within 0.5 deg of B or D) marked *.",
             ""]
    worst = {}
    for t in torques:
        lines += [f"## T1 = {t:g} N m", "",
                  "| roll [deg] | pairs | STE gearfem [um] | STE ccx [um] | dSTE [%] | gearfem refined once: dSTE [%] | k gearfem [N/(mm um)] | "
                  "k(same rotation) ccx/gearfem - 1 [%] | load shares gearfem | load shares ccx | max dshare | "
                  "root pinion gearfem / ccx [MPa] | d [%] | root gear gearfem / ccx [MPa] | d [%] |",
                  "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
        for p in positions:
            g = G[(t, p)]
            x = ccx_at(kref, t, p)
            if x is None:
                continue
            trans = min(abs(roll[p] - B_ROLL), abs(roll[p] - D_ROLL)) < 0.5
            d_ste = x["ste"] / g["STE"] - 1
            d_k = x["k_ratio_rot"] - 1
            sg, sc = load_shares(gp, "torque", t, p), load_shares(cp, "torque_gearfem", t, p, kref)
            keys = sorted(k for k in set(sg) | set(sc) if max(sg.get(k, 0), sc.get(k, 0)) > 1e-3)
            dsh = max(abs(sc.get(k, 0) - sg.get(k, 0)) for k in keys)
            d_rp = x["root_p"] / g["root stress pinion"] - 1
            d_rg = x["root_g"] / g["root stress gear"] - 1
            fmt = lambda m: " ".join(f"{k[0]}/{k[1]}:{m.get(k, 0):.3f}" for k in keys)
            d_fine = F[(t, p)]["STE"] / g["STE"] - 1 if (t, p) in F else float("nan")
            lines.append(f"| {roll[p]:+.2f}{' *' if trans else ''} | {int(g['pairs in contact'])} | {g['STE']:.3f} | "
                         f"{x['ste']:.3f} | {d_ste * 100:+.2f} | {d_fine * 100:+.2f} | {g['k_secant per width']:.2f} | "
                         f"{d_k * 100:+.2f} | "
                         f"{fmt(sg)} | {fmt(sc)} | {dsh:.4f} | {g['root stress pinion']:.1f} / {x['root_p']:.1f} | "
                         f"{d_rp * 100:+.2f} | {g['root stress gear']:.1f} / {x['root_g']:.1f} | {d_rg * 100:+.2f} |")
            tag = "transition" if trans else "away"
            for name, v in (("ste", d_ste), ("share", dsh), ("root_p", d_rp), ("root_g", d_rg), ("k_rot", d_k),
                            ("fine", d_fine)):
                key = (name, tag)
                if key not in worst or abs(v) > abs(worst[key][0]):
                    worst[key] = (v, t, roll[p])
            # ccx self-check: moment of its contact forces about O1 = its bore reaction
            eq = abs(x["T1_contact_moment"] / x["T1_reaction"] - 1)
            if "eq" not in worst or eq > worst["eq"][0]:
                worst["eq"] = (eq, t, roll[p])
        lines.append("")
    return lines, worst


def check_worst(c, worst):
    """Checks the worst differences of comparison_tables against the tolerances; reports
    gearfem's mesh sensitivity and the stiffness at matched rotation."""
    def chk(name, key, tol, src):
        if key not in worst:
            return
        v, t, r = worst[key]
        c.at_most(f"{name} (worst: {t:g} N m, {r:+.2f} deg)", abs(v), tol, src)

    chk("|STE ccx/gearfem - 1|, away from transitions", ("ste", "away"), TOL_STE, "README: two FE codes, same mesh")
    chk("|STE ccx/gearfem - 1|, transition positions", ("ste", "transition"), TOL_STE_TRANSITION,
        "README: tip-corner contact")
    chk("|load share ccx - gearfem|, away from transitions", ("share", "away"), TOL_SHARE, "README")
    chk("|load share ccx - gearfem|, transition positions", ("share", "transition"), TOL_SHARE, "README")
    for k, nm in (("root_p", "pinion"), ("root_g", "gear")):
        for tag in ("away", "transition"):
            chk(f"|root stress {nm} ccx/gearfem - 1|, {tag}", (k, tag), TOL_ROOT, "README: nodal vs boundary recovery")
    if "eq" in worst:
        v, t, r = worst["eq"]
        c.at_most(f"ccx equilibrium |M_contact/T1_reaction - 1| (worst: {t:g} N m, {r:+.2f} deg)", v,
                  TOL_EQUILIBRIUM, "statics (ccx's own)")
    for tag in ("away", "transition"):
        if ("fine", tag) in worst and not math.isnan(worst[("fine", tag)][0]):
            v, t, r = worst[("fine", tag)]
            c.info(f"gearfem STE, one global refinement / default mesh - 1, {tag} (worst: {t:g} N m, {r:+.2f} deg)",
                   f"{v * 100:+.2f} %", "—", "gearfem's own mesh sensitivity (inputs/fzg_c_ccx_fine.prm)")
        if ("k_rot", tag) in worst:
            v, t, r = worst[("k_rot", tag)]
            c.info(f"secant stiffness at the same rotation, ccx/gearfem - 1, {tag} (worst: {t:g} N m, {r:+.2f} deg)",
                   f"{v * 100:+.2f} %", "—", "same figure as dSTE, at matched rotation")


def chord_table(c, lines, torques, positions, roll, G, kref, C):
    """Chord stiffness between the two torques (both codes, each from its own two solutions);
    appends its table to lines."""
    lines += ["## Chord mesh stiffness between the two torques", "",
              "(F_b - F_a)/(STE_b - STE_a), each code from its own two solutions at the same positions.", "",
              "| roll [deg] | gearfem [N/(mm um)] | ccx [N/(mm um)] | d [%] |", "|---|---|---|---|"]
    ta, tb = torques[0], torques[-1]
    dchord = []
    for p in positions:
        if (kref, ta, p) not in C:
            continue
        Fa, Fb = ta / RB1 * 1e3, tb / RB1 * 1e3
        kg = (Fb - Fa) / (G[(tb, p)]["STE"] - G[(ta, p)]["STE"]) / 14
        ra, rb = C[(kref, ta, p)], C[(kref, tb, p)]
        kc = (rb["T1_reaction"] - ra["T1_reaction"]) / RB1 * 1e3 / ((rb["dtheta_urad"] - ra["dtheta_urad"]) * RB1 * 1e-3) / 14
        dchord.append((kc / kg - 1, roll[p]))
        lines.append(f"| {roll[p]:+.2f} | {kg:.2f} | {kc:.2f} | {(kc / kg - 1) * 100:+.2f} |")
    lines.append("")
    if dchord:
        v, r = max(dchord, key=lambda q: abs(q[0]))
        c.info(f"chord stiffness LS7-LS9 ccx/gearfem - 1 (worst at {r:+.2f} deg)", f"{v * 100:+.2f} %", "—",
               "reported; README")


def penalty_table(c, lines, torques, positions, roll, G, kappas, ccx_at):
    """Penalty sensitivity of ccx, with the kappa -> infinity limit; appends its table to
    lines."""
    lines += ["## ccx penalty sensitivity", "",
              "STE of ccx at gearfem's torque for each penalty factor kappa (slope K = kappa E / h_contact), and "
              "the limit kappa -> infinity extrapolated with an error proportional to 1/kappa.", "",
              "| T1 [N m] | roll [deg] | " + " | ".join(f"STE ccx kappa {k:g} [um]" for k in kappas) +
              " | STE ccx kappa -> inf [um] | STE gearfem (Lagrange) [um] | d(inf) [%] |",
              "|---|---|" + "---|" * len(kappas) + "---|---|---|"]
    pen = []
    for t in torques:
        for p in positions:
            xs = [ccx_at(k, t, p) for k in kappas]
            if len(kappas) < 2 or any(x is None for x in xs):
                continue
            s = [x["ste"] for x in xs]
            k_hi, k_lo = kappas[0], kappas[-1]
            inf = s[0] - (s[-1] - s[0]) / (k_hi / k_lo - 1)
            pen.append((s[-1] / s[0] - 1, inf / G[(t, p)]["STE"] - 1, t, roll[p]))
            lines.append(f"| {t:g} | {roll[p]:+.2f} | " + " | ".join(f"{v:.3f}" for v in s) +
                         f" | {inf:.3f} | {G[(t, p)]['STE']:.3f} | {(inf / G[(t, p)]['STE'] - 1) * 100:+.2f} |")
    lines.append("")
    if pen:
        shift = max(pen, key=lambda q: abs(q[0]))
        c.true("ccx: a softer penalty gives a larger STE at every compared point", all(q[0] > 0 for q in pen),
               f"min shift {min(q[0] for q in pen) * 100:+.3f} %", "> 0", "penalty overclosure adds compliance")
        c.at_most(f"ccx: |STE(kappa {kappas[-1]:g})/STE(kappa {kappas[0]:g}) - 1| (worst: {shift[2]:g} N m, "
                  f"{shift[3]:+.2f} deg)", abs(shift[0]), TOL_PENALTY, "README: penalty error, 1/kappa")
        dinf = max(pen, key=lambda q: abs(q[1]))
        c.info(f"STE ccx (kappa -> inf) / gearfem - 1 (worst: {dinf[2]:g} N m, {dinf[3]:+.2f} deg)",
               f"{dinf[1] * 100:+.2f} %", "—", "penalty error removed")


def timing_report(c, out, tm, gs, torques, positions, kappas):
    """Timing of both programs in one run on the same machine: writes timing.md to out and prints
    it."""
    g_row = [r for r in tm if int(r["position"]) == -1][0]
    timing = ["| program | runs | positions x torques | wall [s] | CPU [s] | wall per position [s] |",
              "|---|---|---|---|---|---|",
              f"| gearfem solve (mesh, assembly, factorisation, all positions) | 1 | {len(positions)} x {len(torques)} | "
              f"{g_row['wall_s']:.1f} | {g_row['cpu_s']:.1f} | {g_row['wall_s'] / len(positions):.2f} |"]
    g_pos = sum(r["time"] for r in gs)  # gearfem's per-position times (contact + post), set-up excluded
    timing.append(f"| gearfem, positions only (the `time` column of sweep.csv: contact + post, no set-up) | 1 | "
                  f"{len(positions)} x {len(torques)} | {g_pos:.1f} | — | {g_pos / len(positions):.2f} |")
    ratios = {}
    for k in kappas:
        rows = [r for r in tm if r["kappa"] == k and int(r["position"]) >= 0]
        w, cpu = sum(r["wall_s"] for r in rows), sum(r["cpu_s"] for r in rows)
        timing.append(f"| ccx, kappa {k:g} (one run per position, both torques as two steps) | {len(rows)} | "
                      f"{len(rows)} x {len(torques)} | {w:.1f} | {cpu:.1f} | {w / len(rows):.2f} |")
        ratios[k] = (w / len(rows) / (g_row["wall_s"] / len(positions)),
                     cpu / len(rows) / (g_row["cpu_s"] / len(positions)))
    for k, (rw, rc) in ratios.items():
        rows = [r for r in tm if r["kappa"] == k and int(r["position"]) >= 0]
        marg = sum(r["wall_s"] for r in rows) / len(rows) / (g_pos / len(positions))
        timing.append(f"\nccx (kappa {k:g}) / gearfem, per position (both torques): wall {rw:.0f}x, CPU {rc:.0f}x "
                      f"(gearfem's set-up included); wall {marg:.0f}x against gearfem's positions alone")
        c.info(f"speed: ccx (kappa {k:g}) / gearfem per position, wall | CPU", f"{rw:.0f}x | {rc:.0f}x", "—",
               "measured in this run (timing.md)")
    c.true("both programs timed in this run", g_row["wall_s"] > 0 and all(r["wall_s"] > 0 for r in tm),
           "yes", "wall > 0", "run_peer.py")
    text = "\n".join(timing) + "\n"
    with open(f"{out}/timing.md.tmp", "w") as f:
        f.write(text)
    os.replace(f"{out}/timing.md.tmp", f"{out}/timing.md")
    print(text)


def main():
    a = parse_args()
    out = a.out
    c = Checks("calculix_peer", out)
    d = load(out)
    torques, positions, roll, G, C = d["torques"], d["positions"], d["roll"], d["G"], d["C"]
    kappas, kref = d["kappas"], d["kref"]

    check_slab(c, out)
    check_coverage(c, torques, positions, roll, kappas, kref, C)
    ccx_at = make_ccx_at(C, torques)
    lines, worst = comparison_tables(torques, positions, roll, G, d["F"], d["gp"], d["cp"], kref, ccx_at)
    check_worst(c, worst)
    chord_table(c, lines, torques, positions, roll, G, kref, C)
    penalty_table(c, lines, torques, positions, roll, G, kappas, ccx_at)
    timing_report(c, out, d["tm"], d["gs"], torques, positions, kappas)
    write_if_changed(a.table, "\n".join(lines) + "\n")
    plot(a.plot, torques, positions, roll, G, d["gp"], d["cp"], C, kappas, ccx_at)
    sys.exit(c.finish())


def plot(path, torques, positions, roll, G, gp, cp, C, kappas, ccx_at):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(2, 2, figsize=(12, 8))
    cols = ["C0", "C3", "C2"]
    for i, t in enumerate(torques):
        ps = [p for p in positions if ccx_at(kappas[0], t, p) is not None]
        r = [roll[p] for p in ps]
        ax[0, 0].plot(r, [G[(t, p)]["STE"] for p in ps], "-", color=cols[i], label=f"gearfem {t:g} N m")
        ax[0, 0].plot(r, [ccx_at(kappas[0], t, p)["ste"] for p in ps], "o", mfc="none", color=cols[i],
                      label=f"ccx kappa {kappas[0]:g}")
        pl = [p for p in ps if ccx_at(kappas[-1], t, p) is not None]
        ax[0, 0].plot([roll[p] for p in pl], [ccx_at(kappas[-1], t, p)["ste"] for p in pl], "x", color=cols[i],
                      label=f"ccx kappa {kappas[-1]:g}")
        ax[0, 1].plot(r, [G[(t, p)]["k_secant per width"] for p in ps], "-", color=cols[i], label=f"gearfem {t:g} N m")
        ax[0, 1].plot(r, [t / (RB1 * 1e-3) / (ccx_at(kappas[0], t, p)["ste"]) / 14 for p in ps], "o", mfc="none",
                      color=cols[i], label="ccx")
        sg = [load_shares(gp, "torque", t, p).get((0, 0), 0) for p in ps]
        sc = [load_shares(cp, "torque_gearfem", t, p, kappas[0]).get((0, 0), 0) for p in ps]
        ax[1, 0].plot(r, sg, "-", color=cols[i], label=f"gearfem {t:g} N m")
        ax[1, 0].plot(r, sc, "o", mfc="none", color=cols[i], label="ccx")
        ax[1, 1].plot(r, [G[(t, p)]["root stress pinion"] for p in ps], "-", color=cols[i], label=f"gearfem pinion {t:g} N m")
        ax[1, 1].plot(r, [ccx_at(kappas[0], t, p)["root_p"] for p in ps], "o", mfc="none", color=cols[i], label="ccx pinion")
        ax[1, 1].plot(r, [G[(t, p)]["root stress gear"] for p in ps], "--", color=cols[i], label=f"gearfem gear {t:g} N m")
        ax[1, 1].plot(r, [ccx_at(kappas[0], t, p)["root_g"] for p in ps], "s", mfc="none", color=cols[i], label="ccx gear")
    for a_, yl in zip(ax.flat, ["STE [um]", "k_secant [N/(mm um)]", "load share, pinion tooth 0 / gear tooth 0 [-]",
                                "root stress (max sigma_1 on the loaded fillets) [MPa]"]):
        a_.set_xlabel("pinion roll angle [deg]")
        a_.set_ylabel(yl)
        for x in (B_ROLL, D_ROLL):
            a_.axvline(x, color="0.7", lw=0.8)
        a_.legend(fontsize=7)
        a_.grid(alpha=0.3)
    fig.suptitle("FZG type C: gearfem (Lagrange) against CalculiX 2.20 (CPS8, surface-to-surface penalty), same meshes")
    save_figure(fig, path, dpi=110)


if __name__ == "__main__":
    main()
