#!/usr/bin/env python3
"""Checks of the Siasos 2010 root-stress case (README.md): the HPSTC positions against AGMA 908,
gearfem's AGMA rating against the thesis' AGMA tables, the FE mesh ladder (< 1 %), the FE root
stress at the loaded HPSTC against AGMA and ISO, and against the thesis' FEM (linearity in the
torque). Writes results/summary.md (the tables of the README) and results/checks.md.
Usage: check.py --out <results dir>
"""
import argparse
import math
import os
import sys

from vcheck import Checks, read_csv

TORQUES = (500.0, 400.0, 300.0, 200.0)
# Siasos 2010, tables 6.2-2/3 (AGMA with K_v 1.05 and the thesis' K_H; ANSYS PLANE42, mu 0.15).
THESIS_AGMA = {"pinion": (127.0, 101.6, 76.2, 50.8), "gear": (110.9, 88.7, 66.5, 44.4)}
THESIS_FEM = {"pinion": (117.4, 100.5, 77.3, 65.1), "gear": (105.7, 82.5, 67.9, 52.7)}
THESIS_KH = 1.1546  # the K_H that reproduces the thesis' AGMA tables (validation/analytical)
# Mesh ladder (run.sh): h_fillet at h_contact 0.05 mm, h_contact at h_fillet 0.125 mm [mm].
HF_LADDER = (0.5, 0.25, 0.125, 0.0625)
HC_LADDER = (0.2, 0.1, 0.05)
FINAL = "hc0.05_hf0.0625"


def run_name(hc, hf):
    return f"hc{hc:g}_hf{hf:g}"


def pair_csv(path):
    """{name: value} of pair.csv (gearfem profile)."""
    return {r["quantity"]: r["value"] for r in read_csv(path)}


def rating(path):
    """{(standard, symbol): [values per torque in file order]} of rating.csv (gearfem rate)."""
    import csv
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    torques = [float(h.split("=")[1].split("[")[0]) for h in rows[0][5:]]
    out = {(r[0], r[2]): [float(v) for v in r[5:]] for r in rows[1:] if r}
    return torques, out


def member_curves(out, name):
    """{torque: {"pinion": [(roll, sigma, share)], "gear": [...]}} from pairs.csv: the pinion
    fillet of pinion tooth 0 at roll >= 0 (C to D) and the gear fillet of gear tooth 0 at
    roll <= 0 (B to C), i.e. the tooth pair that passes through C."""
    rows = read_csv(os.path.join(out, name, "pairs.csv"))
    res = {}
    for r in rows:
        T = r["torque"]
        d = res.setdefault(T, {"pinion": [], "gear": []})
        phi = r["roll angle"]
        if int(r["pinion tooth"]) == 0 and phi >= -1e-9:
            d["pinion"].append((phi, r["root stress pinion"], r["load share"]))
        if int(r["gear tooth"]) == 0 and phi <= 1e-9:
            d["gear"].append((phi, r["root stress gear"], r["load share"]))
    for d in res.values():
        for k in d:
            d[k].sort()
    return res


def loaded_hpstc(curve, member):
    """Peak fillet stress of the tooth over its single-pair side of the HPSTC: the loaded HPSTC.
    Returns (roll, sigma, share, bound): bound is the rise of the stress over the last step
    before the peak on the single-pair side, a bound on what the 0.05 deg grid can miss."""
    i = max(range(len(curve)), key=lambda k: curve[k][1])
    j = i - 1 if member == "pinion" else i + 1  # the single-pair side: towards C
    bound = abs(curve[i][1] - curve[j][1]) if 0 <= j < len(curve) else math.inf
    return curve[i][0], curve[i][1], curve[i][2], bound


def at_point(curve, member):
    """(roll, sigma, share) at the geometric HPSTC: D for the pinion (last), B for the gear (first)."""
    return curve[-1] if member == "pinion" else curve[0]


