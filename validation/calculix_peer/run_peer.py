#!/usr/bin/python3
"""Runs the CalculiX peer comparison (README.md): gearfem solve on the case, then ccx at the
same positions with gearfem's pinion rotations prescribed (rotation control, one ccx *STEP
per torque), at each penalty factor; writes results/ccx_sweep.csv, results/ccx_pairs.csv and
results/timing.csv. Wall and CPU times of both programs are measured here, in one run.

Usage: run_peer.py --gearfem build/app/gearfem --prm inputs/fzg_c_ccx.prm --out results
                   [--kappas 100,10] [--kappa-positions 10:all] [--ccx ccx]
"""
import argparse
import math
import os
from concurrent.futures import ThreadPoolExecutor, as_completed
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import ccx_model as cm  # noqa: E402
from vcheck import read_csv  # noqa: E402



def read_prm_value(path, key):
    with open(path) as f:
        for line in f:
            s = line.split("#")[0].strip()
            if s.startswith("set ") and s[4:].split("=")[0].strip() == key:
                return s.split("=", 1)[1].strip()
    return None



def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--gearfem", required=True)
    ap.add_argument("--prm", required=True)
    ap.add_argument("--out", required=True)
    ap.add_argument("--ccx", default="ccx")
    ap.add_argument("--kappas", default="30,3",
                    help="ccx penalty factors kappa: slope K = kappa E / h_contact [N/mm^3]")
    ap.add_argument("--kappa-positions", default="",
                    help="kappa:comma-separated position indices, to run a kappa at a subset only")
    ap.add_argument("--fine-prm", default="",
                    help="the same case on a refined mesh (gearfem only): its own mesh sensitivity")
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
        print("== gearfem mesh (the same gmsh meshes that gearfem solve builds)", flush=True)
        cm.timed([a.gearfem, "mesh", a.prm, "--output-dir", f"{out}/mesh"], f"{out}/gearfem_mesh.log", case="calculix_peer")
        print("== gearfem solve", flush=True)
        g_wall, g_cpu = cm.timed([a.gearfem, "solve", a.prm, "--output-dir", f"{out}/gearfem"], f"{out}/gearfem_solve.log", case="calculix_peer")
        with open(f"{out}/gearfem/time", "w") as f:
            f.write(f"{g_wall} {g_cpu}\n")
    print(f"   gearfem solve: wall {g_wall:.1f} s, CPU {g_cpu:.1f} s", flush=True)
    if a.fine_prm and not (a.reuse and os.path.exists(f"{out}/gearfem_fine/sweep.csv")):
        print("== gearfem solve on the refined mesh (one global refinement; not timed against ccx)", flush=True)
        cm.timed([a.gearfem, "solve", a.fine_prm, "--output-dir", f"{out}/gearfem_fine"], f"{out}/gearfem_fine.log", case="calculix_peer")
    sweep = read_csv(f"{out}/gearfem/sweep.csv")
    torques = sorted({r["torque"] for r in sweep})
    positions = sorted({int(r["position"]) for r in sweep})
    roll = {int(r["position"]): r["roll angle"] for r in sweep}
    dth = {(r["torque"], int(r["position"])): r["STE angle"] for r in sweep}

    # ---- the pair, bodies and contact set-up
    z1 = int(read_prm_value(a.prm, "Number of teeth") or 0)
    g = cm.pair_geometry(16, 24, 4.5, 0.1817, 0.1715)
    assert z1 == 16, "the deck writer is set up for the FZG type C pair"
    h_contact = float(read_prm_value(a.prm, "h_contact") or 0) or 4.5 / 30  # gearfem's default m/30 [mm]
    E, nu, b = 207000.0, 0.3, 14.0  # MPa, -, mm: gearfem's defaults for steel, the face width
    rw1 = g["rb1"] / math.cos(g["alpha_w"])
    b1, b2 = cm.Body(f"{out}/mesh/gear1.msh"), cm.Body(f"{out}/mesh/gear2.msh")
    print(f"   ccx bodies: {len(b1.elems)} + {len(b2.elems)} CPS8, {len(b1.xy)} + {len(b2.xy)} nodes", flush=True)

    kappas = [float(k) for k in a.kappas.split(",")]
    subset = {}
    if a.kappa_positions:
        k, idx = a.kappa_positions.split(":")
        subset[float(k)] = [int(i) for i in idx.split(",")]
    # the penalty pairs first, so that a late stop still shows the penalty sensitivity
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
        rots = [dth[(t, p)] for t in torques]
        model = cm.write_deck(f"{d}/{job}.inp", g, b1, b2, roll[p], rots, slope, b, E, nu, rw1)
        wall, cpu = cm.run_ccx(a.ccx, d, job, a.reuse, env, "calculix_peer")
        return kappa, p, slope, job, d, model, wall, cpu

    done = 0
    cpu_done = 0.0
    with ThreadPoolExecutor(max_workers=a.jobs) as pool:
        for kappa, p, slope, job, d, model, wall, cpu in (f.result() for f in as_completed(
                [pool.submit(run_one, jk) for jk in jobs])):
            done += 1
            steps = cm.read_dat(f"{d}/{job}.dat", model)
            stress = cm.read_frd_stress(f"{d}/{job}.frd")
            if len(steps) != len(torques) or len(stress) != len(torques):
                sys.exit(f"calculix_peer: FAIL (ccx {job}: {len(steps)} steps in the .dat, {len(stress)} in the .frd, "
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
                sweep_rows.append(dict(kappa=kappa, slope_N_per_mm3=slope, position=p, roll_deg=roll[p],
                                       torque_gearfem=t, dtheta_urad=dth[(t, p)], T1_reaction=st["T1"],
                                       T1_contact_moment=-sum(q["M1"] for q in st["pairs"]), T2=st["T2"],
                                       F_n_sum=Fsum, root_pinion=max(r1.values()), root_gear=max(r2.values())))
                for q in st["pairs"]:
                    pair_rows.append(dict(kappa=kappa, position=p, roll_deg=roll[p], torque_gearfem=t,
                                          pinion_tooth=q["pinion_tooth"], gear_tooth=q["gear_tooth"], slave=q["slave"],
                                          unloaded_gap_um=q["gap_mm"] * 1e3, F=q["F"],
                                          share=q["F"] / Fsum if Fsum > 0 else 0.0,
                                          root_pinion=r1.get(q["pinion_tooth"], float("nan")),
                                          root_gear=r2.get(q["gear_tooth"], float("nan"))))
            time_rows.append(dict(kappa=kappa, position=p, roll_deg=roll[p], wall_s=wall, cpu_s=cpu))
            cpu_done += cpu
            el = time.time() - t_all
            eta = el / done * (len(jobs) - done)
            print(f"ccx {done}/{len(jobs)}  kappa {kappa:g}, roll {roll[p]:+.2f} deg: wall {wall:.1f} s, CPU {cpu:.1f} s, "
                  f"T1 {', '.join('%.2f' % s['T1'] for s in steps)} N m (gearfem {', '.join('%g' % t for t in torques)}); "
                  f"elapsed {el:.0f} s, ETA {eta:.0f} s", flush=True)
            key = lambda r: (-r["kappa"], r["position"])
            cm.write_csv(f"{out}/ccx_sweep.csv", sorted(sweep_rows, key=lambda r: (-r["kappa"], r["torque_gearfem"], r["position"])))
            cm.write_csv(f"{out}/ccx_pairs.csv", sorted(pair_rows, key=lambda r: (-r["kappa"], r["torque_gearfem"], r["position"])))
    time_rows.sort(key=key)
    time_rows.append(dict(kappa=0, position=-1, roll_deg=float("nan"), wall_s=g_wall, cpu_s=g_cpu))
    cm.write_csv(f"{out}/timing.csv", time_rows)
    print(f"== ccx: {len(jobs)} runs in {time.time() - t_all:.0f} s", flush=True)


if __name__ == "__main__":
    main()
