#!/usr/bin/python3
"""Checks of validation/manufacturing_deviations (run.sh writes results/): kinematics of the
deviations on the demo pair's hunting cycle, and the Monte Carlo study against the ISO 1328-1:2013
tolerance formulas (evaluated here, independently of gearfem) and the statistics of its draws.
Usage: check.py --out RESULTS_DIR
"""
import argparse
import csv
import math
import os
import re
import sys

import numpy as np

from vcheck import Checks

UNIT = re.compile(r"\s*\[[^\]]*\]\s*$")
Z1 = Z2 = 50
M = 40
N_GEO, P_GEO = 20, 3  # positions per pitch, pitches of the geometry comparison (run.sh step 5)
ALPHA = math.radians(20)


def read(path):
    with open(path, newline="") as f:
        rows = [r for r in csv.reader(f) if r]
    names = [UNIT.sub("", h.strip()) for h in rows[0]]
    data = np.array([[float(v) for v in r] for r in rows[1:]], dtype=float)
    return {n: data[:, i] for i, n in enumerate(names)}


def iso1328(grade, m, d):
    """ISO 1328-1:2013 clause 5.3, rounded by its rule (5.2) [um]."""
    s = math.sqrt(2) ** (grade - 5)

    def r(v):
        step = 1.0 if v > 10 else (0.5 if v >= 5 else 0.1)
        return round(v / step) * step

    F_p = (0.002 * d + 0.55 * math.sqrt(d) + 0.7 * m + 12) * s
    return {"f_pT": r((0.001 * d + 0.4 * m + 5) * s), "F_pT": r(F_p), "F_rT": r(0.9 * F_p)}


def spectrum(x, samples_per_rev):
    x = np.asarray(x) - np.mean(x)
    a = np.abs(np.fft.rfft(x)) / len(x)
    a[1:] *= 2
    return np.arange(len(a)) * samples_per_rev / len(x), a


def loaded_pairs(pairs, position):
    """The (pinion tooth, gear tooth) pairs that carry load at one position."""
    rows = (pairs["position"].astype(int) == position) & (pairs["load share"] > 1e-6)
    return set(zip(pairs["pinion tooth"][rows].astype(int), pairs["gear tooth"][rows].astype(int)))