def est_error(values):
    """values: Q on successively halved sizes. Returns (error estimate of the last, p used)."""
    d1 = values[-1] - values[-2]
    p = 1.0
    if len(values) >= 3:
        d0 = values[-2] - values[-3]
        if d0 * d1 > 0 and abs(d1) > 0:
            p = min(2.0, max(1.0, math.log2(abs(d0 / d1))))
    return d1 / (2 ** p - 1), p


def check_positions(c, out):
    """Section 1: B and D against the AGMA 908 closed forms. Returns (pair.csv, roll of D, roll of B)."""
    pr = pair_csv(os.path.join(out, "profile", "pair.csv"))
    m, alpha = pr["module"], math.radians(pr["working pressure angle"])
    rb1, rb2, ra1, ra2 = pr["base radius 1"], pr["base radius 2"], pr["tip radius 1"], pr["tip radius 2"]
    a = pr["centre distance"]
    pb = math.pi * m * math.cos(math.radians(pr["pressure angle"]))
    C6 = a * math.sin(alpha)
    C1 = C6 - math.sqrt(ra2 ** 2 - rb2 ** 2)  # AGMA 908-B89: start of contact A
    C5 = math.sqrt(ra1 ** 2 - rb1 ** 2)        # end of contact E
    C3 = rb1 * math.tan(alpha)                 # pitch point
    C4, C2 = C1 + pb, C5 - pb                  # pinion HPSTC, pinion LPSTC = gear HPSTC
    roll = lambda g: math.degrees((g - C3) / rb1)
    _, rt = rating(os.path.join(out, "rate", "rating.csv"))
    c.abs("D (pinion HPSTC) from T1 = AGMA 908 C4", pr["D g (from T1)"], C4, 1e-6, "AGMA 908-B89 C4 = C1 + p_b", " mm")
    c.abs("B (gear HPSTC) from T1 = AGMA 908 C2", pr["B g (from T1)"], C2, 1e-6, "AGMA 908-B89 C2 = C5 - p_b", " mm")
    c.abs("gearfem rate C4/m = profile D/m", rt[("AGMA", "C4")][0], pr["D g per module (AGMA 908 C-value)"], 1e-6,
          "gearfem rate (908-B89) against gearfem profile", "")
    c.abs("gearfem rate C2/m = profile B/m", rt[("AGMA", "C2")][0], pr["B g per module (AGMA 908 C-value)"], 1e-6,
          "gearfem rate (908-B89) against gearfem profile", "")
    sweep = read_csv(os.path.join(out, FINAL, "sweep.csv"))
    pts = {int(r["point (0 none; 1 A; 2 B; 3 C; 4 D; 5 E)"]): r["roll angle"] for r in sweep}
    c.abs("solve position named D: roll angle", pts.get(4), roll(C4), 1e-6, "(C4 - C3)/r_b1", " deg")
    c.abs("solve position named B: roll angle", pts.get(2), roll(C2), 1e-6, "(C2 - C3)/r_b1", " deg")
    return pr, roll(C4), roll(C2)


