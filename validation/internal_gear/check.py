#!/usr/bin/python3
"""Internal gear (pinion z 24 inside a ring z 60): Hertz at C, rim thickness against AGMA K_B,
ring root stress against ISO 6336-3, equilibrium (README.md, "Checks").

Usage: check.py <validate_internal_gear output> [--status N] [--table table.md]
                [--plot rim_thickness.png] [--out results dir]
The references (Hertz closed form, K_B, ISO Y_B of internal gears) are computed here from the
geometry rows of the log, independently of lib/."""
import argparse
import math
import os
import sys
from collections import defaultdict

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "lib"))
from vcheck import Checks, write_if_changed

TOL_HERTZ = 0.03       # p_max against Hertz at the resolved mesh (requirement of the case)
TOL_PLATEAU = 0.05     # clamped rim, m_B >= 1.2, against m_B = 2.0
TOL_EQ = 1e-3          # moments (conservation laws)
M_B = [2.0, 1.5, 1.2, 1.0, 0.8, 0.65, 0.5]
POSITIONS = 31         # rim rows per model (one mesh cycle in 0.5 deg steps)
SUPPORTS = {           # name in the log: label in the table and plot
    "clamped": "outer circle clamped",
    "bolts6_between": "6 bolts, teeth midway",
    "bolts6_over": "6 bolts, teeth over a bolt",
    "bolts12_between": "12 bolts, teeth midway",
}
JOHNSON = "Johnson 1985 eqs. 4.43-4.45 (1/R = 1/rho1 - 1/rho2, E* = E/2)"
AGMA = "AGMA 2001-D04 K_B = 1.6 ln(2.242/m_B), 1 for m_B >= 1.2"


def parse(path):
    rows = defaultdict(list)
    with open(path) as f:
        for line in f:
            if not line.startswith("ROW,"):
                continue
            parts = line.strip().split(",")
            d = {}
            for kv in parts[2:]:
                k, _, v = kv.partition("=")
                try:
                    d[k] = float(v)
                except ValueError:
                    d[k] = v
            rows[parts[1]].append(d)
    return rows


def K_B(mB):
    """AGMA 2001-D04 rim thickness factor."""
    return 1.0 if mB >= 1.2 else 1.6 * math.log(2.242 / mB)


def Y_B_internal(s_R, m):
    """ISO 6336-3:2006 clause 8, internal gears; None outside 1.75 < s_R/m_n."""
    x = s_R / m
    if x >= 3.5:
        return 1.0
    if x > 1.75:
        return 1.15 * math.log(8.324 / x)
    return None


def hertz(geo, force):
    """Half-width a [mm] and p0 [MPa] of the concave-convex line contact at C."""
    aw = math.radians(geo["alpha_w_deg"])
    rho1, rho2 = geo["rw1_mm"] * math.sin(aw), geo["rw2_mm"] * math.sin(aw)
    R = 1.0 / (1.0 / rho1 - 1.0 / rho2) * 1e-3
    Es = geo["E_GPa"] * 1e9 / 2  # plane stress, equal steels: 1/E* = 1/E1 + 1/E2
    P = force / (geo["b_mm"] * 1e-3)
    a = math.sqrt(4 * P * R / (math.pi * Es))
    return a * 1e3, 2 * P / (math.pi * a) / 1e6, rho1, rho2


def g(x, d=4):
    return f"{x:.{d}g}"


def parse_args():
    """Command line of check.py."""
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("log", help="output of validate_internal_gear")
    ap.add_argument("--status", type=int, default=0, help="exit status of validate_internal_gear")
    ap.add_argument("--table", help="tracked markdown table to write (no timings)")
    ap.add_argument("--plot", help="rim-thickness figure to write (PNG)")
    ap.add_argument("--out", help="results folder (checks.md)")
    return ap.parse_args()


