#!/usr/bin/python3
"""Independent reference formulas for helical cylindrical gear pairs.

Written from the standards' formulas only (nothing is imported from the
gearfem C++ code).  Sources and doubts: iso_reference_notes.md (same folder).

* ISO 21771:2007 - geometry of cylindrical involute gears (external pairs).
* ISO 6336-1:2006, clause 9 - tooth stiffness, method B (c', c_gamma).
* ISO 6336-1:2006, clause 7 - face load factor K_Hbeta, method C.

Units: lengths in metres and angles in radians (unless a name ends in
``_deg``).  Stiffness results are in the standard's N/(mm*um) (multiply by
``N_PER_MM_UM`` to get N/m^2 = N/m per metre of face width).
"""
import math
import sys

N_PER_MM_UM = 1.0e9  # 1 N/(mm*um) = 1e9 N/m^2


def inv(alpha):
    """Involute function inv(alpha) = tan(alpha) - alpha (ISO 21771)."""
    return math.tan(alpha) - alpha


def inv_inverse(value):
    """Inverse involute: the angle alpha in (0, pi/2) with inv(alpha) = value."""
    a = (3.0 * value) ** (1.0 / 3.0)  # start from the series inv(a) ~ a^3/3
    for _ in range(60):
        step = (inv(a) - value) / math.tan(a) ** 2  # d inv/d a = tan^2 a
        a -= step
        if abs(step) < 1e-15:
            break
    return a


def helical_geometry(z1, z2, m_n, alpha_n, beta, x1, x2, b, a=None, h_aP=1.0):
    """ISO 21771 geometry of an external helical pair from normal-section data.

    z1, z2   numbers of teeth (external gears, > 0)
    m_n      normal module [m];  alpha_n normal pressure angle [rad]
    beta     reference helix angle [rad];  x1, x2 profile shift coefficients
    b        common face width [m]
    a        centre distance [m]; None -> zero-backlash value from x1 + x2
    h_aP     addendum of the basic rack / m_n (tip: d + 2 m_n (h_aP + x),
             no tip shortening)

    Returned dict (metres / radians): m_t, alpha_t, beta_b, d1, d2, d_b1,
    d_b2, d_a1, d_a2, alpha_wt, a, alpha_wt_x, a_x, g_alpha, eps_alpha,
    eps_beta, eps_gamma, p_bt, p_x, z_n1, z_n2, u.

    alpha_wt_x comes from inv(alpha_wt) = inv(alpha_t) + 2 tan(alpha_n)
    (x1 + x2)/(z1 + z2) and a_x = a_d cos(alpha_t)/cos(alpha_wt_x).  When
    ``a`` is given, the operating alpha_wt is taken from it,
    cos(alpha_wt) = a_d cos(alpha_t)/a, so that g_alpha stays consistent with
    the actual centre distance; compare a with a_x to see any mismatch.
    """
    if z1 <= 0 or z2 <= 0:
        raise ValueError("external pairs only (z1, z2 > 0)")
    cb = math.cos(beta)
    m_t = m_n / cb
    alpha_t = math.atan(math.tan(alpha_n) / cb)
    beta_b = math.asin(math.sin(beta) * math.cos(alpha_n))
    d1, d2 = z1 * m_t, z2 * m_t
    d_b1, d_b2 = d1 * math.cos(alpha_t), d2 * math.cos(alpha_t)
    d_a1 = d1 + 2.0 * m_n * (h_aP + x1)
    d_a2 = d2 + 2.0 * m_n * (h_aP + x2)
    a_d = 0.5 * (d1 + d2)
    alpha_wt_x = inv_inverse(inv(alpha_t) + 2.0 * math.tan(alpha_n) * (x1 + x2) / (z1 + z2))
    a_x = a_d * math.cos(alpha_t) / math.cos(alpha_wt_x)
    if a is None:
        a, alpha_wt = a_x, alpha_wt_x
    else:
        alpha_wt = math.acos(a_d * math.cos(alpha_t) / a)
    p_bt = math.pi * m_t * math.cos(alpha_t)
    g_alpha = 0.5 * (math.sqrt(d_a1**2 - d_b1**2) + math.sqrt(d_a2**2 - d_b2**2)) \
        - a * math.sin(alpha_wt)
    eps_alpha = g_alpha / p_bt
    eps_beta = b * math.sin(beta) / (math.pi * m_n)
    zfac = math.cos(beta_b) ** 2 * cb
    return dict(m_t=m_t, alpha_t=alpha_t, beta_b=beta_b, d1=d1, d2=d2,
                d_b1=d_b1, d_b2=d_b2, d_a1=d_a1, d_a2=d_a2,
                alpha_wt=alpha_wt, a=a, alpha_wt_x=alpha_wt_x, a_x=a_x,
                g_alpha=g_alpha, eps_alpha=eps_alpha, eps_beta=eps_beta,
                eps_gamma=eps_alpha + eps_beta, p_bt=p_bt,
                p_x=(math.pi * m_n / math.sin(beta)) if beta != 0.0 else math.inf,
                z_n1=z1 / zfac, z_n2=z2 / zfac, u=z2 / z1)


