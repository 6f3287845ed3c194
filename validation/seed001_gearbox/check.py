#!/usr/bin/env python3
"""Checks of the 150 kW gearbox of Siasos 2010 (README.md) against the thesis (NTUA;
../shared/reference/SEED001_GEARBOX.md): the damage chain from the thesis'
tabulated stresses, the first failure, the scuffing risk, and gearfem's own AGMA contact
stresses against the thesis tables. Ends with one PASS or FAIL line (exit 1 on FAIL)."""
import csv
import math
import os
import sys

out = sys.argv[1]
checks = []


def check(name, ok, detail):
    checks.append((name, ok))
    print(f"  {'ok  ' if ok else 'FAIL'} {name}: {detail}")


def rows(case, name):
    with open(os.path.join(out, case, name)) as f:
        return list(csv.DictReader(f))


life = rows("seed001_gearbox_thesis_stresses", "gearbox_life.csv")
damaged = [r for r in life if float(r["damage D [-]"]) > 0]
sun = [r for r in damaged if r["stage"] == "Stage 1" and r["member"] == "sun" and r["mode"] == "contact"]
planet = [r for r in damaged if r["stage"] == "Stage 1" and r["member"] == "planet" and r["mode"] == "contact"]
spectra = lambda r: float(r["life [spectra] (empty: no damage)"])
# Thesis Tables 9.4-5/6: sun D = 0.2732, life 3.66 spectra; planet 19.22; rounding of the
# tabulated stresses (2 decimals) moves the lives by < 0.2 %: tolerance 0.5 %.
check("stage-1 sun contact life [spectra]", len(sun) == 1 and abs(spectra(sun[0]) / 3.66 - 1) <= 5e-3,
      f"{spectra(sun[0]) if sun else None} vs 3.66 (thesis), 0.5 %")
check("stage-1 sun damage D", len(sun) == 1 and abs(float(sun[0]["damage D [-]"]) / 0.2732 - 1) <= 5e-3,
      f"{sun[0]['damage D [-]'] if sun else None} vs 0.2732 (thesis), 0.5 %")
check("stage-1 planet contact life [spectra]", len(planet) == 1 and abs(spectra(planet[0]) / 19.22 - 1) <= 5e-3,
      f"{spectra(planet[0]) if planet else None} vs 19.22 (thesis), 0.5 %")
check("no damage elsewhere (all other members, all bending)", len(damaged) == 2,
      f"{len(damaged)} damaged member-modes vs 2 (thesis)")
first = min(damaged, key=spectra) if damaged else None
check("first failure: stage-1 sun, pitting", first is not None and first["member"] == "sun" and first["mode"] == "contact",
      f"{first['stage'] + ' ' + first['member'] + ' ' + first['mode'] if first else None} (thesis ch. 10)")

own = rows("seed001_gearbox", "gearbox.csv")
p_max = max(float(r["P_scuffing [-]"]) for r in own)
check("scuffing probability, every bin and mesh", p_max <= 0.05, f"max {p_max} vs <= 5 % (thesis App. B, low risk)")
thesis = [1322.96, 659.17, 862.75, 456.07]  # contact stresses at 45 000 N m, thesis tables
first_bin = [float(r["sigma_H [MPa]"]) for r in own if abs(float(r["input torque [N m]"]) - 45000) < 1e-6]
# The thesis' own printed formulas land +2.4 / -0.5 / +1.6 / -4.0 % from its tables (digest):
# an unstated detail; 5 % bounds that spread without tuning to the tables.
ok = len(first_bin) == 4 and all(abs(a / b - 1) <= 0.05 for a, b in zip(first_bin, thesis))
check("AGMA sigma_H at 45 000 N m vs the thesis tables",
      ok, ", ".join(f"{a:.2f}/{b} ({100 * (a / b - 1):+.2f} %)" for a, b in zip(first_bin, thesis)) + ", 5 %")


# ---- ISO and FE stress sources (stage-2 sun-planet mesh) -----------------------------------
def num(x):
    return float(x) if x not in ("", "inf") else math.inf


def bin_rows(case, stage, mesh):
    return {float(r["input torque [N m]"]): r for r in rows(case, "gearbox.csv") if r["stage"] == stage and r["mesh"] == mesh}


