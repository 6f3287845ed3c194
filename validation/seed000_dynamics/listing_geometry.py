#!/usr/bin/python3
"""Gkimisis 2019, the geometric model of its listings (Appendix: "Αλγόριθμος Γεωμετρικής
Ανάλυσης Ζεύγους" and "Αλγόριθμος Υπολογισμού Δυνάμεων Επαφής"), replicated in numpy from the
thesis' text, independent of gearfem.

Units as the listing: mm, rad, N, MPa. `geometry(da12)` is the contact path over the pinion
angle w1 (line of action AB and the corner contacts OA / BΓ), the moment arms, load angles,
Hertz radii and the bending integrals of both teeth; `torque_table(g)` the tables
MELG1/MELG2(POS1, STE) of the elastic torques on both gears (bilinear in the dynamics), with
the load-dependent Hertz compliance solved by load increments as the listing does it.

Where the listing's text is not what MATLAB can run (OCR of the printed code), the reading
used is named at the line: `th0` read as `thO`; the unbalanced `floor(...)` wraps of the
dynamics read as floor(((w1LoA2 + w1LoA1)/2 + pi/z1 - p1)/(2 pi/z1)) (listing_replica.py)."""
import math

import numpy as np

Z1, Z2, M, A0X = 32, 60, 3.0, math.pi / 9
B, CF1, CF2, E1, E2, V1, V2 = 30.0, 0.49, 0.49, 200e3, 200e3, 0.3, 0.3


def inv(a):
    return np.tan(a) - a


def _max_radius(Rg, So, Ro, a_start):
    """The listing's `Maximum Radius` loop, as written: af <- tan(af) - th until |change| <=
    pi/10000 (a repelling fixed point, so it stops where the orbit happens to pass)."""
    th = math.tan(A0X) - A0X + So / 2 / Ro
    af, da, n = a_start, 1.0, 0
    while abs(da) > math.pi / 10000 and n < 100000:
        afn = math.tan(af) - th
        da, af, n = afn - af, afn, n + 1
    return Rg / math.cos(af), n


def _gear(z, hk_c, hf_c, Cf, a_start, tb_factor, c_factor, Rg_over):
    """Detailed geometry of one gear (listing, `Detailed Geometry of Gear j`)."""
    Ro = M * z / 2
    Rg = Ro * math.cos(A0X)
    to = math.pi * M
    So = Cf * to
    phit = So / Ro + 2 * (math.tan(A0X) - A0X)        # angular thickness at Rg
    rkmax, iters = _max_radius(Rg, So, Ro, a_start)
    Rk = min(Ro + hk_c * M, rkmax)
    Rmin = Ro - hf_c * M
    tb = tb_factor * Rmin * phit                        # approximate width at Rmin
    c = max(c_factor * (Rk - Rmin), 1.2 * (Rg - Rmin))  # trochoid length
    Rtr = Rmin + c
    phitr = math.tan(A0X) - A0X - (math.tan(math.acos(Rg / Rtr)) - math.acos(Rg / Rtr))
    Str = (So / Ro + 2 * phitr) * Rtr
    return dict(Ro=Ro, Rg=Rg, So=So, phit=phit, Rk=Rk, rkmax=rkmax, rk_iters=iters, Rmin=Rmin, tb=tb,
                c=c, Rtr=Rtr, Str=Str)


def _integrals(C, g, dr=1e-3):
    """I1 = sum dr/t, I2 = sum (y - C)^2/t^3 dr over y = 0:dr:C (the listing's loops), with the
    trochoid t = a y^2 - y + tb below y = c and the involute thickness above."""
    a = (g["Str"] - g["tb"] + g["c"]) / g["c"] ** 2
    y = np.arange(0.0, float(np.max(C)) + 2 * dr, dr)
    r = y + g["Rmin"]
    with np.errstate(invalid="ignore"):
        al = np.arccos(np.minimum(g["Rg"] / r, 1.0))
    t = np.where(y < g["c"], a * y ** 2 - y + g["tb"], (g["phit"] - 2 * inv(al)) * r)
    I1 = np.empty_like(C)
    I2 = np.empty_like(C)
    for k, Ck in enumerate(C):
        n = int(math.floor(Ck / dr + 1e-9)) + 1         # y = 0:dr:C
        yy, tt = y[:n], t[:n]
        I1[k] = np.sum(dr / tt)
        I2[k] = np.sum((yy - Ck) ** 2 / tt ** 3 * dr)
    return I1, I2