# ISO 6336-1:2006 clause 9 (method B), coefficients C1..C9 of q'.
Q_COEFFS = (0.04723, 0.15551, 0.25791, -0.00635, -0.11654,
            -0.00193, -0.24188, 0.00529, 0.00182)


def q_prime(z_n1, z_n2, x1, x2):
    """Minimum flexibility of a tooth pair q' [mm*um/N], ISO 6336-1 clause 9.

    q' = C1 + C2/z_n1 + C3/z_n2 + C4 x1 + C5 x1/z_n1 + C6 x2 + C7 x2/z_n2
         + C8 x1^2 + C9 x2^2.
    Internal gear: pass z_n2 = math.inf (the standard's instruction).
    """
    c = Q_COEFFS
    i1, i2 = 1.0 / z_n1, 1.0 / z_n2
    return (c[0] + c[1] * i1 + c[2] * i2 + c[3] * x1 + c[4] * x1 * i1
            + c[5] * x2 + c[6] * x2 * i2 + c[7] * x1 * x1 + c[8] * x2 * x2)


def basic_rack_factor(h_fP_over_mn, alpha_n):
    """C_B = [1 + 0.5 (1.2 - h_fP/m_n)] [1 - 0.02 (20 deg - alpha_n)].

    ISO 6336-1:2006 clause 9 (method B).  alpha_n in rad; the bracket uses
    degrees.  For pinion and wheel racks that differ use the mean of both.
    """
    return (1.0 + 0.5 * (1.2 - h_fP_over_mn)) * \
        (1.0 - 0.02 * (20.0 - math.degrees(alpha_n)))


def blank_factor(b_s_over_b=1.0, s_R_over_mn=None):
    """Gear blank factor C_R, ISO 6336-1:2006 clause 9 (method B).

    Solid gears: 1.  Otherwise C_R = 1 + ln(b_s/b)/(5 exp(s_R/(5 m_n))) with
    b_s/b limited to [0.2, 1.2] and s_R/m_n >= 1.
    """
    if s_R_over_mn is None or b_s_over_b >= 1.0:
        return 1.0
    bs = min(max(b_s_over_b, 0.2), 1.2)
    sr = max(s_R_over_mn, 1.0)
    return 1.0 + math.log(bs) / (5.0 * math.exp(sr / 5.0))