# Miner re-done in Python from gearbox_sn.csv (an independent implementation of eqs. 8.4-1..4:
# N = N_ref 10^((sigma - sigma_n)/B), no damage at or below sigma_n) against gearbox_life.csv.
def miner_check(case):
    sn = rows(case, "gearbox_sn.csv")
    worst = 0.0
    for r in rows(case, "gearbox_life.csv"):
        pts = [q for q in sn if (q["stage"], q["member"], q["mode"]) == (r["stage"], r["member"], r["mode"])
               and q["load"].startswith(r["load"])]
        D = 0.0
        for q in pts:
            sig, sn_, Nref, B = float(q["stress [MPa]"]), float(q["sigma_n [MPa]"]), float(q["N_ref [-]"]), float(q["B [MPa/decade]"])
            if sig > sn_:
                D += float(q["cycles per spectrum [-]"]) / (Nref * 10 ** ((sig - sn_) / B))
        d = float(r["damage D [-]"])
        worst = max(worst, abs(D - d) / max(d, 1e-300) if d > 0 else (0.0 if D == 0 else math.inf))
    return worst


cases = ["seed001_gearbox", "seed001_gearbox_iso", "seed001_gearbox_fe"]
for case in cases:
    w = miner_check(case)
    check(f"{case}: Miner from gearbox_sn.csv (Python) = gearbox_life.csv", w <= 1e-6, f"max relative difference {w:.2e}, 1e-6")

agma = bin_rows("seed001_gearbox", "Stage 2", "sun-planet")
iso = bin_rows("seed001_gearbox_iso", "Stage 2", "sun-planet")
fe = bin_rows("seed001_gearbox_fe", "Stage 2", "sun-planet")
top = 45000.0
# ISO 6336-3 sigma_F on every external member, none on the ring (not rated, as in AGMA).
pr = bin_rows("seed001_gearbox", "Stage 2", "planet-ring")
ok = all(float(r["ISO sigma_F1 [MPa]"]) > 0 and float(r["ISO sigma_F2 [MPa]"]) > 0 for r in agma.values()) and \
    all(float(r["ISO sigma_F1 [MPa]"]) > 0 and float(r["ISO sigma_F2 [MPa]"]) == 0 for r in pr.values())
check("ISO 6336-3 sigma_F: every external member rated, ring not", ok,
      f"stage-2 sun-planet {agma[top]['ISO sigma_F1 [MPa]']}/{agma[top]['ISO sigma_F2 [MPa]']} MPa at 45 000 N m")
# The ISO source uses the ISO columns: sigma_H = max(sigma_H1, sigma_H2), sigma_F = ISO 6336-3.
r = iso[top]
ok = abs(float(r["sigma_H [MPa]"]) - max(float(r["ISO sigma_H1 [MPa]"]), float(r["ISO sigma_H2 [MPa]"]))) < 1e-6 and \
    abs(float(r["sigma_F1 [MPa]"]) - float(r["ISO sigma_F1 [MPa]"])) < 1e-6
check("Stress source = ISO puts the ISO columns into the damage sum", ok, f"sigma_H {r['sigma_H [MPa]']} MPa")

fe_all = rows("seed001_gearbox_fe", "fe_stresses.csv")
fes = [q for q in fe_all if q["stage [-]"] == "2" and q["mesh (0 sun-planet or pair) [-]"] == "0"]
solved = {float(q["input torque [N m]"]): q for q in fes}
# At a solved torque the damage-sum stress is the FE value (interpolation exact there).
ok = all(abs(float(fe[T]["sigma_H [MPa]"]) - float(q["sigma_H FE Hertz [MPa]"])) < 1e-6 * float(q["sigma_H FE Hertz [MPa]"]) and
         abs(float(fe[T]["sigma_F1 [MPa]"]) - float(q["sigma_F1 FE [MPa]"])) < 1e-6 * float(q["sigma_F1 FE [MPa]"])
         for T, q in solved.items())
check("FE: damage-sum stresses = FE values at the solved torques", ok and len(solved) == 3, f"{sorted(solved)} N m")
# Hertz law: sigma_H/sqrt(T) nearly constant between solved torques (load share barely changes).
ks = [float(q["sigma_H FE Hertz [MPa]"]) / math.sqrt(T) for T, q in sorted(solved.items())]
check("FE: sigma_H ~ sqrt(T) (Hertz with the FE load share)", max(ks) / min(ks) - 1 <= 0.05,
      ", ".join(f"{k:.4f}" for k in ks) + " MPa/sqrt(N m), spread <= 5 %")
