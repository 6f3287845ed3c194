#!/usr/bin/python3
"""Runs the CalculiX peer comparison of the planet-ring pair (README.md): gearfem mesh and
gearfem solve on the case, then ccx at the same positions with gearfem's pinion rotations
prescribed (matched rotation, one ccx *STEP per torque); writes results/geometry.json,
results/ccx_sweep.csv, results/ccx_pairs.csv and results/timing.csv. Wall and CPU times of
both programs are measured here, in one run.

The mesh reader, CPS8 conversion, surface writer and result readers are those of
validation/calculix_peer/ccx_model.py (imported); the internal pair's geometry and placement,
the sector supports and the contact pairs of the conformal mesh are set up here.

Usage: run_peer.py --gearfem build/app/gearfem --prm inputs/internal_ccx.prm --out results
                   [--kappas 30] [--kappa-positions 3:0,4] [--jobs 2] [--ccx ccx] [--reuse]
"""
import argparse
import json
import math
import os
import sys
import time
from concurrent.futures import ThreadPoolExecutor, as_completed

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "calculix_peer"))
sys.path.insert(0, os.path.join(HERE, "..", "lib"))
import ccx_model as cm  # noqa: E402
from vcheck import read_csv  # noqa: E402

CASE = "calculix_internal"
DRIVE_FLANK, FILLET_DRIVE, TIP, TIP_ROUND_DRIVE = 1, 3, 5, 6
BORE, CUT_CW, CUT_CCW = 1, 2, 3
SUPPORT = (BORE, CUT_CW, CUT_CCW)  # the supported boundary of a sector: bore / outer arc and both cuts


# --------------------------------------------------------------------------- geometry
def inv(a):
    return math.tan(a) - a


def inv_inverse(v):
    lo, hi = 1e-9, 1.5
    for _ in range(200):
        mid = (lo + hi) / 2
        lo, hi = (mid, hi) if inv(mid) < v else (lo, mid)
    return (lo + hi) / 2


def internal_pair_geometry(z1, z2, m, x1, x2, alpha_deg=20.0, ha=1.0, k1=0.0, k2=0.0):
    """Zero-backlash pinion-in-ring pair from the involute formulas (ISO 21771 sign of x2:
    x2 > 0 thickens the ring teeth). Pair frame as in docs/internal-gears.md: pinion at the
    origin turned by phase1 + phi1, ring centre (0, -a) turned by phase2 + phi1 z1/z2 [mm, rad].
    The path of contact runs from A (the ring's tip circle) to E (the pinion's tip circle);
    B = E - p_b and D = A + p_b; roll angles of the pinion from C [deg]."""
    al = math.radians(alpha_deg)
    r1, r2 = m * z1 / 2, m * z2 / 2
    rb1, rb2 = r1 * math.cos(al), r2 * math.cos(al)
    s1 = m * (math.pi / 2 + 2 * x1 * math.tan(al))  # pinion tooth, ring tooth on the reference circles
    s2 = m * (math.pi / 2 + 2 * x2 * math.tan(al))
    aw = inv_inverse(inv(al) - 2 * math.tan(al) * (x1 + x2) / (z2 - z1))
    a = (rb2 - rb1) / math.cos(aw)
    rw1, rw2 = rb1 / math.cos(aw), rb2 / math.cos(aw)
    # arc tooth thicknesses on the working pitch circles: the pinion's thins outwards, the ring's thickens
    sw1 = 2 * rw1 * (s1 / (2 * r1) + inv(al) - inv(aw))
    sw2 = 2 * rw2 * (s2 / (2 * r2) - inv(al) + inv(aw))
    pw = 2 * math.pi * rw1 / z1
    ra1 = r1 + (ha + x1 - k1) * m               # pinion tip circle
    ra2 = r2 - (ha + x2 - k2) * m               # ring tip (inner) circle
    pb = 2 * math.pi * rb1 / z1
    xi_c = rb1 * math.tan(aw)                   # C from the pinion's tangency point T1
    xi_a = math.sqrt(ra2 ** 2 - rb2 ** 2) - a * math.sin(aw)
    xi_e = math.sqrt(ra1 ** 2 - rb1 ** 2)
    deg = lambda xi: math.degrees((xi - xi_c) / rb1)
    return dict(z1=z1, z2=z2, m=m, x1=x1, x2=x2, alpha_w=aw, alpha_w_deg=math.degrees(aw), a=a, rb1=rb1, rb2=rb2,
                rw1=rw1, rw2=rw2, sw1=sw1, sw2=sw2, backlash_arc=pw - sw1 - sw2, ra1=ra1, ra2=ra2, pb=pb,
                phase1=-sw1 / (2 * rw1), phase2=sw2 / (2 * rw2),
                eps_alpha=(xi_e - xi_a) / pb, pitch_deg=360.0 / z1,
                roll=dict(A=deg(xi_a), B=deg(xi_e - pb), C=0.0, D=deg(xi_a + pb), E=deg(xi_e)))