def stiffness_method_b(z_n1, z_n2, x1, x2, beta, eps_alpha, alpha_n,
                       h_fP1=1.25, h_fP2=None, C_M=0.8, C_R=1.0,
                       line_load=None):
    """Single and mesh stiffness, ISO 6336-1:2006 clause 9, method B.

    z_n1, z_n2  virtual numbers of teeth z/(cos^2 beta_b cos beta)
                (helical_geometry gives them); internal wheel: math.inf
    beta        reference helix angle [rad];  alpha_n [rad]
    h_fP1/2     dedendum of the basic rack / m_n for pinion / wheel
    C_M         theoretical correction factor (0.8);  C_R blank factor
    line_load   F_t K_A / b in N/m (SI).  Below 100 N/mm the load correction
                (F_t K_A / b / 100 N/mm)^0.25 multiplies c'; None -> none.

    Returns dict with q_prime [mm*um/N], c_th, C_B, load_factor, c_prime,
    c_gamma_alpha = c'(0.75 eps_alpha + 0.25), c_gamma_beta = 0.85
    c_gamma_alpha (all stiffnesses in N/(mm*um)).
    """
    if h_fP2 is None:
        h_fP2 = h_fP1
    q = q_prime(z_n1, z_n2, x1, x2)
    c_th = 1.0 / q
    C_B = 0.5 * (basic_rack_factor(h_fP1, alpha_n) + basic_rack_factor(h_fP2, alpha_n))
    w = None if line_load is None else line_load * 1e-3  # N/m -> N/mm
    load_factor = (w / 100.0) ** 0.25 if (w is not None and w < 100.0) else 1.0
    c_prime = c_th * C_M * C_R * C_B * math.cos(beta) * load_factor
    c_ga = c_prime * (0.75 * eps_alpha + 0.25)
    return dict(q_prime=q, c_th=c_th, C_M=C_M, C_R=C_R, C_B=C_B,
                load_factor=load_factor, c_prime=c_prime,
                c_gamma_alpha=c_ga, c_gamma_beta=0.85 * c_ga)


def k_h_beta_method_c(F_beta_y, c_gamma_beta, F_m_over_b):
    """Face load factor K_Hbeta, ISO 6336-1:2006 clause 7, method C.

    K = 1 + F_beta_y c_gamma_beta / (2 F_m/b)     if that value is <= 2,
    K = sqrt(2 F_beta_y c_gamma_beta / (F_m/b))   otherwise.
    The ratio is dimensionless, so any consistent units work: either the
    standard's (F_beta_y in um, c_gamma_beta in N/(mm*um), F_m/b in N/mm) or
    SI (m, N/m^2 = c * N_PER_MM_UM, N/m).
    """
    r = F_beta_y * c_gamma_beta / F_m_over_b
    k = 1.0 + 0.5 * r
    return k if k <= 2.0 else math.sqrt(2.0 * r)


# ---------------------------------------------------------------------------
# Published reference: ISO/TR 6336-30:2017, calculation example 1 (helical,
# m_n 8 mm, z 17/103), values as quoted (reference column) in the test table
# of example_01 in gfsReboucas/Drivetrain, KSISO_6336.m (also ISO_6336.m).
# The TR itself is not freely available; see the notes for doubts.
PUBLISHED = {
    "source": "ISO/TR 6336-30:2017 example 1, as quoted in "
              "https://github.com/gfsReboucas/Drivetrain/blob/"
              "2d6597118d51a36e8dd61e3b136e32ddc4137809/KSISO_6336.m "
              "(function example_01, 'Reference' column)",
    "inputs": dict(m_n=8.0e-3, alpha_n_deg=20.0, z1=17, z2=103, b=100.0e-3,
                   x1=0.145, x2=0.0, beta_deg=15.8, a=500.0e-3,
                   rack="ISO 53 profile D (h_aP = 1.0, h_fP = 1.4 m_n)",
                   h_aP=1.0, h_fP=1.4, T1=9.0e3, n1=360.0, K_A=1.0),
    # geometry values printed in the table (dimensionless or SI)
    "geometry": dict(z_n1=18.905, z_n2=114.543),
    # geometry-derived values printed in the table; each is recomputed from
    # this module's geometry with the one-line ISO formula in self_check()
    "derived": dict(F_t=127352.0, v=2.664, Z_H=2.39533, Z_beta=1.01944,
                    Z_eps=0.803),
    # stiffness values printed in the table, N/(mm*um)
    "stiffness": dict(c_th=17.85584, c_prime=12.37047,
                      c_gamma_alpha=17.46485, c_gamma_beta=14.84512),
}