def check_hertz(c, rows, geo, md):
    """a. p_max at C against Hertz; appends the table to md."""
    md += ["## a. Hertz at the pitch point C (phi1 = 0)", "",
           f"rho1 = r_w1 sin alpha_w, rho2 = r_w2 sin alpha_w; P = force of the pair at C / b; {JOHNSON}.", "",
           "| T1 [N m] | h [mm] | a/h | pairs | share of the pair at C | force at C [N] | a Hertz [mm] | "
           "p0 Hertz [MPa] | p_max FE [MPa] | FE/Hertz | a fit FE [mm] | post's Hertz p0 [MPa] |",
           "|---|---|---|---|---|---|---|---|---|---|---|---|"]
    hz = sorted(rows["hertz"], key=lambda r: (r["T1_Nm"], -r["h_mm"]))
    finest = max((r["level"] for r in hz), default=None)
    for r in hz:
        a, p0, rho1, rho2 = hertz(geo, r["force_N"])
        ratio = r["p_max_MPa"] / p0
        md.append(f"| {g(r['T1_Nm'])} | {r['h_mm']:.4f} | {a / r['h_mm']:.1f} | {int(r['n_pairs'])} | "
                  f"{r['share']:.3f} | {r['force_N']:.0f} | {a:.4f} | {p0:.1f} | {r['p_max_MPa']:.1f} | "
                  f"{ratio:.4f} | {r['a_fit_mm']:.4f} | {r['p_hertz_post_MPa']:.1f} |")
        label = f"T1 {g(r['T1_Nm'])} N m, h {r['h_mm']:.4f} mm (a/h {a / r['h_mm']:.1f})"
        if r["level"] == finest:
            c.rel(f"Hertz p_max at C, {label}", r["p_max_MPa"], round(p0, 2), TOL_HERTZ, JOHNSON, " MPa")
            c.true(f"pair at C flank-to-flank and resolved, {label}", r["resolved"] == 1 and r["edge"] == 0,
                   f"resolved {int(r['resolved'])}, edge {int(r['edge'])}", "resolved 1, edge 0", "post/position.h")
        else:
            c.info(f"Hertz p_max at C, {label}", f"{r['p_max_MPa']:.1f} MPa ({(ratio - 1) * 100:+.2f} %)",
                   f"{p0:.1f} MPa", "coarser mesh, reported")
    c.true("Hertz rows", len(hz) == 6, f"{len(hz)} rows", "6 (2 torques x 3 meshes)", "validate_internal_gear.cc")
    if hz:
        md += ["", f"rho1 = {rho1:.4f} mm, rho2 = {rho2:.4f} mm, R = {1 / (1 / rho1 - 1 / rho2):.4f} mm.", ""]


def rim_peaks(c, rows):
    """Peak rim rows per (support, m_B) and the (support, m_B) models missing from the log;
    checks that every model is complete."""
    by = defaultdict(list)
    for r in rows["rim"]:
        by[(r["support"], r["m_B"])].append(r)
    peak = {}
    for key, rs in by.items():
        best = max(rs, key=lambda r: r["sigma_MPa"])
        fine = max(rs, key=lambda r: r["sigma_fine_MPa"])
        peak[key] = (best, fine)
    short = sorted(f"{k[0]} m_B {g(k[1])}" for k, rs in by.items() if len(rs) != POSITIONS)
    c.true(f"{POSITIONS} positions for each of the {len(by)} ring models", not short,
           "; ".join(short) or "all complete", f"{POSITIONS} each", "validate_internal_gear.cc")
    missing = [(s, m) for s in SUPPORTS for m in M_B if (s, m) not in peak]
    c.true("rim models present", not missing, f"{len(missing)} missing", "all", "validate_internal_gear.cc")
    return peak, missing