def check_agma(c, out):
    """Section 2: gearfem rate against the thesis' AGMA tables. Returns {"KH", "agma", "agma_kh",
    "nominal", "iso"}: K_H and the root stresses per member at TORQUES."""
    tq, rt = rating(os.path.join(out, "rate", "rating.csv"))
    _, rk = rating(os.path.join(out, "rate_thesis_kh", "rating.csv"))
    KH = rt[("AGMA", "K_H")][0]
    idx = [tq.index(T) for T in TORQUES]
    agma = {"pinion": [rt[("AGMA", "sigma_F1")][i] for i in idx], "gear": [rt[("AGMA", "sigma_F2")][i] for i in idx]}
    agma_kh = {"pinion": [rk[("AGMA", "sigma_F1")][i] for i in idx], "gear": [rk[("AGMA", "sigma_F2")][i] for i in idx]}
    fac = [rt[("AGMA", s)][0] for s in ("K_o", "K_v", "K_s", "K_H", "K_B")]
    nominal = {k: [v / math.prod(fac) for v in agma[k]] for k in agma}  # F_t/(b m Y_J)
    iso = {"pinion": [rt[("ISO 6336", "sigma_F01")][i] for i in idx], "gear": [rt[("ISO 6336", "sigma_F02")][i] for i in idx]}
    for k in ("pinion", "gear"):
        worst = max(abs(x / t - 1) for x, t in zip(agma_kh[k], THESIS_AGMA[k]))
        c.at_most(f"AGMA sigma_F {k}, thesis K_H 1.1546, worst of 4 torques vs thesis table", 100 * worst, 0.5,
                  "Siasos 2010 tables 6.2-2/3; 0.5 %: the tables' 0.1 MPa rounding (0.23 % at 44.4 MPa) and K_H to 5 digits", " %")
        dev = [100 * (x / t - 1) for x, t in zip(agma[k], THESIS_AGMA[k])]
        c.abs(f"AGMA sigma_F {k}, standard K_H {KH:.4f}: deviation from the thesis table (mean of 4)", sum(dev) / 4,
              100 * (KH / THESIS_KH - 1), 0.5, "K_H ratio 1.1751/1.1546 - 1 (validation/analytical); the tables' rounding", " %")
    for k in ("pinion", "gear"):  # Y_J from the generated fillet confirms the 908 layout
        s = "1" if k == "pinion" else "2"
        c.rel(f"AGMA Y_J {k}: 908 rack layout vs generated fillet", rt[("AGMA", "Y_J" + s + ",gen")][0],
              rt[("AGMA", "Y_J" + s)][0], 0.005, "gearfem rate, two constructions of the same fillet")
    return {"KH": KH, "agma": agma, "agma_kh": agma_kh, "nominal": nominal, "iso": iso}


def ladder_curves(out):
    """{run name: member_curves} of the h_fillet and h_contact ladders."""
    curves = {}
    for hc in (0.05,):
        for hf in HF_LADDER:
            curves[run_name(hc, hf)] = member_curves(out, run_name(hc, hf))
    for hc in HC_LADDER:
        curves[run_name(hc, 0.125)] = member_curves(out, run_name(hc, 0.125))
    return curves


def check_mesh_ladder(c, curves):
    """Section 3: discretisation error at 500 and 200 N m. Returns (summary lines,
    {(T, member, quantity): (finest value, total error estimate)})."""
    ladder_rows, err = [], {}
    for T in (500.0, 200.0):
        for k in ("pinion", "gear"):
            for what, fn in (("loaded HPSTC", lambda cv: loaded_hpstc(cv, k)), ("at " + ("D" if k == "pinion" else "B"), lambda cv: at_point(cv, k))):
                qf = [fn(curves[run_name(0.05, hf)][T][k])[1] for hf in HF_LADDER]
                qc = [fn(curves[run_name(hc, 0.125)][T][k])[1] for hc in HC_LADDER]
                ef, pf = est_error(qf)
                ec, pc = est_error(qc)
                grid = loaded_hpstc(curves[FINAL][T][k], k)[3] if what == "loaded HPSTC" else 0.0
                total = abs(ef) + abs(ec) + grid
                q = qf[-1]
                err[(T, k, what)] = (q, total)
                ladder_rows.append(f"| {T:g} | {k} | {what} | " + " / ".join(f"{v:.2f}" for v in qf) + f" | {100 * ef / q:+.2f} (p {pf:.2f}) | "
                                   + " / ".join(f"{v:.2f}" for v in qc) + f" | {100 * ec / qc[-1]:+.2f} (p {pc:.2f}) | {100 * grid / q:.2f} | {100 * total / q:.2f} |")
                c.at_most(f"FE {k} root stress {what}, {T:g} N m: estimated discretisation error", 100 * total / q, 1.0,
                          "Richardson on the h_fillet and h_contact ladders (observed order in [1, 2]) + position grid; requirement < 1 %", " %")
    md = ["## Mesh ladder (3-tooth sectors, Q2)", "",
          "h_fillet 0.5 / 0.25 / 0.125 / 0.0625 mm at h_contact 0.05 mm; h_contact 0.2 / 0.1 / 0.05 mm at h_fillet 0.125 mm. "
          "Error estimates in % of the finest value; total = |e_hf| + |e_hc| + position grid.", "",
          "| T1 [N m] | member | quantity | h_fillet ladder [MPa] | e_hf [%] | h_contact ladder [MPa] | e_hc [%] | grid [%] | total [%] |",
          "|---|---|---|---|---|---|---|---|---|"] + ladder_rows + [""]
    return md, err