def self_check():
    """Recompute PUBLISHED; return [(name, computed, published, rel. error)]."""
    p = PUBLISHED["inputs"]
    an, be = math.radians(p["alpha_n_deg"]), math.radians(p["beta_deg"])
    g = helical_geometry(p["z1"], p["z2"], p["m_n"], an, be, p["x1"], p["x2"],
                         p["b"], a=p["a"], h_aP=p["h_aP"])
    F_t = 2.0 * p["T1"] / g["d1"]                      # N
    line_load = F_t * p["K_A"] / p["b"]                # N/m
    s = stiffness_method_b(g["z_n1"], g["z_n2"], p["x1"], p["x2"], be,
                           g["eps_alpha"], an, h_fP1=p["h_fP"],
                           line_load=line_load)
    Z_eps = (math.sqrt(1.0 / g["eps_alpha"]) if g["eps_beta"] >= 1.0 else
             math.sqrt((4.0 - g["eps_alpha"]) / 3.0 * (1.0 - g["eps_beta"])
                       + g["eps_beta"] / g["eps_alpha"]))   # ISO 6336-2
    derived = dict(
        F_t=F_t,
        v=math.pi * g["d1"] * p["n1"] / 60.0,
        Z_H=math.sqrt(2.0 * math.cos(g["beta_b"]) * math.cos(g["alpha_wt"])
                      / (math.cos(g["alpha_t"]) ** 2 * math.sin(g["alpha_wt"]))),
        Z_beta=1.0 / math.sqrt(math.cos(be)),
        Z_eps=Z_eps)
    rows = []
    for group, comp in (("geometry", g), ("derived", derived), ("stiffness", s)):
        for name, pub in PUBLISHED[group].items():
            rows.append((name, comp[name], pub, (comp[name] - pub) / pub))
    return rows


TOLERANCE = {"geometry": 1e-3, "derived": 1e-3, "stiffness": 1e-2}


def _group(name):
    for group in ("geometry", "derived", "stiffness"):
        if name in PUBLISHED[group]:
            return group
    raise KeyError(name)


def main():
    p = PUBLISHED["inputs"]
    g = helical_geometry(p["z1"], p["z2"], p["m_n"], math.radians(p["alpha_n_deg"]),
                         math.radians(p["beta_deg"]), p["x1"], p["x2"], p["b"],
                         a=p["a"], h_aP=p["h_aP"])
    print("Source:", PUBLISHED["source"])
    print("Geometry (mm / deg): d1 %.4f d2 %.4f db1 %.4f db2 %.4f da1 %.4f da2 %.4f"
          % tuple(1e3 * g[k] for k in ("d1", "d2", "d_b1", "d_b2", "d_a1", "d_a2")))
    print("  alpha_t %.5f beta_b %.5f alpha_wt %.5f (from x: %.5f, a_x %.4f mm)"
          % (math.degrees(g["alpha_t"]), math.degrees(g["beta_b"]),
             math.degrees(g["alpha_wt"]), math.degrees(g["alpha_wt_x"]), 1e3 * g["a_x"]))
    print("  eps_alpha %.5f eps_beta %.5f eps_gamma %.5f p_bt %.4f mm p_x %.4f mm"
          % (g["eps_alpha"], g["eps_beta"], g["eps_gamma"], 1e3 * g["p_bt"], 1e3 * g["p_x"]))
    print("%-14s %14s %14s %11s  %s" % ("name", "computed", "published", "rel.err", "status"))
    bad = 0
    for name, comp, pub, err in self_check():
        ok = abs(err) <= TOLERANCE[_group(name)]
        bad += not ok
        print("%-14s %14.6g %14.6g %+11.3e  %s"
              % (name, comp, pub, err, "ok" if ok else "FAIL"))
    print("all within tolerance" if not bad else "%d value(s) out of tolerance" % bad)
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