def rim_tables(rows, geo, peak, md):
    """b. Tables of the ring root stress against m_B; returns sigma(2.0) per support,
    sigma/sigma(2.0) per support and m_B, and the module."""
    ht = peak[("clamped", 2.0)][0]["h_t_mm"]
    mod = geo["m_mm"]
    ref = {s: peak[(s, 2.0)][0]["sigma_MPa"] for s in SUPPORTS}
    md += ["## b. Ring root stress against the backup ratio m_B = t_R/h_t", "",
           f"T1 = {g(rows['rim'][0]['T1_Nm'])} N m; h_t = {ht:.3f} mm; sigma = max over one mesh cycle "
           f"(31 positions) of the tension-side (drive) fillet sigma_1 of the loaded ring teeth; "
           "sigma/sigma(2.0) normalised by the same support at m_B = 2.0; 'on tooth' the loaded ring tooth that "
           "holds the peak (0: the tooth at B when phi1 = phi_B); 'height' the peak's distance from the root "
           "circle; Y_B ISO 6336-3 for internal gears at s_R/m_n.", ""]
    head = "| m_B | t_R [mm] | K_B AGMA | Y_B ISO (internal) |"
    sep = "|---|---|---|---|"
    for s, label in SUPPORTS.items():
        head += f" {label}: sigma [MPa] | sigma/sigma(2.0) | FE/K_B | on tooth, height [mm] |"
        sep += "---|---|---|---|"
    md += [head, sep]
    ratios = defaultdict(dict)
    for mB in M_B:
        tR = peak[("clamped", mB)][0]["t_R_mm"]
        yb = Y_B_internal(tR, mod)
        line = f"| {g(mB)} | {tR:.3f} | {K_B(mB):.3f} | {('%.3f' % yb) if yb else 'out of range'} |"
        for s in SUPPORTS:
            best = peak[(s, mB)][0]
            q = best["sigma_MPa"] / ref[s]
            ratios[s][mB] = q
            line += (f" {best['sigma_MPa']:.1f} | {q:.3f} | {q / K_B(mB):.3f} | "
                     f"{int(best['tooth'])}, {best['height_mm']:.2f} |")
        md.append(line)
    md += ["", "Peak over both fillets of the fine ring teeth -1, 0, 1 (loaded or not) [MPa], where it is:", "",
           "| m_B | " + " | ".join(SUPPORTS.values()) + " |", "|---|" + "---|" * len(SUPPORTS)]
    for mB in M_B:
        md.append(f"| {g(mB)} | " + " | ".join(
            f"{peak[(s, mB)][1]['sigma_fine_MPa']:.1f} (tooth {int(peak[(s, mB)][1]['fine_tooth'])}, "
            f"{peak[(s, mB)][1]['fine_side']})" for s in SUPPORTS) + " |")
    return ref, ratios, mod


def check_rim(c, rows, peak, ref, ratios, md):
    """b. K_B of lib/ against the closed form, clamped plateau, bolted rims, fillet-mesh check."""
    for r in rows["rim"]:
        if abs(r["K_B_lib"] / K_B(r["m_B"]) - 1) > 1e-5:  # the log prints 6 digits
            c.true("rating::agma::K_B against the closed form", False, g(r["K_B_lib"], 8), g(K_B(r["m_B"]), 8), AGMA)
            break
    else:
        c.true("rating::agma::K_B against the closed form (7 m_B)", True, "equal to 1e-5", "equal", AGMA)
    for mB in (1.5, 1.2):
        c.rel(f"clamped rim plateau, sigma(m_B {g(mB)})/sigma(2.0)", ratios["clamped"][mB], 1.0, TOL_PLATEAU,
              "AGMA 2001-D04: K_B = 1 for m_B >= 1.2")
    thin = [m for m in M_B if m <= 1.2]
    for s in ("bolts6_between", "bolts12_between"):
        seq = [peak[(s, m)][0]["sigma_MPa"] for m in thin]
        c.true(f"bolted rim ({SUPPORTS[s]}): sigma rises monotonically as m_B falls from 1.2 to 0.5",
               all(b > a for a, b in zip(seq, seq[1:])), " < ".join(f"{x:.0f}" for x in seq) + " MPa",
               "increasing", "AGMA 2001-D04: K_B rises below m_B = 1.2")
    for s in SUPPORTS:
        for mB in M_B:
            if mB < 1.2 or s != "clamped":
                c.info(f"FE/K_B, {SUPPORTS[s]}, m_B {g(mB)}", f"{ratios[s][mB] / K_B(mB):.3f}",
                       f"K_B {K_B(mB):.3f}", "README, rim thickness")
    # The fillet-mesh check of the thick clamped rim.
    fm = [k for k in peak if k[0].startswith("clamped_fillet")]
    for k in fm:
        c.info(f"thick clamped rim, fillet size {g(peak[k][0]['h_fillet_mm'])} mm against 0.1 mm",
               f"{peak[k][0]['sigma_MPa']:.1f} MPa", f"{ref['clamped']:.1f} MPa",
               f"{(peak[k][0]['sigma_MPa'] / ref['clamped'] - 1) * 100:+.2f} %")
    md += ["", "Fillet-mesh check (clamped, m_B = 2.0): " + ", ".join(
        f"h_fillet {g(peak[k][0]['h_fillet_mm'])} mm: {peak[k][0]['sigma_MPa']:.1f} MPa "
        f"({(peak[k][0]['sigma_MPa'] / ref['clamped'] - 1) * 100:+.2f} % against 0.1 mm)" for k in fm) + ".", ""]