def check_hpstc_positions(c, fin, fe_pt, roll_d, roll_b):
    """Section 4: the FE points at D and B, and the FE peak as the loaded HPSTC (4 torques)."""
    c.abs("FE 'at D' values: roll angle", max(p[0] for p in fe_pt["pinion"]), roll_d, 1e-6, "(C4 - C3)/r_b1", " deg")
    c.abs("FE 'at B' values: roll angle", min(p[0] for p in fe_pt["gear"]), roll_b, 1e-6, "(C2 - C3)/r_b1", " deg")
    for k in ("pinion", "gear"):
        ok, detail = True, []
        for T in TORQUES:
            cv = fin[T][k]
            i = max(range(len(cv)), key=lambda j: cv[j][1])
            nxt = i + 1 if k == "pinion" else i - 1  # the next grid point towards the geometric HPSTC
            good = cv[i][2] >= 0.999 and 0 <= nxt < len(cv) and cv[nxt][2] < 0.999
            ok = ok and good
            detail.append(f"{T:g}: share {cv[i][2]:.4f} at {cv[i][0]:.2f}, next {cv[nxt][2]:.4f}" if 0 <= nxt < len(cv) else f"{T:g}: at the window end")
        c.true(f"FE {k}: the peak is the last single-pair position before the next pair touches (4 torques)", ok,
               "; ".join(detail), "share >= 0.999 at the peak, < 0.999 one step on", "definition of the loaded HPSTC (README)")


def hpstc_table(fe, fe_pt, err, ag):
    """Summary lines of the root stress at the HPSTC: FE, AGMA, ISO and the thesis."""
    KH, agma, agma_kh, nominal, iso = ag["KH"], ag["agma"], ag["agma_kh"], ag["nominal"], ag["iso"]
    md = ["## Root stress at the HPSTC [MPa]", "",
          "| T1 [N m] | member | FE loaded HPSTC (roll [deg]) | est. error [%] | FE at the geometric HPSTC (share) | AGMA nominal F_t/(b m Y_J) | "
          f"AGMA gearfem (K_v 1.05, K_H {KH:.4f}) | AGMA gearfem, thesis K_H | AGMA thesis | ISO 6336-3 sigma_F0 | thesis FEM (mu 0.15) |",
          "|---|---|---|---|---|---|---|---|---|---|---|"]
    for k in ("pinion", "gear"):
        for i, T in enumerate(TORQUES):
            e = err.get((T, k, "loaded HPSTC"))
            md.append(f"| {T:g} | {k} | {fe[k][i][1]:.2f} ({fe[k][i][0]:.2f}) | {100 * e[1] / e[0]:.2f} | " if e else
                      f"| {T:g} | {k} | {fe[k][i][1]:.2f} ({fe[k][i][0]:.2f}) | (ladder at 500, 200) | ")
            md[-1] += (f"{fe_pt[k][i][1]:.2f} ({fe_pt[k][i][2]:.3f}) | {nominal[k][i]:.2f} | {agma[k][i]:.2f} | {agma_kh[k][i]:.2f} | "
                       f"{THESIS_AGMA[k][i]} | {iso[k][i]:.2f} | {THESIS_FEM[k][i]} |")
    md.append("")
    return md