def _contact_points(g, w1):
    """Contact point, pressure angles and w2 (before the w2 = pi - w2 turn) per w1."""
    a12, Rg1, Rg2, a0, Rk1, Rk2 = g["a12"], g["Rg1"], g["Rg2"], g["a0"], g["g1"]["Rk"], g["g2"]["Rk"]
    n = w1.size
    xC, yC, aC1, w2, dydx, idx = (np.zeros(n) for _ in range(6))
    loa = (w1 >= g["w1LoA1"]) & (w1 <= g["w1LoA2"])
    oa = (g["thO"] + g["tht1"] <= w1) & (w1 < g["w1LoA1"])          # `th0` read as thO
    bg = (g["thB"] + g["tht1"] < w1) & (w1 <= g["thD"] + g["tht1"])
    # line of action
    a = np.arctan(a0 + w1[loa])
    pos = w1[loa] - inv(a)
    xC[loa], yC[loa], aC1[loa] = np.sin(pos) * Rg1 / np.cos(a), np.cos(pos) * Rg1 / np.cos(a), a
    # OA: recursive method, per point as the listing (stops at |da| <= pi/10000)
    a = np.full(int(oa.sum()), math.pi / 6)
    active = np.ones_like(a, dtype=bool)
    w = w1[oa]
    for _ in range(10000):
        if not active.any():
            break
        th = inv(a[active])
        pos = w[active] - th
        A = a12 - np.sqrt(Rk2 ** 2 - (Rg1 / np.cos(a[active]) * np.sin(pos)) ** 2)
        a1 = np.arccos(Rg1 / A * np.cos(pos))
        da = a[active] - a1
        sub = a[active]
        sub[:] = a1
        a[active] = sub
        act_idx = np.flatnonzero(active)
        active[act_idx[np.abs(da) <= math.pi / 10000]] = False
    pos = w - inv(a)
    xC[oa] = Rg1 / np.cos(a) * np.sin(pos)
    yC[oa] = a12 - np.sqrt(Rk2 ** 2 - xC[oa] ** 2)
    aC1[oa] = a
    # BΓ: pinion tip corner
    xC[bg], yC[bg], aC1[bg] = Rk1 * np.sin(w1[bg] - g["tht1"]), Rk1 * np.cos(w1[bg] - g["tht1"]), math.acos(Rg1 / Rk1)
    d2 = np.sqrt(xC ** 2 + (a12 - yC) ** 2)
    aC2 = np.arccos(np.minimum(Rg2 / d2, 1.0))
    w2[loa] = (np.tan(aC2[loa]) - a0) + math.pi
    cor = oa | bg
    w2[cor] = math.pi + inv(aC2[cor]) - np.arcsin(xC[cor] / d2[cor])
    dydx[loa | oa] = 1 / np.tan(w1[loa | oa] - np.tan(aC1[loa | oa]))
    dydx[bg] = 1 / np.tan(w2[bg] - np.tan(aC2[bg]))
    idx[oa], idx[loa], idx[bg] = 0, 1, 2
    keep = loa | oa | bg
    return dict(xC=xC, yC=yC, aC1=aC1, aC2=aC2, w2=w2, dydx=dydx, index=idx, keep=keep)