def placements(g, phi1_deg):
    """(centre, angle) of pinion and ring at pinion roll angle phi1 [deg]."""
    phi1 = math.radians(phi1_deg)
    return ((0.0, 0.0), g["phase1"] + phi1), ((0.0, -g["a"]), g["phase2"] + phi1 * g["z1"] / g["z2"])


# --------------------------------------------------------------------------- contact pairs
def nodes_of(body, tags):
    s = []
    for t in tags:
        s += body.group_nodes(t)
    return sorted(set(s))


def tooth_pairs(g, b1, b2, x1, x2, fine1, fine2, reach):
    """Tooth pairs (pinion tooth k, ring tooth k) of the fine teeth whose drive flank / tip
    outlines come within `reach` mm without load: the unloaded gap [mm] (nodes of either
    outline to the other's polyline), its point (pair frame) and the distance of that point
    from each tip circle [mm]."""
    out = []
    O2 = np.array([0.0, -g["a"]])
    for i in fine1:
        j = (i if i <= g["z1"] // 2 else i - g["z1"]) % g["z2"]  # pinion tooth k meshes ring tooth k (signed)
        if j not in fine2:
            continue
        t1 = [cm.tooth_tag(i, s) for s in (DRIVE_FLANK, TIP_ROUND_DRIVE, TIP)]
        t2 = [cm.tooth_tag(j, s) for s in (DRIVE_FLANK, TIP_ROUND_DRIVE, TIP)]
        p1, p2 = x1[nodes_of(b1, t1)], x2[nodes_of(b2, t2)]
        d1 = cm.point_segment_distance(p1, cm._polyline(b2, x2, t2))
        d2 = cm.point_segment_distance(p2, cm._polyline(b1, x1, t1))
        k1, k2 = int(np.argmin(d1)), int(np.argmin(d2))
        gap = float(min(d1[k1], d2[k2]))
        close = p1[k1] if d1[k1] <= d2[k2] else p2[k2]
        if gap < reach:
            out.append(dict(pinion_tooth=i, gear_tooth=j, gap_mm=gap, close=close,
                            tip1=g["ra1"] - float(np.linalg.norm(close)),
                            tip2=float(np.linalg.norm(close - O2)) - g["ra2"]))
    return out


# --------------------------------------------------------------------------- deck
def write_deck(path, g, b1, b2, phi1_deg, rotations_urad, slope, thickness, E, nu, fine1, fine2,
               band=(2.5, 3.5), reach=0.05, slab=1e-3):
    """The ccx input of the internal pair at one position: one *STEP per pinion rotation
    [urad]. CPS8 in a slab of slab x thickness (plane stress; calculix_peer/README.md), every
    force and moment read back scaled by 1/slab. The ring's outer arc and its cut edges are
    clamped; the pinion's bore and cut edges turn rigidly about O1. One surface-to-surface
    penalty pair per tooth pair of the fine teeth within `reach` mm without load (the
    loaded pairs and the conformal neighbours that close under load): slave faces within
    band[0], master faces within band[1] mm of the pair's closest unloaded approach; the slave
    is the body whose tip circle is nearer that point; the master surface has the mate's
    drive fillet as well."""
    (c1, a1), (c2, a2) = placements(g, phi1_deg)
    x1 = cm.placed(b1, c1, a1)
    x2 = cm.placed(b2, c2, a2)
    off2, eoff2 = len(x1), len(b1.elems)
    pairs = tooth_pairs(g, b1, b2, x1, x2, fine1, fine2, reach)
    L = []
    w = L.append
    w("*HEADING\ngearfem calculix_internal: planet z %d in ring z %d, roll angle %.4f deg (mm, N, MPa)"
      % (g["z1"], g["z2"], phi1_deg))
    cm.deck_bodies(w, b1, b2, x1, x2, E, nu, thickness * slab)

    def nset(name, ids):
        cm.deck_nset(w, name, ids)

    sup1 = [v + 1 for v in nodes_of(b1, SUPPORT)]
    sup2 = [off2 + v + 1 for v in nodes_of(b2, SUPPORT)]
    nset("BORE1", sup1)
    nset("BORE2", sup2)
    fil1 = {i: [v + 1 for v in b1.group_nodes(cm.tooth_tag(i, FILLET_DRIVE))] for i in fine1}
    fil2 = {j: [off2 + v + 1 for v in b2.group_nodes(cm.tooth_tag(j, FILLET_DRIVE))] for j in fine2}
    nset("FILLETS", sorted({v for s in list(fil1.values()) + list(fil2.values()) for v in s}))

    def surface(name, body, xb, eo, tags, centre, radius):
        cm.deck_surface(w, name, body, xb, eo, tags, centre, radius)

    w("*SURFACE INTERACTION, NAME=SI\n*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR\n%.6g" % slope)
    contact = []
    for q in pairs:
        i, j, close = q["pinion_tooth"], q["gear_tooth"], q["close"]
        s1 = [cm.tooth_tag(i, s) for s in (DRIVE_FLANK, TIP_ROUND_DRIVE, TIP)]
        s2 = [cm.tooth_tag(j, s) for s in (DRIVE_FLANK, TIP_ROUND_DRIVE, TIP)]
        m1, m2 = s1 + [cm.tooth_tag(i, FILLET_DRIVE)], s2 + [cm.tooth_tag(j, FILLET_DRIVE)]
        pin_slave = q["tip1"] <= q["tip2"]  # the pinion's tip is nearer the contact
        sl, ms = f"P{i}_{j}_S", f"P{i}_{j}_M"
        if pin_slave:
            surface(sl, b1, x1, 0, s1, close, band[0])
            surface(ms, b2, x2, eoff2, m2, close, band[1])
        else:
            surface(sl, b2, x2, eoff2, s2, close, band[0])
            surface(ms, b1, x1, 0, m1, close, band[1])
        w(f"*CONTACT PAIR, INTERACTION=SI, TYPE=SURFACE TO SURFACE\n{sl}, {ms}")
        contact.append(dict(pinion_tooth=i, gear_tooth=j, gap_mm=q["gap_mm"], slave=1 if pin_slave else 2,
                            slave_name=sl, master_name=ms, close=[float(v) for v in close]))
    w("*BOUNDARY\nBORE2, 1, 2, 0.")
    for urad in rotations_urad:
        dth = urad * 1e-6
        w("*STEP, INC=200\n*STATIC\n1., 1., 1e-5, 1.")
        w("*BOUNDARY")
        for v in sup1:
            x, y = x1[v - 1]
            w(f"{v}, 1, 1, {-dth * y:.12g}")
            w(f"{v}, 2, 2, {dth * x:.12g}")
        w("*NODE PRINT, NSET=BORE1\nRF\n*NODE PRINT, NSET=BORE2\nRF")
        for c in contact:
            w(f"*CONTACT PRINT, SLAVE={c['slave_name']}, MASTER={c['master_name']}\nCF")
        w("*EL FILE, NSET=FILLETS\nS\n*END STEP")
    tmp = path + ".tmp"
    with open(tmp, "w") as f:
        f.write("\n".join(L) + "\n")
    os.replace(tmp, path)
    return dict(contact=contact, x1=x1, x2=x2, off2=off2, fillets1=fil1, fillets2=fil2, O2=np.array(c2),
                force_scale=1.0 / slab)


def read_frd_stress(path):
    """Nodal stresses of the last result block at each distinct time of a ccx ASCII .frd (one
    per step; ccx ends some steps with a second, zero-size increment at the same time):
    list of {node: (sxx, syy, szz, sxy, syz, szx)}. The block parsing is ccx_model's."""
    blocks, cur, t_now = {}, None, None
    with open(path) as f:
        for line in f:
            if line.startswith("  100CL"):
                t_now = float(line[12:24])
                continue
            if line.startswith(" -4  STRESS"):
                cur = {}
                blocks[t_now] = cur
                continue
            if cur is not None:
                if line.startswith(" -3"):
                    cur = None
                elif line.startswith(" -1"):
                    cur[int(line[3:13])] = [float(line[13 + 12 * k:25 + 12 * k]) for k in range(6)]
    return [blocks[t] for t in sorted(blocks)]


# --------------------------------------------------------------------------- runs

def prm_values(path):
    """`set key = value` entries of a parameter file by subsection path ("Gear 1/Number of teeth")."""
    vals, stack = {}, []
    with open(path) as f:
        for line in f:
            s = line.split("#")[0].strip()
            if s.startswith("subsection "):
                stack.append(s[len("subsection "):].strip())
            elif s == "end":
                stack.pop()
            elif s.startswith("set "):
                k, v = s[4:].split("=", 1)
                vals["/".join(stack + [k.strip()])] = v.strip()
    return vals



def fine_teeth(text, z):
    return sorted({int(v) % z for v in text.split(",")})


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--gearfem", required=True)
    ap.add_argument("--prm", required=True)
    ap.add_argument("--out", required=True)
    ap.add_argument("--ccx", default="ccx")
    ap.add_argument("--kappas", default="30",
                    help="ccx penalty factors kappa: slope K = kappa E / h_contact [N/mm^3]")
    ap.add_argument("--kappa-positions", default="",
                    help="kappa:comma-separated position indices, to run a kappa at a subset only")
    ap.add_argument("--jobs", type=int, default=2,
                    help="ccx runs side by side (each single-threaded; timed apart by their own CPU time)")
    ap.add_argument("--reuse", action="store_true",
                    help="development only: reuse finished ccx runs (their recorded times) and gearfem's run")
    a = ap.parse_args()
    out = os.path.abspath(a.out)
    os.makedirs(out, exist_ok=True)

    # ---- gearfem: mesh (the bodies for ccx) and the solve (the timed reference run)
    if a.reuse and os.path.exists(f"{out}/gearfem/time"):
        g_wall, g_cpu = map(float, open(f"{out}/gearfem/time").read().split())
    else:
        print("== gearfem mesh (the meshes that gearfem solve builds)", flush=True)
        cm.timed([a.gearfem, "mesh", a.prm, "--output-dir", f"{out}/mesh"], f"{out}/gearfem_mesh.log", case=CASE)
        print("== gearfem solve", flush=True)
        g_wall, g_cpu = cm.timed([a.gearfem, "solve", a.prm, "--output-dir", f"{out}/gearfem"],
                              f"{out}/gearfem_solve.log", case=CASE)
        with open(f"{out}/gearfem/time", "w") as f:
            f.write(f"{g_wall} {g_cpu}\n")
    print(f"   gearfem solve: wall {g_wall:.1f} s, CPU {g_cpu:.1f} s", flush=True)
    sweep = read_csv(f"{out}/gearfem/sweep.csv")
    torques = sorted({r["torque"] for r in sweep})
    positions = sorted({int(r["position"]) for r in sweep})
    roll = {int(r["position"]): r["roll angle"] for r in sweep}
    dth = {(r["torque"], int(r["position"])): r["STE angle"] for r in sweep}

    # ---- the pair, recomputed from the involute formulas
    P = prm_values(a.prm)
    if P.get("Pair/Type") != "internal":
        sys.exit(f"{CASE}: FAIL ({a.prm}: Pair/Type is not internal)")
    g = internal_pair_geometry(int(P["Gear 1/Number of teeth"]), int(P["Gear 2/Number of teeth"]),
                               float(P["Rack/Module"]), float(P["Gear 1/Profile shift coefficient"]),
                               float(P["Gear 2/Profile shift coefficient"]), float(P.get("Rack/Pressure angle", 20)),
                               float(P.get("Rack/Addendum coefficient", 1.0)))
    h_contact = float(P["Mesh/h_contact"])
    E = float(P.get("Material/Young's modulus", 207)) * 1e3  # GPa -> MPa
    nu = float(P.get("Material/Poisson ratio", 0.3))
    b = float(P["Gear 1/Face width"])
    fine1 = fine_teeth(P["Mesh/Gear 1/Fine teeth"], g["z1"])
    fine2 = fine_teeth(P["Mesh/Gear 2/Fine teeth"], g["z2"])
    b1, b2 = cm.Body(f"{out}/mesh/gear1.msh"), cm.Body(f"{out}/mesh/gear2.msh")
    print(f"   ccx bodies: {len(b1.elems)} + {len(b2.elems)} CPS8, {len(b1.xy)} + {len(b2.xy)} nodes", flush=True)

    # the unloaded gaps of the tooth pairs at every position (no ccx needed): the placement check
    gaps = []
    for p in positions:
        (c1, a1), (c2, a2) = placements(g, roll[p])
        x1, x2 = cm.placed(b1, c1, a1), cm.placed(b2, c2, a2)
        for q in tooth_pairs(g, b1, b2, x1, x2, fine1, fine2, reach=1.0):
            k = q["pinion_tooth"] if q["pinion_tooth"] <= g["z1"] // 2 else q["pinion_tooth"] - g["z1"]
            gaps.append(dict(position=p, roll_deg=roll[p], pinion_tooth=q["pinion_tooth"], gear_tooth=q["gear_tooth"],
                             path_roll_deg=roll[p] + k * g["pitch_deg"], unloaded_gap_um=q["gap_mm"] * 1e3,
                             radius_pinion_mm=float(np.linalg.norm(q["close"]))))
    cm.write_csv(f"{out}/unloaded_gaps.csv", gaps)
    geo = {k: v for k, v in g.items()}
    geo.update(E_MPa=E, nu=nu, face_width_mm=b, h_contact_mm=h_contact, fine1=fine1, fine2=fine2,
               cells=[len(b1.elems), len(b2.elems)], nodes_cps8=[len(b1.xy), len(b2.xy)])
    with open(f"{out}/geometry.json", "w") as f:
        json.dump(geo, f, indent=1)
    print(f"   pair: a {g['a']:.6f} mm, alpha_w {g['alpha_w_deg']:.4f} deg, eps_alpha {g['eps_alpha']:.4f}; "
          "roll A/B/C/D/E " + ", ".join(f"{k} {v:+.4f}" for k, v in g["roll"].items()) + " deg", flush=True)

    kappas = [float(k) for k in a.kappas.split(",")]
    subset = {}
    if a.kappa_positions:
        k, idx = a.kappa_positions.split(":")
        subset[float(k)] = [int(i) for i in idx.split(",")]
    jobs = [(k, p) for p in positions for k in kappas if p in subset.get(k, positions)]
    jobs.sort(key=lambda kp: (not all(kp[1] in subset.get(k, positions) for k in kappas), positions.index(kp[1])))
    env = dict(os.environ, OMP_NUM_THREADS="1", CCX_NPROC_STIFFNESS="1", CCX_NPROC_EQUATION_SOLVER="1")
    sweep_rows, pair_rows, time_rows = [], [], []
    t_all = time.time()

    def run_one(job_kp):
        kappa, p = job_kp
        slope = kappa * E / h_contact
        job = f"k{kappa:g}_p{p}"
        d = f"{out}/ccx/{job}"
        os.makedirs(d, exist_ok=True)
        model = write_deck(f"{d}/{job}.inp", g, b1, b2, roll[p], [dth[(t, p)] for t in torques], slope, b, E, nu,
                           fine1, fine2)
        wall, cpu = cm.run_ccx(a.ccx, d, job, a.reuse, env, CASE)
        return kappa, p, slope, job, d, model, wall, cpu

    done = 0
    with ThreadPoolExecutor(max_workers=a.jobs) as pool:
        for kappa, p, slope, job, d, model, wall, cpu in (f.result() for f in as_completed(
                [pool.submit(run_one, jk) for jk in jobs])):
            done += 1
            steps = cm.read_dat(f"{d}/{job}.dat", model)
            stress = read_frd_stress(f"{d}/{job}.frd")
            if len(steps) != len(torques) or len(stress) != len(torques):
                sys.exit(f"{CASE}: FAIL (ccx {job}: {len(steps)} steps in the .dat, {len(stress)} in the .frd, "
                         f"expected {len(torques)}; see {d}/{job}.log)")
            for t, st, sb in zip(torques, steps, stress):
                def peak(fil):
                    best = {}
                    for k, nodes in fil.items():
                        vals = [cm.sigma1(sb[v]) for v in nodes if v in sb]
                        if vals:
                            best[k] = max(vals)
                    return best
                r1, r2 = peak(model["fillets1"]), peak(model["fillets2"])
                Fsum = sum(q["F"] for q in st["pairs"])
                loaded = [q for q in st["pairs"] if Fsum > 0 and q["F"] / Fsum > 1e-3]
                sweep_rows.append(dict(kappa=kappa, slope_N_per_mm3=slope, position=p, roll_deg=roll[p],
                                       torque_gearfem=t, dtheta_urad=dth[(t, p)], T1_reaction=st["T1"],
                                       T1_contact_moment=-sum(q["M1"] for q in st["pairs"]), T2=st["T2"],
                                       F_n_sum=Fsum, pairs_loaded=len(loaded),
                                       root_pinion=max(r1.get(q["pinion_tooth"], -1e9) for q in loaded),
                                       root_gear=max(r2.get(q["gear_tooth"], -1e9) for q in loaded),
                                       root_gear_all_fine=max(r2.values())))
                for q in st["pairs"]:
                    pair_rows.append(dict(kappa=kappa, position=p, roll_deg=roll[p], torque_gearfem=t,
                                          pinion_tooth=q["pinion_tooth"], gear_tooth=q["gear_tooth"], slave=q["slave"],
                                          unloaded_gap_um=q["gap_mm"] * 1e3, F=q["F"],
                                          share=q["F"] / Fsum if Fsum > 0 else 0.0,
                                          root_pinion=r1.get(q["pinion_tooth"], float("nan")),
                                          root_gear=r2.get(q["gear_tooth"], float("nan"))))
            time_rows.append(dict(kappa=kappa, position=p, roll_deg=roll[p], wall_s=wall, cpu_s=cpu))
            el = time.time() - t_all
            print(f"ccx {done}/{len(jobs)}  kappa {kappa:g}, roll {roll[p]:+.3f} deg: wall {wall:.1f} s, CPU {cpu:.1f} s, "
                  f"T1 {', '.join('%.1f' % s['T1'] for s in steps)} N m (gearfem {', '.join('%g' % t for t in torques)}); "
                  f"elapsed {el:.0f} s, ETA {el / done * (len(jobs) - done):.0f} s", flush=True)
            cm.write_csv(f"{out}/ccx_sweep.csv", sorted(sweep_rows, key=lambda r: (-r["kappa"], r["torque_gearfem"], r["position"])))
            cm.write_csv(f"{out}/ccx_pairs.csv", sorted(pair_rows, key=lambda r: (-r["kappa"], r["torque_gearfem"], r["position"])))
    time_rows.sort(key=lambda r: (-r["kappa"], r["position"]))
    time_rows.append(dict(kappa=0, position=-1, roll_deg=float("nan"), wall_s=g_wall, cpu_s=g_cpu))
    cm.write_csv(f"{out}/timing.csv", time_rows)
    print(f"== ccx: {len(jobs)} runs in {time.time() - t_all:.0f} s", flush=True)


if __name__ == "__main__":
    main()