def check_against_standards(c, fin, fe, fe_pt, nominal, iso):
    """Section 4: FE at the loaded HPSTC against AGMA nominal and ISO, and FE at the geometric
    HPSTC against the single-pair branch."""
    for k in ("pinion", "gear"):
        # Static FE, uniform load over the face: compare with AGMA without K_o K_v K_s K_H K_B.
        worst = max((f[1] / n - 1 for f, n in zip(fe[k], nominal[k])), key=abs)
        c.within(f"FE {k} loaded HPSTC / AGMA nominal - 1, worst of 4 torques", 100 * worst, -20, 20,
                 "AGMA 908 Y_J (Lewis + Dolan-Broghamer K_f): 20 %, the spread of the two standards on this pair (README)", " %")
        worst = max((f[1] / n - 1 for f, n in zip(fe[k], iso[k])), key=abs)
        c.within(f"FE {k} loaded HPSTC / ISO 6336-3 sigma_F0 (method B) - 1, worst of 4 torques", 100 * worst, -20, 20,
                 "ISO 6336-3 method B (load at the outer point of single contact); same 20 %", " %")
        # The geometric HPSTC carries only part of the load (the next pair touches at zero gap):
        # sigma(point)/share is the whole load at the point; compare it with the single-pair
        # branch (share 1) extrapolated linearly to the point.
        worst = 0.0
        for i, T in enumerate(TORQUES):
            branch = [(p, s_) for p, s_, sh in fin[T][k] if sh > 1 - 1e-12]
            branch = branch[-6:] if k == "pinion" else branch[:6]  # the last 0.25 deg before the peak
            n_ = len(branch)
            mx = sum(p for p, _ in branch) / n_
            my = sum(s_ for _, s_ in branch) / n_
            sl = sum((p - mx) * (s_ - my) for p, s_ in branch) / sum((p - mx) ** 2 for p, _ in branch)
            pred = my + sl * (fe_pt[k][i][0] - mx)
            worst = max(worst, abs(fe_pt[k][i][1] / fe_pt[k][i][2] / pred - 1), key=abs)
        c.at_most(f"FE {k}: sigma at {'D' if k == 'pinion' else 'B'} / load share vs single-pair branch extrapolated there, worst",
                  100 * worst, 5.0, "explains sigma at the geometric HPSTC (its load share); 5 %: the other pair's load (README)", " %")