def geometry(da12=0.0):
    g1 = _gear(Z1, 1.0, 1.25, CF1, math.pi / 10, 1.1, 0.18, None)
    g2 = _gear(Z2, 1.0, 1.25, CF2, math.pi / 4, 0.98, 0.15, None)
    Rg1, Rg2, Rk1, Rk2 = g1["Rg"], g2["Rg"], g1["Rk"], g2["Rk"]
    a12 = g1["Ro"] + g2["Ro"] + da12
    Rb1 = a12 * Rg1 / (Rg1 + Rg2)
    Rb2 = a12 - Rb1
    a0 = math.acos(Rg1 / Rb1)
    ta = math.tan(a0)
    D1 = (2 * Rb1 * ta) ** 2 + 4 * (1 + ta ** 2) * (Rk1 ** 2 - Rb1 ** 2)
    xB = (-2 * Rb1 * ta + math.sqrt(D1)) / (2 * (1 + ta ** 2))
    yB = Rb1 + xB * ta
    thB = math.atan(xB / yB)
    D2 = (2 * Rb2 * ta) ** 2 - 4 * (1 + ta ** 2) * (Rb2 ** 2 - Rk2 ** 2)
    xA = (2 * Rb2 * ta - math.sqrt(D2)) / (2 * (1 + ta ** 2))
    yA = Rb1 + ta * xA
    thA = math.atan(xA / yA)
    yD = (Rk1 ** 2 - Rk2 ** 2 + a12 ** 2) / (2 * a12)
    xD = math.sqrt(Rk1 ** 2 - yD ** 2)
    thD = math.atan(xD / yD)
    thO = -thD
    tht1 = math.tan(math.acos(Rg1 / Rk1)) - math.acos(Rg1 / Rk1)
    tht2 = math.tan(math.acos(Rg2 / Rk2)) - math.acos(Rg2 / Rk2)
    to = math.pi * M
    blsh = (1 - CF1 - CF2) * to * math.cos(A0X) + (Rg1 + Rg2) * (inv(a0) - inv(A0X))  # listing: no factor 2
    g = dict(g1=g1, g2=g2, a12=a12, Rb1=Rb1, Rb2=Rb2, a0=a0, Rg1=Rg1, Rg2=Rg2, thA=thA, thB=thB, thD=thD,
             thO=thO, tht1=tht1, tht2=tht2, blsh=float(blsh), w1LoA1=math.tan(thA + a0) - a0,
             w1LoA2=thB + tht1)
    g["epsilon"] = abs(g["w1LoA2"] - g["w1LoA1"]) * Rg1 / to / math.cos(a0)
    n = int(math.floor((thD - thO) / (math.pi / 10000) + 1e-9)) + 1
    w1 = (thO + tht1) + np.arange(n) * (math.pi / 10000)
    cp = _contact_points(g, w1)
    k = cp.pop("keep")
    w1 = w1[k]
    cp = {key: v[k] for key, v in cp.items()}
    _arms(g, w1, cp)
    return g


def _arms(g, w1, cp):
    """Moment arms, tooth-axis heights, Hertz distances, load angles and bending integrals."""
    a12, phit1, phit2 = g["a12"], g["g1"]["phit"], g["g2"]["phit"]
    xC, yC, w2, dydx = cp["xC"], cp["yC"], cp["w2"], cp["dydx"]
    A = -1 / dydx
    c1 = w1 - phit1 / 2
    c2 = w2 - phit2 / 2
    RK1 = (yC - A * xC) / (np.cos(c1) - A * np.sin(c1))
    RK2 = np.abs((a12 - yC + A * xC) / (A * np.sin(c2 - math.pi) - np.cos(c2 - math.pi)))
    K1E = np.abs((xC - yC * np.tan(c1)) / (1 - A * np.tan(c1))) * np.sqrt(1 + A ** 2)
    K2E = np.abs((xC + (a12 - yC) * np.tan(c2)) / (A * np.tan(c2) - 1)) * np.sqrt(1 + A ** 2)
    C1 = np.maximum(RK1 - g["g1"]["Rmin"], 0.0)
    C2 = np.maximum(RK2 - g["g2"]["Rmin"], 0.0)
    I1G1, I2G1 = _integrals(C1, g["g1"])
    I1G2, I2G2 = _integrals(C2, g["g2"])
    CR1 = g["Rg1"] * np.tan(cp["aC1"])
    CR2 = g["Rg2"] * np.tan(cp["aC2"])
    phi1 = np.arctan(dydx) + math.pi / 2 + w1 - phit1 / 2
    phi2 = np.arctan(dydx) - math.pi / 2 + (w2 - phit2 / 2)
    w2 = math.pi - w2
    RC1 = np.abs(A * xC - yC) / np.sqrt(A ** 2 + 1)
    RC2 = a12 * np.sin(-np.arctan(dydx)) - RC1
    g.update(w1=w1, w2=w2, RC1=RC1, RC2=RC2, phi1=phi1, phi2=phi2, CR1=CR1, CR2=CR2, K1E=K1E, K2E=K2E,
             C1=C1, C2=C2, I1G1=I1G1, I2G1=I2G1, I1G2=I1G2, I2G2=I2G2, index=cp["index"])
    g["w20"] = (g["Rg1"] / g["Rg2"] + 1) * (g["a0"] - math.tan(g["a0"]))


