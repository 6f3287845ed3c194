#!/usr/bin/python3
"""The 3-D FE model of the face against its plane limits, its nu = 0 identity, equilibrium, the
beam of the slicing on a misaligned spur face and on the helical demo, and its cost (README.md).

Usage: check.py --out <results dir> [--table table.md] [--plot three_d.png]
The references are the plane-stress and plane-strain sections of the same pair (gearfem's
exact 2-D FE, uncoupled slices), the exact nu = 0 identity, and the torque balance."""
import argparse
import csv
import json
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "lib"))
from vcheck import Checks, save_figure, write_if_changed  # noqa: E402

PLANE = "2-D sections of the same pair, uncoupled (gearfem's exact 2-D contact FE)"


def load(out, name):
    d = os.path.join(out, name)
    with open(os.path.join(d, "helical.json")) as f:
        j = json.load(f)
    with open(os.path.join(d, "helical.csv")) as f:
        rows = list(csv.DictReader(f))
    with open(os.path.join(d, "slices.csv")) as f:
        sl = list(csv.DictReader(f))
    mem = None
    tf = os.path.join(out, name + ".time")
    if os.path.exists(tf):
        for line in open(tf):
            if "Maximum resident set size" in line:
                mem = float(line.split(":")[1]) / 1024 ** 2  # GB
    return dict(json=j, rows=rows, slices=sl, t=j["torques"][0], mem=mem)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--out", required=True)
    ap.add_argument("--table")
    ap.add_argument("--plot")
    a = ap.parse_args()
    c = Checks("three_d", a.out)
    r = {n: load(a.out, n) for n in ["b1.5_3d", "b1.5_ps", "b1.5_pe", "b30_3d", "b30_ps", "b30_pe", "nu0_3d",
                                     "nu0_2d", "mis10_3d", "mis10_beam", "mis25_3d", "mis25_beam", "demo_3d",
                                     "demo_beam"]}
    md = ["| case | model | mean STE [um] | p-p STE [um] | K_Hbeta | root stress pinion [MPa] |", "|---|---|---|---|---|---|"]
    for n, v in r.items():
        t = v["t"]
        md.append(f"| {n} | {v['json']['model']} | {t['ste_mean_um']:.4f} | {t['ste_pp_um']:.4f} | "
                  f"{t['k_h_beta']:.4f} | {t['root_stress_pinion_MPa']:.2f} |")

    # Plane limits: the fraction of the way from plane stress to plane strain.
    frac = {}
    for b in ("1.5", "30"):
        s3, ps, pe = (r[f"b{b}_{m}"]["t"]["ste_mean_um"] for m in ("3d", "ps", "pe"))
        frac[b] = (ps - s3) / (ps - pe)
        c.within(f"b = {b} mm: mean STE between plane stress ({ps:.4f}) and plane strain ({pe:.4f}) um",
                 s3, min(ps, pe), max(ps, pe), PLANE, " um")
    c.rel("b = m/2: mean STE against plane stress", r["b1.5_3d"]["t"]["ste_mean_um"], r["b1.5_ps"]["t"]["ste_mean_um"],
          0.01, "plane-stress limit of a thin face (sigma_zz -> 0)")
    c.rel("b = m/2: largest root stress against plane stress", r["b1.5_3d"]["t"]["root_stress_pinion_MPa"],
          r["b1.5_ps"]["t"]["root_stress_pinion_MPa"], 0.02, "plane-stress limit of a thin face")
    c.at_most("b = m/2: fraction of the way to plane strain", frac["1.5"], 0.1, "plane-stress limit")
    c.at_least("b = 10 m: fraction of the way to plane strain", frac["30"], 0.4,
               "generalized plane strain in the middle of a wide face")
    # Face ends: the aligned wide face carries less at its free ends than in its middle.
    sl = [x for x in r["b30_3d"]["slices"] if x["position"] == "0"]
    w = [float(x["load_N_per_mm"]) for x in sl]
    c.info("b = 10 m: end / middle load per width (position 0)", w[0] / w[len(w) // 2], 1.0,
           "the softer free ends (the face-end stiffness drop)")
    # nu = 0: the identity.
    d = max(abs(float(x["ste_um"]) / float(y["ste_um"]) - 1) for x, y in zip(r["nu0_3d"]["rows"], r["nu0_2d"]["rows"]))
    c.at_most("nu = 0: max |STE 3-D / sections - 1| over the positions", d, 1e-6,
              "exact: no Poisson coupling across the face, equal slice loads")
    # Equilibrium of the demo in 3-D: sum of slice forces = T1 / r_b1.
    j = r["demo_3d"]["json"]
    rb1 = 0.5 * 50 * j["transverse_module_mm"] * 1e-3 * math.cos(math.radians(j["transverse_pressure_angle_deg"]))
    worst = 0
    for p in {x["position"] for x in r["demo_3d"]["slices"]}:
        F = sum(float(x["force_N"]) for x in r["demo_3d"]["slices"] if x["position"] == p)
        worst = max(worst, abs(F * rb1 / 200 - 1))
    c.at_most("demo 3-D: max |sum of slice forces r_b1 / T1 - 1|", worst, 1e-6, "equilibrium")
    # The beam of the slicing against 3-D (reported: the fit of the beam is not done).
    for n in ("mis10", "mis25", "demo"):
        t3, tb = r[f"{n}_3d"]["t"], r[f"{n}_beam"]["t"]
        for k, lab in (("k_h_beta", "K_Hbeta"), ("ste_pp_um", "p-p STE"), ("ste_mean_um", "mean STE"),
                       ("root_stress_pinion_MPa", "root stress")):
            c.info(f"{n}: {lab}, beam (l = m_n) against 3-D", tb[k], t3[k],
                   f"beam error {(tb[k] / t3[k] - 1) * 100:+.1f} %")
    # Cost (the demo: 21 slices, 40 positions, two 3-D bodies).
    c.at_most("demo: 3-D set-up (both bodies and their tables)", j["face_setup_seconds"], 600, "requirement", " s")
    per = j["sweep_seconds"] / j["solved"]
    c.at_most("demo: one position on the stored cycle", per * 1e3, 20, "requirement", " ms")
    first = float(r["demo_3d"]["rows"][0]["seconds"])
    c.at_most("demo: the first position after set-up", first, 5, "requirement", " s")
    c.at_most("demo: peak memory", r["demo_3d"]["mem"], 12, "requirement", " GB")
    c.info("demo: 3-D DoFs (both bodies)", j["face_dofs"], 0, "")
    md += ["", f"Fraction of the way from plane stress to plane strain: b = m/2 {frac['1.5']:.3f}, "
           f"b = 10 m {frac['30']:.3f}."]
    if a.table:
        write_if_changed(a.table, "\n".join(md) + "\n")
    if a.plot:
        plot(r, a.plot)
    return c.finish()


def plot(r, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(1, 2, figsize=(10, 3.8))
    for n, lab in (("mis25_3d", "3-D FE"), ("mis25_beam", "beam l = m_n")):
        sl = [x for x in r[n]["slices"] if x["position"] == "0"]
        ax[0].plot([float(x["z_mm"]) for x in sl], [float(x["load_N_per_mm"]) for x in sl], "o-", label=lab)
    ax[0].set_xlabel("z [mm]")
    ax[0].set_ylabel("load per width [N/mm]")
    ax[0].set_title("spur, f_Sigma_beta 25 um, position 0")
    ax[0].legend()
    for n, lab in (("demo_3d", "3-D FE"), ("demo_beam", "beam l = m_n")):
        rows = r[n]["rows"]
        ax[1].plot([float(x["phi1_deg"]) for x in rows], [float(x["ste_um"]) for x in rows], "-", label=lab)
    ax[1].set_xlabel("roll angle [deg]")
    ax[1].set_ylabel("STE [um]")
    ax[1].set_title("helical demo, beta 20 deg")
    ax[1].legend()
    save_figure(fig, path, dpi=110)


if __name__ == "__main__":
    sys.exit(main())