def check_linearity(c, fin, fe, fe_pt):
    """Section 4: linearity of FE and thesis FEM in the torque. Returns the summary lines."""
    # Linearity: a frictionless elastic pair at a fixed position scales with the torque up to the
    # Hertzian patch growth; the loaded HPSTC itself moves with the torque (the next pair
    # touches earlier under a larger deflection), which the peak values carry.
    lin_rows = []
    for k in ("pinion", "gear"):
        full = [phi for phi, s_, sh in fin[500.0][k] if sh > 1 - 1e-12]
        common = [phi for phi in full if all(any(abs(p - phi) < 1e-9 and sh > 1 - 1e-12 for p, s_, sh in fin[T][k]) for T in TORQUES)]
        val = {T: {p: s_ for p, s_, sh in fin[T][k]} for T in TORQUES}
        fixed = max(abs((val[T][p] / T) / (val[500.0][p] / 500.0) - 1) for p in common for T in TORQUES)
        c.at_most(f"FE {k}, every single-pair position ({len(common)}, {min(common):.2f} to {max(common):.2f} deg): "
                  f"|sigma(T)/T / (sigma(500)/500) - 1|, worst", 100 * fixed, 0.1,
                  "linear elasticity, frictionless, fixed position: homogeneous in T up to the Hertz patch (0.1 %)", " %")
        s500 = fe[k][0][1] / 500.0
        dev = [(f[1] / T) / s500 - 1 for f, T in zip(fe[k], TORQUES)]
        c.at_most(f"FE {k} loaded HPSTC: |sigma(T)/T / (sigma(500)/500) - 1|, worst", 100 * max(abs(d) for d in dev), 2.0,
                  "the loaded HPSTC moves towards the geometric one as the torque falls (roll column): 2 %", " %")
        devp = [(f[1] / T) / (fe_pt[k][0][1] / 500.0) - 1 for f, T in zip(fe_pt[k], TORQUES)]
        c.at_most(f"FE {k} at the geometric HPSTC: same, worst", 100 * max(abs(d) for d in devp), 0.5,
                  "fixed position, zero gap of the next pair: load share independent of T (0.5 %)", " %")
        t500 = THESIS_FEM[k][0] / 500.0
        tdev = [(t / T) / t500 - 1 for t, T in zip(THESIS_FEM[k], TORQUES)]
        for d, dp, td, T in zip(dev, devp, tdev, TORQUES):
            lin_rows.append(f"| {k} | {T:g} | {100 * d:+.2f} | {100 * dp:+.2f} | {100 * td:+.1f} |")
        # The thesis' 200 N m values leave the linear trend of its own 500 N m value: its defect.
        c.at_least(f"thesis FEM {k} at 200 N m above its 500 N m value scaled linearly", 100 * tdev[-1], 10.0,
                   "thesis table 6.2-2/3; shown defect: > 5x gearfem's own non-linearity (2 %)", " %")
        # At 500 N m, where a load-independent offset weighs least, FE and thesis FEM agree.
        c.rel(f"FE {k} loaded HPSTC vs thesis FEM at 500 N m", fe[k][0][1], THESIS_FEM[k][0], 0.15,
              "thesis table 6.2-2/3; 15 %: friction mu 0.15 on the bending moment (beam estimate, README)", " MPa")
        # Explanation of the low-torque gap: the thesis is affine in gearfem's linear values.
        xs = [f[1] for f in fe[k]]
        ys = list(THESIS_FEM[k])
        n = len(xs)
        mx, my = sum(xs) / n, sum(ys) / n
        slope = sum((x - mx) * (y - my) for x, y in zip(xs, ys)) / sum((x - mx) ** 2 for x in xs)
        icpt = my - slope * mx
        rms = math.sqrt(sum((y - icpt - slope * x) ** 2 for x, y in zip(xs, ys)) / n)
        c.within(f"thesis FEM {k} = a + b x FE (4 torques): offset a", icpt, 10.0, 40.0,
                 "the low-torque excess is a load-independent offset (README)", " MPa")
        c.at_most(f"thesis FEM {k} = a + b x FE: rms residual", rms, 3.0,
                  "the tables' own scatter about a line (README)", " MPa")
    return ["## Linearity in the torque: sigma(T)/T against sigma(500)/500 - 1 [%]", "",
            "| member | T1 [N m] | FE loaded HPSTC | FE at the geometric HPSTC | thesis FEM |", "|---|---|---|---|---|"] + lin_rows + [""]