def geometry_checks(c, geo):
    """Pitch deviations built into the geometry (full FE, teeth turned by F_p,k / r_ref) against the
    condensed route's hunting cycle, position by position over P_GEO pitches of N_GEO positions."""
    nominal = read(os.path.join(geo, "nominal", "sweep.csv"))
    hunt, hunt_pairs = read(os.path.join(geo, "hunting", "sweep.csv")), read(os.path.join(geo, "hunting", "pairs.csv"))
    full, full_pairs = read(os.path.join(geo, "geometry", "sweep.csv")), read(os.path.join(geo, "geometry", "pairs.csv"))
    n = N_GEO * P_GEO
    c.abs("positions: condensed hunting cycle, full FE sweep", float(len(hunt["STE"]) + len(full["STE"])), 2.0 * n, 0.0,
          f"{P_GEO} pitches x {N_GEO} positions on each route")
    if len(hunt["STE"]) != n or len(full["STE"]) != n or len(nominal["STE"]) != N_GEO:
        return
    # The mapping, explicitly: full-FE position i (Solve: n positions over P_GEO pitches from A) is
    # hunting position j N + k (pitch j, stored position k), at roll angle phi_k + j 360/z1.
    i = np.arange(n)
    j, k = i // N_GEO, i % N_GEO
    expected_roll = nominal["roll angle"][k] + j * 360.0 / Z1
    c.abs("hunting cycle: position index j N + k", float(np.max(np.abs(hunt["position"] - i))), 0.0, 0.0,
          "docs/deviations.md, the hunting cycle's outputs")
    c.abs("roll angles: hunting (phi_k + j 360/z1) and full FE against the mapping, worst",
          float(max(np.max(np.abs(hunt["roll angle"] - expected_roll)), np.max(np.abs(full["roll angle"] - expected_roll)))),
          0.0, 1e-6, "positions of one pitch repeated pitch after pitch (CSV precision)", " deg")
    # The same physical teeth carry the load on both routes: the hunting cycle's relabelling (pinion
    # tooth s - j, gear tooth s + j in the slot of stored tooth s) against the body-frame teeth of
    # the full FE, whose pinion has really turned by j pitches.
    differ = [int(p) for p in i if loaded_pairs(hunt_pairs, p) != loaded_pairs(full_pairs, p)]
    c.abs("positions where the loaded tooth pairs differ between the routes", float(len(differ)), 0.0, 0.0,
          "the hunting relabelling against the full FE's physical teeth" + (f" (first: {differ[:5]})" if differ else ""))
    # Relabelled back to the one-pitch cycle (pinion t + j, gear t - j), the full FE's loaded teeth
    # are teeth the nominal cycle has in mesh over its pitch.
    nominal_pairs = read(os.path.join(geo, "nominal", "pairs.csv"))
    slots = (set(nominal_pairs["pinion tooth"].astype(int) % Z1), set(nominal_pairs["gear tooth"].astype(int) % Z2))
    back = [(pt + jj) % Z1 in slots[0] and (gt - jj) % Z2 in slots[1]
            for p, jj in zip(i, j) for pt, gt in loaded_pairs(full_pairs, int(p))]
    c.true("full FE at pitch j: pinion tooth s - j and gear tooth s + j where the one-pitch cycle has tooth s",
           bool(back) and all(back), f"{sum(back)} of {len(back)} loaded pairs",
           f"all (stored pinion teeth {sorted(slots[0])}, gear teeth {sorted(slots[1])})",
           "the hunting cycle's relabelling, docs/deviations.md")
    # STE: relative to the local STE, the stricter measure here (the local STE of the deviated pair
    # drops well below its mean where the teeth set forward of the datum carry the load).
    d = full["STE"] - hunt["STE"]
    rel = np.abs(d) / np.abs(hunt["STE"])
    worst = int(np.argmax(rel))
    c.at_most(f"STE, full FE with turned teeth against the condensed route, {n} positions: worst |difference| / local "
              f"STE (position {worst}: pitch {worst // N_GEO}, {float(d[worst]):+.4f} um of {float(hunt['STE'][worst]):.3f} um)",
              float(100 * rel[worst]), 0.2, "the same pitch deviations as drive advances (kinematically exact for a "
              "rigid tooth turn); tolerance 0.2 % of the local STE", " %")
    effect = np.abs(hunt["STE"] - np.tile(nominal["STE"], P_GEO))
    c.at_least("the deviations move the STE (condensed route against the nominal pair), largest", float(np.max(effect)),
               1.0, "a comparison that ignored the turned teeth would fail by this much (>= 50x the tolerance)", " um")
    c.info("largest |STE difference|; relative to the mean STE", f"{float(np.max(np.abs(d))):.4f} um; "
           f"{float(100 * np.max(np.abs(d)) / np.mean(hunt['STE'])):.3f} %", "", "full FE with turned teeth - condensed")
    fallback = []
    for name in ("mesh.log", "geometry.log"):
        with open(os.path.join(geo, name)) as f:
            if "subdivision fallback" in f.read():
                fallback.append(name)
    c.info("gmsh subdivision fallback (nominal mesh.log, turned geometry.log)", ", ".join(fallback) or "none",
           "none", "a fallback mesh on one route only raised the worst difference to 0.25 % (measured)")
    times = []
    for name in ("condensed_seconds.txt", "geometry_seconds.txt"):
        with open(os.path.join(geo, name)) as f:
            times.append(f.read().strip())
    c.info("wall time: condensed route (condense + nominal + hunting); full FE with turned teeth",
           f"{times[0]} s; {times[1]} s", "", f"{n} positions")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--out", required=True)
    out = ap.parse_args().out
    c = Checks("manufacturing_deviations", out)
    base = read(os.path.join(out, "base", "sweep.csv"))["STE"]
    tiled = np.tile(base, Z1)

    # Flank offsets: a common offset is a rigid turn of the gear.
    s = read(os.path.join(out, "offset", "sweep.csv"))["STE"]
    c.abs("flank offsets +3 um (pinion), -2 um (gear): STE shift, worst position", float(np.max(np.abs(s - base + 1))),
          0.0, 1e-6, "kinematics: an involute moved along its normal by d is the same involute turned by d/r_b", " um")

    # Runout of the pinion: once-per-revolution TE of amplitude e = F_r/2 and sidebands.
    r = read(os.path.join(out, "runout", "sweep.csv"))["STE"]
    d = r - tiled
    n = len(d)
    phi = 2 * math.pi * np.arange(n) / (Z1 * M)
    A = np.column_stack([np.ones(n), np.cos(phi), np.sin(phi)])
    coef, *_ = np.linalg.lstsq(A, d, rcond=None)
    amp = math.hypot(coef[1], coef[2])
    res = float(np.sqrt(np.mean((d - A @ coef) ** 2)))
    c.rel("pinion runout F_r 10 um: once-per-revolution STE amplitude", amp, 5.0, 0.01,
          "closed form: projection of the rotating eccentricity e = F_r/2 on the line of action (docs/deviations.md)",
          " um")
    c.at_most("runout: residual of the once-per-revolution fit", res, 0.05, "the same closed form (1 % of e)", " um")
    orders, a_run = spectrum(r, Z1 * M)
    _, a_base = spectrum(tiled, Z1 * M)
    for o in (Z1 - 1, Z1 + 1):
        k = int(round(o * n / (Z1 * M)))
        c.at_least(f"runout under load: sideband at order {o} (against {a_base[k]:.2g} um without runout)",
                   float(a_run[k]), 10 * a_base[k] + 1e-4, "amplitude modulation of the mesh order by the runout",
                   " um")

    # One pinion tooth (5) advanced by 25 and 35 um, set back by 25 um.
    s25, p25 = read(os.path.join(out, "tooth25", "sweep.csv")), read(os.path.join(out, "tooth25", "pairs.csv"))
    s35, p35 = read(os.path.join(out, "tooth35", "sweep.csv")), read(os.path.join(out, "tooth35", "pairs.csv"))

    def alone(p, tooth):
        g = p["position"].astype(int)
        return [k for k in np.unique(g) if np.all(p["pinion tooth"][g == k] == tooth)]

    both = sorted(set(alone(p25, 5)) & set(alone(p35, 5)))
    shift = -10 * (1 - 1 / Z1) * math.cos(ALPHA)
    err = float(np.max(np.abs(s35["STE"][both] - s25["STE"][both] - shift))) if both else float("nan")
    c.abs(f"tooth 5 advanced 25 -> 35 um, where it meshes alone ({len(both)} positions): STE shift error", err, 0.0,
          1e-6, "kinematics: -delta (1 - 1/z1) cos(alpha) (datum: the teeth's mean position)", " um")
    pitches = sorted({int(k) // M for k in alone(p25, 5)})
    expected = {j for j in range(Z1) for s_ in (-1, 0, 1) if (s_ - j) % Z1 == 5}
    c.true("the advanced tooth carries the whole load only at the pitches where it is in mesh",
           bool(pitches) and set(pitches) <= expected, str(pitches), str(sorted(expected)),
           "tooth s - j occupies the slot of stored tooth s at pitch j")
    # Set back by 25 um (more than the loaded deflection, about 8 um): the pair unloads. On this
    # pair the neighbours then carry the load through their extended (tip-corner) contact, so
    # the STE where tooth 5 would mesh rises, by at most its setback.
    sb, pb = read(os.path.join(out, "toothback", "sweep.csv")), read(os.path.join(out, "toothback", "pairs.csv"))
    loaded = int(np.count_nonzero((pb["pinion tooth"] == 5) & (pb["load share"] > 1e-9)))
    c.abs("tooth 5 set back 25 um: positions where it carries load", float(loaded), 0.0, 0.0,
          "a setback larger than the loaded deflection unloads the pair")
    where = sorted({int(k) for k in p25["position"][p25["pinion tooth"] == 5]})
    rise = sb["STE"][where] - tiled[where]
    setback = 25 * (1 - 1 / Z1) * math.cos(ALPHA)
    c.within(f"STE rise where tooth 5 meshes without the setback ({len(where)} positions), largest",
             float(np.max(rise)), 0.0, setback + 1e-6, "0 < rise <= delta (1 - 1/z1) cos(alpha): the other pairs "
             "take over", " um")
    # The datum is the teeth's mean position: setting tooth 5 back by delta puts every other tooth
    # delta/z1 forward, so where they carry the load alone the STE drops by that much.
    c.at_least("STE rise there, smallest", float(np.min(rise)), -25 / Z1 * math.cos(ALPHA) - 1e-6,
               "-delta/z1 cos(alpha): the other teeth moved forward by the datum", " um")

    geometry_checks(c, os.path.join(out, "geometry"))

    # Monte Carlo: 1000 samples at grade 6.
    mc = read(os.path.join(out, "mc", "samples.csv"))
    tol = iso1328(6, 3.0, 150.0)
    failed = 0
    for name in os.listdir(os.path.join(out, "mc")):
        if name.startswith("failed.rank"):
            with open(os.path.join(out, "mc", name)) as f:
                failed += sum(1 for line in f if line.strip())
    c.abs("samples complete or recorded as failed", float(len(mc["sample"]) + failed), 1000.0, 0.0, "Tolerance/Samples")
    c.at_most("samples the condensed cycle cannot serve (recorded, not in the statistics)", float(failed), 10.0,
              "1 % of the samples: a corner candidate loaded far from its build state is refused, never solved wrongly")
    for g, key in ((1, "pinion"), (2, "gear")):
        c.at_most(f"max |f_pt| over all samples, {key}", float(np.max(mc[f"max |f_pt| {key}"])), tol["f_pT"],
                  "ISO 1328-1:2013 f_pT, grade 6, m 3, d 150 (computed here)", " um")
        c.at_most(f"span of F_p over all samples, {key}", float(np.max(mc[f"F_p span {key}"])), tol["F_pT"] + 1e-9,
                  "ISO 1328-1:2013 F_pT", " um")
        Fr = mc[f"F_r {key}"]
        c.at_most(f"F_r over all samples, {key}", float(np.max(Fr)), tol["F_rT"] + 1e-9, "ISO 1328-1:2013 F_rT = 0.9 F_pT",
                  " um")
        se = float(np.std(Fr, ddof=1) / math.sqrt(len(Fr)))
        c.abs(f"mean F_r / F_rT, {key} (uniform draw: 1/2; standard error {se / tol['F_rT']:.3f})",
              float(np.mean(Fr)) / tol["F_rT"], 0.5, 3.5 * se / tol["F_rT"], "mean of |U(-1, 1)|")
    # Statistics converge as 1/sqrt(N): the standard error of the mean p-p STE over the first
    # 250 samples against all 1000.
    pp = mc["p-p STE"]
    se250 = float(np.std(pp[:250], ddof=1) / math.sqrt(250))
    se1000 = float(np.std(pp, ddof=1) / math.sqrt(1000))
    c.within("standard error of the mean p-p STE, 250 / 1000 samples", se250 / se1000, 1.6, 2.4,
             "1/sqrt(N): 2")
    c.abs("mean p-p STE, 250 against 1000 samples", float(np.mean(pp[:250])), float(np.mean(pp)), 3 * se250,
          "within 3 standard errors", " um")
    with open(os.path.join(out, "mc_seconds.txt")) as f:
        seconds = float(f.read())
    with open(os.path.join(out, "mc_resume.log")) as f:
        resumed = "before; 0 to solve" in f.read()  # the whole study: nothing left for any rank
    c.true("a second run of the study resumes with every sample done", resumed, str(resumed), "True",
           "journals samples.rank*.csv")
    c.info("Monte Carlo wall time, 1000 samples x 2000 positions, np 2", f"{seconds:.0f} s", "<= 600 s",
           "the cycle (built separately) not included")
    p = np.percentile(pp, [5, 50, 95])
    c.info("p-p STE percentiles 5/50/95 %", f"{p[0]:.2f} / {p[1]:.2f} / {p[2]:.2f} um", "", "grade 6, 200 N m")
    sys.exit(c.finish())


if __name__ == "__main__":
    main()