# FE Hertz against AGMA sigma_H (the same W, Hertz at the critical single-contact point):
# a priori bound 10 %; the FE root stress against ISO 6336-3 (method B): 25 %.
sH_fe, sH_a = float(fe[top]["sigma_H [MPa]"]), float(agma[top]["sigma_H [MPa]"])
check("FE sigma_H vs AGMA at 45 000 N m", abs(sH_fe / sH_a - 1) <= 0.10, f"{sH_fe:.1f} vs {sH_a:.1f} MPa ({100 * (sH_fe / sH_a - 1):+.1f} %), 10 %")
for k in ("1", "2"):
    f_, i_ = float(fe[top][f"sigma_F{k} [MPa]"]), float(agma[top][f"ISO sigma_F{k} [MPa]"])
    check(f"FE sigma_F{k} vs ISO 6336-3 at 45 000 N m", abs(f_ / i_ - 1) <= 0.25, f"{f_:.1f} vs {i_:.1f} MPa ({100 * (f_ / i_ - 1):+.1f} %), 25 %")
# The planet-ring meshes (a pinion in a ring, docs/internal-gears.md): FE values in the damage
# sum at the solved torques, and the FE Hertz stress against AGMA's internal Z_I. AGMA loads
# one pair at its critical point; the conformal internal mesh shares the load with the
# neighbouring pairs (validation/internal_gear), so the FE lies below AGMA: bound [0.75, 1.05].
for st in ("1", "2"):
    ring_fe = {float(q["input torque [N m]"]): q for q in fe_all if q["stage [-]"] == st and q["mesh (0 sun-planet or pair) [-]"] == "1"}
    ring_tab = bin_rows("seed001_gearbox_fe", "Stage " + st, "planet-ring")
    ok = len(ring_fe) == 3 and all(
        abs(float(ring_tab[T]["sigma_H [MPa]"]) - float(q["sigma_H FE Hertz [MPa]"])) < 1e-6 * float(q["sigma_H FE Hertz [MPa]"]) and
        abs(float(ring_tab[T]["sigma_F2 [MPa]"]) - float(q["sigma_F2 FE [MPa]"])) < 1e-6 * float(q["sigma_F2 FE [MPa]"])
        for T, q in ring_fe.items())
    check(f"FE stage-{st} planet-ring: damage-sum sigma_H and ring sigma_F = FE values", ok, f"{sorted(ring_fe)} N m")
    r_fe = float(ring_tab[top]["sigma_H [MPa]"])
    r_ag = float(bin_rows("seed001_gearbox", "Stage " + st, "planet-ring")[top]["sigma_H [MPa]"])
    check(f"FE stage-{st} planet-ring sigma_H vs AGMA (internal Z_I) at 45 000 N m", 0.75 <= r_fe / r_ag <= 1.05,
          f"{r_fe:.1f} vs {r_ag:.1f} MPa ({100 * (r_fe / r_ag - 1):+.1f} %), [0.75, 1.05]; ring sigma_F "
          f"{float(ring_tab[top]['sigma_F2 [MPa]']):.1f} MPa (AGMA and ISO do not rate the ring)")
# The life chain with FE stresses on every mesh: the first failure stays the stage-1 sun (pitting).
LIFE = "life [spectra] (empty: no damage)"
fe_lives = [r for r in rows("seed001_gearbox_fe", "gearbox_life.csv") if num(r[LIFE]) < math.inf]
fe_first = min(fe_lives, key=lambda r: num(r[LIFE])) if fe_lives else None
ring_bending = [r for r in rows("seed001_gearbox_fe", "gearbox_life.csv") if r["member"] == "ring" and r["mode"] == "bending"]
check("FE on every mesh: first failure stage-1 sun, pitting; the ring rated in bending",
      fe_first is not None and fe_first["stage"] == "Stage 1" and fe_first["member"] == "sun" and fe_first["mode"] == "contact"
      and len(ring_bending) == 2,
      (f"{fe_first['stage']} {fe_first['member']} {fe_first['mode']}, {num(fe_first[LIFE]):.4g} spectra" if fe_first else "none")
      + f"; {len(ring_bending)} ring bending rows")
# Stage 1 (the member that fails): FE sigma_H against the thesis' table (1322.96 MPa at
# 45 000 N m), with the same a-priori 5 % bound as the AGMA check above (not tuned).
fe1 = bin_rows("seed001_gearbox_fe", "Stage 1", "sun-planet")[top]
s1 = float(fe1["sigma_H [MPa]"])
check("FE stage-1 sun-planet sigma_H vs the thesis tables", abs(s1 / 1322.96 - 1) <= 0.05,
      f"{s1:.2f} vs 1322.96 MPa ({100 * (s1 / 1322.96 - 1):+.2f} %; AGMA {float(bin_rows('seed001_gearbox', 'Stage 1', 'sun-planet')[top]['sigma_H [MPa]']):.2f}), 5 %")