def check_near_a(c, out, pr):
    """Section 5: the h_contact sensitivity of validation/speed_vs_error. Returns the summary lines."""
    # The contact at A lies r_A - r_Ff above the pinion's form circle, where the fillet meets
    # the involute. With h_contact above that gap one element spans the contact patch and the
    # fillet end, and the entering tooth's peak fillet stress jumps to the fillet end (r_Ff).
    rF, rA = pr["form radius 1"], pr["start of active profile radius 1"]
    near = {}
    for name in ("nearA_hc0.4", "nearA_hc0.05"):
        rows = read_csv(os.path.join(out, name, "pairs.csv"))
        near[name] = [(r["roll angle"], r["root stress pinion"], r["root radius pinion"], r["load share"])
                      for r in rows if int(r["pinion tooth"]) == 0]
    md = ["## The first positions after A (entering pinion tooth), h_fillet 0.25 mm", "",
          f"r_A - r_Ff = {rA - rF:.3f} mm (start of active profile {rA:.3f} mm, form radius {rF:.3f} mm).", "",
          "| roll [deg] | load share | h_contact 0.4: sigma [MPa] (radius [mm]) | h_contact 0.05: sigma [MPa] (radius [mm]) |",
          "|---|---|---|---|"]
    for a_, b_ in zip(near["nearA_hc0.4"], near["nearA_hc0.05"]):
        md.append(f"| {a_[0]:.3f} | {b_[3]:.3f} | {a_[1]:.2f} ({a_[2]:.3f}) | {b_[1]:.2f} ({b_[2]:.3f}) |")
    md.append("")
    coarse = max(near["nearA_hc0.4"], key=lambda x: x[1])
    fine = max(near["nearA_hc0.05"], key=lambda x: x[1])
    c.at_least("near A, h_contact 0.4: entering tooth's peak / its h_contact 0.05 value", coarse[1] / fine[1], 1.25,
               "the speed_vs_error symptom (25-36 % at h_contact 0.4 / 0.25 mm)")
    c.abs("near A, h_contact 0.4: radius of that peak - form radius", coarse[2] - rF, 0.0, 0.05,
          "the excess sits at the fillet end beside the contact", " mm")
    c.at_least("near A, h_contact 0.05: form radius - radius of the peak", rF - fine[2], 1.0,
               "converged: the peak is in the fillet, away from the contact", " mm")
    c.at_most("r_A - r_Ff (contact at A above the form circle)", rA - rF, 0.4,
              "below h_contact 0.4 mm: one element spans both", " mm")
    return md


def write_summary(out, md):
    """Appends the wall time of run.sh, writes results/summary.md and prints it."""
    # Cost of the run (reported).
    wt = os.path.join(out, "wall_time.txt")
    if os.path.exists(wt):
        md += ["Wall time of run.sh: " + open(wt).read().strip().split("time")[-1].strip(), ""]
    with open(os.path.join(out, "summary.md"), "w") as f:
        f.write("\n".join(md) + "\n")
    print("\n".join(md))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--out", required=True)
    out = ap.parse_args().out
    c = Checks("seed001_root_stress", out)
    md = []

    # ---- 1. positions: B and D against AGMA 908 closed forms ------------------------------
    pr, roll_d, roll_b = check_positions(c, out)

    # ---- 2. AGMA: gearfem rate against the thesis' AGMA tables ---------------------------
    ag = check_agma(c, out)

    # ---- 3. FE: mesh ladder ---------------------------------------------------------------
    curves = ladder_curves(out)
    ladder_md, err = check_mesh_ladder(c, curves)
    md += ladder_md

    # ---- 4. FE at all torques (finest mesh): against AGMA, ISO and the thesis -----------
    fin = curves[FINAL]
    fe = {k: [loaded_hpstc(fin[T][k], k) for T in TORQUES] for k in ("pinion", "gear")}
    fe_pt = {k: [at_point(fin[T][k], k) for T in TORQUES] for k in ("pinion", "gear")}
    check_hpstc_positions(c, fin, fe_pt, roll_d, roll_b)
    md += hpstc_table(fe, fe_pt, err, ag)
    check_against_standards(c, fin, fe, fe_pt, ag["nominal"], ag["iso"])
    md += check_linearity(c, fin, fe, fe_pt)

    # ---- 5. the h_contact sensitivity of validation/speed_vs_error -------------------------
    md += check_near_a(c, out, pr)

    write_summary(out, md)
    sys.exit(c.finish())


if __name__ == "__main__":
    try:
        main()
    except (OSError, KeyError, ValueError, IndexError, ZeroDivisionError) as e:  # missing or malformed results
        print(f"seed001_root_stress: FAIL (check.py could not read the results: {type(e).__name__}: {e})")
        sys.exit(1)
