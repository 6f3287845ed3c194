#!/usr/bin/env python3
"""Checks of seed 001's 150 kW gearbox (issue 16, section 3) against the thesis (Siasos,
NTUA 2010; ../shared/reference/SEED001_GEARBOX.md): the damage chain from the thesis'
tabulated stresses, the first failure, the scuffing risk, and gearfem's own AGMA contact
stresses against the thesis tables. Ends with one PASS or FAIL line (exit 1 on FAIL)."""
import csv
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

bad = [n for n, ok in checks if not ok]
print(f"seed001_gearbox: {'PASS' if not bad else 'FAIL'} ({len(checks)} checks{': ' + '; '.join(bad) if bad else ''})")
sys.exit(1 if bad else 0)