def _interp(xq, xp, fp):
    """MATLAB interp1 (linear, NaN outside), for increasing or decreasing xp."""
    if xp[0] > xp[-1]:
        xp, fp = xp[::-1], fp[::-1]
    return np.interp(xq, xp, fp, left=np.nan, right=np.nan)


def _deltas():
    """deltap sequence of the listing: -1e-5, -1e-7, 0, 1e-6, then x1.05 while <= 0.1 rad."""
    d, out = 1e-6, [-1e-5, -1e-7, 0.0, 1e-6]
    while d <= 1e-1:
        d *= 1.05
        out.append(d)
    return np.array(out)


def torque_table(g, Fn=0.1):
    """MELG1, MELG2 [N m] and the pair count TCN over POS1 (101 pinion positions over one pitch
    about the middle of AB) x STE (the compression of the first position per deltap), and the
    pair stiffnesses Ktotal of the table's last entry (the listing's Kmean = mean(Ktotal))."""
    pitch1, pitch2 = 2 * math.pi / Z1, 2 * math.pi / Z2
    mid = (g["w1LoA2"] + g["w1LoA1"]) / 2
    POS1 = mid - math.pi / Z1 + np.arange(101) * (pitch1 / 100)
    deltas = _deltas()
    w1, w2 = g["w1"], g["w2"]
    E = 2 * E1 * E2 / (E1 + E2)
    v = math.sqrt(1 - E / 2 * ((1 - V1 ** 2) / E1 + (1 - V2 ** 2) / E2))
    slots = np.arange(-4, 5)
    P1 = POS1[:, None]
    p2 = _interp(POS1, w1, w2)[:, None]
    w2T = p2 + slots[None, :] * pitch2
    in2 = (w2[0] < w2T) & (w2T < w2[-1])
    w1NOM = _interp(w2T, w2, w1)
    prop2 = {k: _interp(w2T, w2, g[k]) for k in ("RC2", "phi2", "CR2", "I1G2", "I2G2", "K2E", "C2")}
    F = np.full(w2T.shape, Fn)
    MELG1 = np.zeros((POS1.size, deltas.size))
    MELG2 = np.zeros_like(MELG1)
    TCN = np.zeros_like(MELG1)
    STE = np.zeros(deltas.size)
    g1, g2 = g["g1"], g["g2"]
    for j, d in enumerate(deltas):
        p01 = P1 + d
        iMin = np.ceil((-p01 + g["thO"] + g["tht1"]) * Z1 / (2 * math.pi))
        iMax = np.floor((-p01 + g["thD"] + g["tht1"]) * Z1 / (2 * math.pi))
        on = in2 & (slots[None, :] >= iMin) & (slots[None, :] <= iMax)
        w1T = p01 + slots[None, :] * pitch1
        pr1 = {k: _interp(w1T, w1, g[k]) for k in ("RC1", "phi1", "CR1", "I1G1", "I2G1", "K1E", "C1")}
        STE[j] = (p01[0, 0] * g["Rg1"] - (p2[0, 0] - g["w20"]) * g["Rg2"])
        disp = np.where(on, np.maximum(g["Rg1"] * (w1T - w1NOM), 0.0), 0.0)
        Ph1, Ph2 = pr1["phi1"], prop2["phi2"]
        Cb1 = 12 * (np.cos(Ph1) ** 2 * (pr1["I2G1"] + (0.2 * (1 + V1) + np.tan(Ph1) ** 2 / 12) * pr1["I1G1"]))
        Cb2 = 12 * (np.cos(Ph2) ** 2 * (prop2["I2G2"] + (0.2 * (1 + V2) + np.tan(Ph2) ** 2 / 12) * prop2["I1G2"]))
        Cf1 = (1 - V1 ** 2) * np.cos(Ph1) ** 2 * (50 / 2 / math.pi * (pr1["C1"] / g1["tb"]) ** 2 + 2 * (1 - 2 * V1) / (1 - V1)
                                                 * pr1["C1"] / g1["tb"] + 4.82 / math.pi * (1 + np.tan(Ph1) ** 2 / 2.4 / (1 + v)))
        Cf2 = (1 - V2 ** 2) * np.cos(Ph2) ** 2 * (50 / 2 / math.pi * (prop2["C2"] / g2["tb"]) ** 2 + 2 * (1 - 2 * V2) / (1 - V2)
                                                 * prop2["C2"] / g2["tb"] + 4.82 / math.pi * (1 + np.tan(Ph2) ** 2 / 2.4 / (1 + v)))
        CG12 = (Cb1 + Cf1) * E / E1 + (Cb2 + Cf2) * E / E2
        Csqd = 8 * F * (pr1["CR1"] * prop2["CR2"] * (1 - v ** 2) / (math.pi * B * E * (pr1["CR1"] + prop2["CR2"])))
        with np.errstate(invalid="ignore", divide="ignore"):
            Chr2 = 2 * (1 - v ** 2) / math.pi * (np.log(4 * pr1["K1E"] * prop2["K2E"] / Csqd) - v / (1 - v))
            K = np.where(on, E * B / (CG12 + Chr2), np.nan)
        Fnew = np.where(on, np.maximum(np.nan_to_num(K) * disp, Fn), Fn)
        F = Fnew
        MELG1[:, j] = np.nansum(np.where(on, K * disp * pr1["RC1"] / 1e3, 0.0), axis=1)
        MELG2[:, j] = np.nansum(np.where(on, K * disp * prop2["RC2"] / 1e3, 0.0), axis=1)
        TCN[:, j] = np.sum(on & (disp > 0), axis=1)
        if j == deltas.size - 1:
            Klast = K[-1][on[-1]]
    return dict(POS1=POS1, STE=STE, MELG1=MELG1, MELG2=MELG2, TCN=TCN, Kmean=float(np.mean(Klast)) * 1e3,
                deltas=deltas)


if __name__ == "__main__":
    for da in (0.0, 1.0):
        g = geometry(da)
        t = torque_table(g)
        print(f"a12 {g['a12']:.3f}: Rk1 {g['g1']['Rk']:.4f} (loop {g['g1']['rkmax']:.4g}, {g['g1']['rk_iters']} it), "
              f"Rk2 {g['g2']['Rk']:.4f} (loop {g['g2']['rkmax']:.4g}), eps {g['epsilon']:.4f}, blsh {g['blsh']:.4f} mm, "
              f"AB [{math.degrees(g['w1LoA1']):.2f}, {math.degrees(g['w1LoA2']):.2f}] deg, Kmean {t['Kmean']:.4g} N/m, "
              f"STE0 {t['STE'][3]:.3g}, w2 increasing {bool(g['w2'][-1] > g['w2'][0])}")