def check_iso(c, rows, ref, md):
    """c. Ring root stress of the thick clamped rim against ISO 6336-3 method B."""
    iso = {r["T1_Nm"]: r for r in rows["iso"]}
    T1 = rows["rim"][0]["T1_Nm"]
    if T1 in iso and rows["iso_fe"]:
        ir = iso[T1]
        fe = ref["clamped"]
        light = rows["iso_fe"]
        Tl = light[0]["T1_Nm"]
        il = iso.get(Tl)
        alone = [r for r in light if r["share0"] > 0.999]
        first = min(alone, key=lambda r: r["phi1_deg"]) if alone else None
        near_B = min(light, key=lambda r: abs(r["phi1_deg"] - [p for p in rows["loa"] if p["point"] == "B"][0]
                                                   ["roll_deg"]))
        md += ["## c. Ring root stress against ISO 6336-3 method B (thick rim, clamped)", "",
               f"ISO (rate_internal): load F_t = 2 T1/d_1 on one pair at the ring's outer point of single contact B "
               f"(d_en = {ir['d_en_mm']:.3f} mm), closed-form section s_Fn = {ir['s_Fn_mm']:.3f} mm, "
               f"rho_F = {ir['rho_F_mm']:.3f} mm, h_Fe = {ir['h_Fe_mm']:.3f} mm, Y_F = {ir['Y_F']:.4f}, "
               f"Y_S = {ir['Y_S']:.4f}, Y_B = {ir['Y_B']:.3f}; on the generated fillet Y_F = {ir['Y_F_gen']:.4f}, "
               f"Y_S = {ir['Y_S_gen']:.4f}.", "",
               "| quantity | T1 [N m] | FE [MPa] | ISO sigma_F0 [MPa] | FE/ISO | FE/ISO (generated fillet) |",
               "|---|---|---|---|---|---|"]

        def iso_row(name, T, fe_val, i):
            md.append(f"| {name} | {g(T)} | {fe_val:.1f} | {i['sigma_F0_MPa']:.1f} | "
                      f"{fe_val / i['sigma_F0_MPa']:.3f} | {fe_val / i['sigma_F0_gen_MPa']:.3f} |")
            c.info(f"FE/ISO sigma_F0, {name}", f"{fe_val / i['sigma_F0_MPa']:.3f}",
                   f"ISO {i['sigma_F0_MPa']:.1f} MPa", "README, ISO 6336-3")

        iso_row("peak over the mesh cycle (pairs share the load)", T1, fe, ir)
        if il:
            iso_row(f"at B (phi1 {near_B['phi1_deg']:.2f} deg, share {near_B['share0']:.3f})", Tl,
                    near_B["sigma0_MPa"], il)
            iso_row("at B divided by the share (one pair carrying F_t at B, estimate)", Tl,
                    near_B["sigma0_MPa"] / near_B["share0"], il)
            if first:
                iso_row(f"first position with the pair alone (phi1 {first['phi1_deg']:.2f} deg)", Tl,
                        first["sigma0_MPa"], il)
        md.append("")
    else:
        c.true("ISO rows present", False, "missing", "rows iso and iso_fe", "validate_internal_gear.cc")


