#!/usr/bin/python3
"""Natural frequency of the Parker pair: the closed forms check.py compares with.

1. ISO 6336-1 method B (independent of any gearfem STE): c'_th = 1/q' (eq. 71, C1..C9 for
   x = 0), c' = c'_th C_M C_R C_B (C_M 0.8, C_R 1 solid, C_B = [1 + 0.5 (1.2 - h_fP/m)]
   [1 - 0.02 (20 - alpha)] with h_fP = 1.25 m), c_gamma_alpha = c' (0.75 eps + 0.25);
   f = sqrt(k/m_eq)/2 pi with k = c_gamma_alpha b (mesh) or c' b (one pair).
2. Gkimisis 2019's f_eigen = 2370 Hz (Table 2 pair, b 10). Its listing computes
   `Kmean = mean(Ktotal)`, `eigenf = sqrt(Kmean/mx)/2/pi` with Ktotal = E b / C_tot of the
   tooth pairs (N/mm per pair, eq. 3.2), and I from the same b (b1 = b2, b = min(b1, b2)):
   the stiffness of one tooth pair, not the mesh (the sum over the pairs in contact, ~ eps
   pairs). With the FE pair stiffness (mean over the cycle of the load of each loaded pair /
   STE, i.e. sum(F_n/STE)/sum(pairs) of validation/parker_ste) this is computed here; f is
   independent of b when k and I use the same b. The alternative, mesh stiffness of b 10 with
   inertia of b 20, is computed too.

Usage: eigen_thesis.py <parker_ste plane-stress sweep.csv>   (prints the table)
"""
import math
import os
import sys

Z, M, ALPHA, A = 50, 3.0, math.radians(20), 150.0
RHO_THESIS = 7860.0  # the thesis' listing (den1 = 7.86e3)
F_THESIS = 2370.0    # Hz, Gkimisis 2019 section 5.2


def contact_ratio():
    r, rb, ra = M * Z / 2, M * Z / 2 * math.cos(ALPHA), M * Z / 2 + M
    return (2 * math.sqrt(ra ** 2 - rb ** 2) - A * math.sin(ALPHA)) / (math.pi * M * math.cos(ALPHA))


def iso_stiffness():
    """(c', c_gamma_alpha) in N/(mm um), ISO 6336-1:2006 method B, x1 = x2 = 0, beta = 0."""
    q = 0.04723 + 0.15551 / Z + 0.25791 / Z  # C1 + C2/zn1 + C3/zn2 (x terms vanish)
    c_th = 1 / q
    c_b = (1 + 0.5 * (1.2 - 1.25)) * (1 - 0.02 * (20 - 20))
    c1 = c_th * 0.8 * 1.0 * c_b
    return c1, c1 * (0.75 * contact_ratio() + 0.25)


def m_eq(b_mm, rho):
    """Equivalent mass [kg] of two solid discs of the pitch diameter (eq. 4.3), z1 = z2."""
    r, rb = M * Z / 2e3, M * Z / 2e3 * math.cos(ALPHA)
    inertia = 0.5 * math.pi * r ** 4 * b_mm * 1e-3 * rho
    return inertia / (2 * rb ** 2)


def freq(k, m):
    return math.sqrt(k / m) / (2 * math.pi)


def fe_stiffness(rows, torque):
    """(mesh kbar = mean F_n/mean STE, mean pair stiffness) in N/m of the FE sweep at a torque."""
    sel = [r for r in rows if abs(r["torque"] - torque) < 1e-9]
    kbar = sum(r["F_n"] for r in sel) / sum(r["STE"] * 1e-6 for r in sel)
    kpair = sum(r["F_n"] / (r["STE"] * 1e-6) for r in sel) / sum(r["pairs in contact"] for r in sel)
    return kbar, kpair, sum(r["pairs in contact"] for r in sel) / len(sel)


def candidates(rows, b_fe=20.0):
    """Natural-frequency candidates per torque: dict torque -> dict name -> Hz."""
    out = {}
    for T in (100, 200, 340):
        kbar, kpair, pairs = fe_stiffness(rows, T)
        m20 = m_eq(b_fe, RHO_THESIS)
        out[T] = {"mesh, same b": freq(kbar, m20),
                  "one pair, same b (listing)": freq(kpair, m20),
                  "mesh of b 10, inertia of b 20": freq(kbar * 10 / b_fe, m20),
                  "mean pairs in contact": pairs}
    return out


def main():
    sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "lib"))
    from vcheck import read_csv
    rows = read_csv(sys.argv[1])
    c1, cga = iso_stiffness()
    print(f"contact ratio {contact_ratio():.5f}; ISO c' {c1:.4f}, c_gamma_alpha {cga:.4f} N/(mm um)")
    print(f"ISO f (mesh, b 20, rho 7850) = {freq(cga * 20e6, m_eq(20, 7850)):.1f} Hz; "
          f"(one pair) = {freq(c1 * 20e6, m_eq(20, 7850)):.1f} Hz")
    for T, c in candidates(rows).items():
        print(T, {k: round(v, 3) for k, v in c.items()})


if __name__ == "__main__":
    main()
