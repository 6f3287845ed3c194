#!/usr/bin/python3
"""ccx's plane stress (README.md): a CPS8 cantilever 10 x 1 mm (40 x 4 elements, parabolic
tip shear of 100 N, E 207 GPa, nu 0.3) at section thicknesses t; the tip deflection scaled to
14 mm against Timoshenko's closed form in plane stress and plane strain. ccx expands CPS8 into
a layer of 20-node bricks t thick, so only a thin layer is plane stress. Writes
results/slab_check.csv; the check is in check.py.

Usage: slab_check.py --ccx ccx --out results
"""
import argparse
import os
import subprocess

L, H, NX, NY, P, E, NU, B = 10.0, 1.0, 40, 4, 100.0, 207000.0, 0.3, 14.0


def deck(t):
    nid, lines, k = {}, ["*NODE"], 0
    for j in range(2 * NY + 1):
        for i in range(2 * NX + 1):
            if i % 2 == 1 and j % 2 == 1:
                continue
            k += 1
            nid[(i, j)] = k
            lines.append(f"{k}, {L * i / (2 * NX)}, {H * j / (2 * NY) - H / 2}")
    lines.append("*ELEMENT, TYPE=CPS8, ELSET=A")
    e = 0
    for j in range(NY):
        for i in range(NX):
            i0, j0 = 2 * i, 2 * j
            e += 1
            c = [nid[(i0, j0)], nid[(i0 + 2, j0)], nid[(i0 + 2, j0 + 2)], nid[(i0, j0 + 2)],
                 nid[(i0 + 1, j0)], nid[(i0 + 2, j0 + 1)], nid[(i0 + 1, j0 + 2)], nid[(i0, j0 + 1)]]
            lines.append(f"{e}, " + ", ".join(map(str, c)))
    left = [nid[(0, j)] for j in range(2 * NY + 1)]
    tip = [nid[(2 * NX, j)] for j in range(2 * NY + 1)]
    lines += ["*NSET, NSET=LEFT", ", ".join(map(str, left)), f"*NSET, NSET=TIPMID\n{nid[(2 * NX, NY)]}",
              "*MATERIAL, NAME=S", "*ELASTIC", f"{E}, {NU}", "*SOLID SECTION, ELSET=A, MATERIAL=S", f"{t}",
              "*BOUNDARY", "LEFT, 1, 2, 0.", "*STEP", "*STATIC", "*CLOAD"]
    h = H / (2 * NY)
    w = [1] + [4 if j % 2 else 2 for j in range(1, 2 * NY)] + [1]  # Simpson weights
    tau = [1 - (2 * (H * j / (2 * NY) - H / 2) / H) ** 2 for j in range(2 * NY + 1)]
    f = [tau[j] * w[j] * h / 3 for j in range(2 * NY + 1)]
    s = sum(f)
    for j, n in enumerate(tip):
        lines.append(f"{n}, 2, {-f[j] * P * t / B / s}")  # the load per unit thickness of 14 mm
    lines += ["*NODE PRINT, NSET=TIPMID", "U", "*END STEP"]
    return "\n".join(lines) + "\n"


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--ccx", default="ccx")
    ap.add_argument("--out", required=True)
    a = ap.parse_args()
    d = os.path.join(a.out, "slab_check")
    os.makedirs(d, exist_ok=True)
    I, G = B * H ** 3 / 12, E / (2 * (1 + NU))
    ps = P * L ** 3 / (3 * E * I) + P * L / (5 / 6 * G * B * H)
    pe = P * L ** 3 / (3 * E * I) * (1 - NU ** 2) + P * L / (5 / 6 * G * B * H)
    rows = []
    for t in (B * 1e-3, 1.0, B):
        job = f"cant_t{t:g}"
        with open(f"{d}/{job}.inp", "w") as f:
            f.write(deck(t))
        with open(f"{d}/{job}.log", "w") as f:
            subprocess.check_call(["nice", "-n", "15", a.ccx, job], cwd=d, stdout=f, stderr=subprocess.STDOUT,
                                  env=dict(os.environ, OMP_NUM_THREADS="1"))
        with open(f"{d}/{job}.dat") as f:
            v = [ln for ln in f.read().split("\n") if ln.strip()][-1].split()
        rows.append((t, -float(v[2])))
    tmp = f"{a.out}/slab_check.csv.tmp"
    with open(tmp, "w") as f:
        f.write("thickness_mm,tip_deflection_mm,timoshenko_plane_stress_mm,timoshenko_plane_strain_mm\n")
        for t, u in rows:
            f.write(f"{t},{u},{ps},{pe}\n")
    os.replace(tmp, f"{a.out}/slab_check.csv")
    for t, u in rows:
        print(f"   CPS8 cantilever, thickness {t:g} mm: tip {u:.5f} mm (plane stress {ps:.5f}, plane strain {pe:.5f})")


if __name__ == "__main__":
    main()