# Mesh convergence: halved element sizes at the top torque.
fine = [q for q in rows("seed001_gearbox_fe_fine", "fe_stresses.csv") if q["stage [-]"] == "2" and q["mesh (0 sun-planet or pair) [-]"] == "0"][0]
for col, tol in (("sigma_H FE Hertz [MPa]", 0.02), ("sigma_F1 FE [MPa]", 0.03), ("sigma_F2 FE [MPa]", 0.03)):
    a, b = float(solved[top][col]), float(fine[col])
    check(f"FE convergence, {col} (h -> h/2)", abs(a / b - 1) <= tol, f"{a:.2f} -> {b:.2f} ({100 * (a / b - 1):+.2f} %), {100 * tol:.0f} %")


def life_of(case, member, mode, detail="", stage="Stage 2"):
    for r in rows(case, "gearbox_life.csv"):
        if r["stage"] == stage and r["member"] == member and r["mode"] == mode and detail in r["load"]:
            return num(r["life [spectra] (empty: no damage)"])
    return None


print("  stage-2 sun-planet at 45 000 N m and lives [spectra] by stress source (inf: no damage):")
for name, case, t in (("AGMA", "seed001_gearbox", agma), ("ISO", "seed001_gearbox_iso", iso), ("FE", "seed001_gearbox_fe", fe)):
    print(f"    {name:4s} sigma_H {float(t[top]['sigma_H [MPa]']):8.2f} sigma_F1/F2 {float(t[top]['sigma_F1 [MPa]']):7.2f}/"
          f"{float(t[top]['sigma_F2 [MPa]']):7.2f} MPa; sun contact {life_of(case, 'sun', 'contact')}, planet sun-side "
          f"{life_of(case, 'planet', 'contact', 'sun-side')}, sun bending {life_of(case, 'sun', 'bending')}, "
          f"planet bending {life_of(case, 'planet', 'bending')}")

print("  stage-1 sun contact life [spectra] by stress source (thesis 3.66 from its tables): " + ", ".join(
    f"{n} {life_of(c, 'sun', 'contact', stage='Stage 1'):.4g}" for n, c in
    (("AGMA", "seed001_gearbox"), ("ISO", "seed001_gearbox_iso"), ("FE", "seed001_gearbox_fe"), ("thesis sigma", "seed001_gearbox_thesis_stresses"))))
# What-if (not the thesis' material): stage-2 contact endurance lowered to 850 MPa, below the
# top-bin sigma_H of AGMA and FE (ISO stays below it); Miner in Python from each run's
# gearbox_sn.csv (stage-2 sun, contact). The sensitivity law: with sigma_FE/sigma_AGMA nearly
# the same in every damaging bin, life_FE/life_AGMA = 10^((sigma_AGMA - sigma_FE)/10 MPa)
# at the top bin (15 %: the difference shrinks slightly with sqrt(T) in the lower bins).
def whatif_sun_life(case, sigma_n=850.0):
    D = 0.0
    for q in rows(case, "gearbox_sn.csv"):
        if (q["stage"], q["member"], q["mode"]) == ("Stage 2", "sun", "contact"):
            sig = float(q["stress [MPa]"])
            if sig > sigma_n:
                D += float(q["cycles per spectrum [-]"]) / (float(q["N_ref [-]"]) * 10 ** ((sig - sigma_n) / float(q["B [MPa/decade]"])))
    return 1 / D if D > 0 else math.inf


L = {n: whatif_sun_life(c) for n, c in (("AGMA", "seed001_gearbox"), ("ISO", "seed001_gearbox_iso"), ("FE", "seed001_gearbox_fe"))}
print("  what-if, stage-2 contact sigma_n = 850 MPa (thesis: 930): stage-2 sun life [spectra] "
      + ", ".join(f"{n} {v:.4g}" for n, v in L.items()))
expected = 10 ** ((float(agma[top]["sigma_H [MPa]"]) - float(fe[top]["sigma_H [MPa]"])) / 10.0)
check("what-if life ratio FE/AGMA = 10^(delta sigma_H / 10 MPa)", math.isfinite(L["AGMA"]) and
      abs(L["FE"] / L["AGMA"] / expected - 1) <= 0.15 and math.isinf(L["ISO"]),
      f"{L['FE'] / L['AGMA']:.3f} vs {expected:.3f}, 15 %; ISO (768.8 MPa < 850) no damage")

bad = [n for n, ok in checks if not ok]
print(f"seed001_gearbox: {'PASS' if not bad else 'FAIL'} ({len(checks)} checks{': ' + '; '.join(bad) if bad else ''})")
sys.exit(1 if bad else 0)