def check_equilibrium(c, rows, md):
    """d. Moments on the ring and the pinion bore against T1 and u T1."""
    eq = rows["equilibrium"]
    if eq:
        e = eq[0]
        uT = e["u"] * e["T1_Nm"]
        c.true("equilibrium position has one loaded pair", e["n_pairs"] == 1, int(e["n_pairs"]), "1",
               "validate_internal_gear.cc (mid single-pair zone, light load)")
        c.rel("ring contact moment at one loaded pair", e["torque_gear_Nm"], uT, TOL_EQ,
              "T2 = u T1 (frictionless forces on the line of action)", " N m")
        c.rel("pinion bore reaction at one loaded pair", e["torque_reaction_Nm"], e["T1_Nm"], TOL_EQ,
              "moment balance of the pinion", " N m")
    else:
        c.true("equilibrium row present", False, "missing", "1 row", "validate_internal_gear.cc")
    allrows = rows["hertz"] + rows["rim"] + rows["iso_fe"] + eq
    worst = max(abs(r["torque_reaction_Nm"] / r["T1_Nm"] - 1) for r in allrows)
    c.at_most(f"pinion bore reaction, all {len(allrows)} solved positions, max |M/T1 - 1|", worst, TOL_EQ,
              "moment balance of the pinion")
    single = [r for r in rows["rim"] + rows["iso_fe"] + eq if r["n_pairs"] == 1]
    if single:
        w1 = max(abs(r["torque_gear_Nm"] / (r["u"] * r["T1_Nm"]) - 1) for r in single)
        c.at_most(f"ring moment at the {len(single)} positions with one loaded pair, max |M2/(u T1) - 1|", w1, TOL_EQ,
                  "T2 = u T1 (frictionless forces on the line of action)")
    multi = [r for r in rows["rim"] + rows["iso_fe"] if r["n_pairs"] > 1]
    if multi:
        w2 = max(abs(r["torque_gear_Nm"] / (r["u"] * r["T1_Nm"]) - 1) for r in multi)
        c.info("ring moment where 2-3 pairs are loaded, max |M2/(u T1) - 1|", g(w2, 3), "—",
               "a pair touches near a tip or beyond A/E (README, d)")
    md += ["## d. Equilibrium", ""]
    if eq:
        md += [f"Middle of the single-pair zone (phi1 = {e['phi1_deg']:.3f} deg), T1 = {g(e['T1_Nm'])} N m, "
               f"{int(e['n_pairs'])} loaded pair: ring moment {e['torque_gear_Nm']:.4f} N m against u T1 = {uT:.4f} "
               f"N m ({(e['torque_gear_Nm'] / uT - 1):+.1e}); bore reaction {e['torque_reaction_Nm']:.4f} N m.", ""]
    md += [f"Bore reaction over all {len(allrows)} solved positions: max |M/T1 - 1| = {worst:.1e}.", ""]


def main():
    args = parse_args()
    rows = parse(args.log)
    c = Checks("internal_gear", args.out)
    c.true("validate_internal_gear exit status", args.status == 0, f"exit {args.status}", "exit 0",
           "tests/unit/contact/validate_internal_gear.cc")
    if not rows.get("geometry"):
        c.true("geometry row present", False, "missing", "1 row", "validate_internal_gear output")
        return c.finish()
    geo = rows["geometry"][0]
    md = []
    check_hertz(c, rows, geo, md)
    peak, missing = rim_peaks(c, rows)
    if missing:
        return finish(c, args, md)
    ref, ratios, mod = rim_tables(rows, geo, peak, md)
    check_rim(c, rows, peak, ref, ratios, md)
    check_iso(c, rows, ref, md)
    check_equilibrium(c, rows, md)
    if args.plot:
        plot(args.plot, peak, ratios, mod)
    return finish(c, args, md)


def finish(c, args, md):
    if args.table:
        write_if_changed(args.table, "# internal_gear: figures (written by check.py)\n\n" + "\n".join(md) + "\n")
    return c.finish()


def plot(path, peak, ratios, mod):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(1, 2, figsize=(11, 4.4))
    mk = {"clamped": "o-", "bolts6_between": "s-", "bolts6_over": "^-", "bolts12_between": "d-"}
    xs = [m / 100 for m in range(50, 201)]
    ax[0].plot(xs, [K_B(x) for x in xs], "k--", label="AGMA K_B")
    yb = [(x, Y_B_internal(x * peak[("clamped", 2.0)][0]["h_t_mm"], mod)) for x in xs]
    ax[0].plot([x for x, y in yb if y], [y for x, y in yb if y], "k:", label="ISO Y_B (internal, s_R/m_n)")
    for s, label in SUPPORTS.items():
        ax[0].plot(M_B, [ratios[s][m] for m in M_B], mk[s], label=label)
        ax[1].plot(M_B, [peak[(s, m)][0]["sigma_MPa"] for m in M_B], mk[s], label=label)
    ax[0].set_ylabel("sigma / sigma(m_B = 2.0), same support")
    ax[1].set_ylabel("ring root stress sigma_1 [MPa]")
    for a in ax:
        a.set_xlabel("backup ratio m_B = t_R / h_t")
        a.invert_xaxis()
        a.grid(True, alpha=0.3)
        a.legend(fontsize=8)
    ax[0].set_title("normalised ring root stress against K_B")
    ax[1].set_title("peak over a mesh cycle, T1 = 100 N m")
    fig.tight_layout()
    fig.savefig(path, dpi=110)


if __name__ == "__main__":
    sys.exit(main())
