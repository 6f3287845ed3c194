#!/usr/bin/python3
"""The NTUA tooth-mass thesis' compliance code (ch. 2, eqs. 2.1-2.20, and the appendix
listings `gear_v4`, `compliance1`, `curv_rad_h1`, `pmax_hertz`, `CH`), replayed in numpy
from the thesis' text, and the mesh stiffness it gives for the 20/40 pair (README.md,
"Stiffness: the thesis' compliance code").

The listing, as printed:
- `gear_v4`: rack generation of the tooth (rack with addendum C_k m, dedendum C_f m, tip
  radius C_c m, root radius C_h m, tooth share C_s), then the profile turned by
  `aot = So/(4*pi*ro)` and shifted by So/2 so that the tooth centreline is the y axis
  (the text, ch. 1: "rotation by the angle (S0/2)/r0 rad");
- `compliance1`: load angle f = a - w with `w = (0.25*S)./(pi*r)`, Y = y - tan(f) x;
  bending Cb = 12 cos^2 f (I2 + I1 (0.2 (1+v) + tan^2 f/12)), I1 = int 1/t dy,
  I2 = int (y-Y)^2/t^3 dy (polynomial fits of 1/t and 1/t^3, first sample set to 0, n
  rectangles); foundation Cfnd = (1-v^2) cos^2 f (50/(3 pi) X^2 + 2(1-2v)/(1-v) X
  + 4.82/pi (1 + tan^2 f/(2.4 (1+v)))), X = Y/tf;
- `curv_rad_h1`: rc = rg tan a, h = sqrt((y-Y)^2 + x^2);
- `pmax_hertz`: `Pmax = sqrt((W.*R*E)/(pi*b*2*(1-v^2)))`, R = rc1 rc2/(rc1+rc2);
- `CH`: c = (4/E) R (1-v^2) pmax, CH = (2/pi)(1-v^2)(ln(4 h1 h2/c^2) - v/(1-v));
- pair compliance C = Cb1 + Cf1 + CH + Cb2 + Cf2 (eq. 2.2), load shared as 1/C (eqs.
  2.15-2.18), pair stiffness E b/C (eq. 2.20), pairs in parallel (sec. 2.3).

The corrections (each switchable alone, `Variant`):
- `pmax`: Hertz p_max = sqrt(W E/(2 pi b R (1-v^2))) (R in the denominator; then
  c = 4 R (1-v^2) p_max/E is the Hertz half-width sqrt(8 W R (1-v^2)/(pi b E)));
- `w`: the half-thickness angle of the arc thickness S on the circle r is S/(2 r);
- `aot`: the profile turned by (S0/2)/r0, the angle the thesis' text gives;
- `hertz = False`: C without the Hertz part, Cb1 + Cf1 + Cb2 + Cf2: the thesis' fits are
  this sum with the listing's w and aot (within 5 %), not eq. 2.2 (the README).

Units: the listing's geometry is in mm (m = 2.5, ro = 0.5 z m); forces in N, E in N/mm^2
(210 GPa), b in mm, so E b/C is in N/mm (x 1e3 for N/m). With R in the numerator p_max
depends on the unit of length; the units are the listing's own (mm).
Not given by the thesis: the rack tip and root radius coefficients C_c, C_h (0.25 and 0:
gearfem's rack, rate_20_40.prm) and the degree of the polynomial fits (8 here; the result
moves by < 0.5 % between 6 and 10). The load is the pinion torque at the pitch radius,
W = 100 N m / 25 mm = 4000 N (model_solve's lever arm).

Usage: compliance_replica.py OUT_DIR  (writes OUT_DIR/compliance_replica.json)
"""
import json
import math
import os
import sys
from dataclasses import dataclass

import numpy as np

M, AO, CF, CK, CC, CH_RACK, CS = 2.5, math.radians(20.0), 1.25, 1.0, 0.25, 0.0, 0.5
Z1, Z2 = 20, 40
E, NU, B = 210e3, 0.3, 30.0          # N/mm^2, -, mm
W_TOTAL = 100e3 / (0.5 * Z1 * M)     # N: 100 N m at the pitch radius (model_solve's r1)
A_SPLIT, PITCH = 0.228, math.pi / 10  # the thesis' fits (model_solve)


@dataclass(frozen=True)
class Variant:
    pmax: bool = False  # Hertz p_max with R in the denominator
    w: bool = False     # half-thickness angle S/(2 r)
    aot: bool = False   # profile turned by (S0/2)/r0 (gear_v4)
    hertz: bool = True  # the Hertz compliance CH in C (eq. 2.2); False: Cb1 + Cf1 + Cb2 + Cf2


LISTING = Variant()
CORRECTED = Variant(True, True, True)
VARIANTS = {"listing": LISTING, "pmax": Variant(pmax=True), "w": Variant(w=True), "aot": Variant(aot=True),
            "no_hertz": Variant(hertz=False), "corrected": CORRECTED,
            "corrected_no_hertz": Variant(True, True, True, False)}


def kth1(c):
    return 1.269e09 * np.sin(3.174 * c + 1.195)


def kth2(c):
    return 7.82e08 * np.sin(3.957 * c + 6.628)


def gear_v4(z, m, ao, cf, ck, cc, ch, cs, n, fix_aot):
    """The listing's gear_v4: rack profile, generated tooth, turned and shifted to the tooth
    frame (y axis = centreline, y = 0 at the root circle). Returns xc, yc and the segment
    index of each point (0 tip flat, 1 tip rounding, 2 involute, 3 fillet, 4 root)."""
    ro = 0.5 * z * m
    to = m * math.pi
    hk, hf, rc, rh = m * ck, m * cf, m * cc, m * ch
    at = hf - rc * (1 - math.sin(ao))
    af = hk - rh * (1 - math.sin(ao))
    so = cs * to
    lo = to - so
    d = lo - 2 * (at * math.tan(ao) + rc * math.cos(ao))
    dk = so - 2 * (af * math.tan(ao) + rh * math.cos(ao))
    x = np.linspace(-0.5 * so, 0.5 * lo, n)
    y = np.full(n, np.nan)
    dydx = np.full(n, np.nan)
    seg = np.full(n, -1)
    s0 = (x >= -0.5 * so) & (x < -0.5 * (so - dk))
    s1 = (x >= -0.5 * (so - dk)) & (x < -af * math.tan(ao))
    s2 = (x >= -af * math.tan(ao)) & (x <= at * math.tan(ao))
    s3 = (x > at * math.tan(ao)) & (x <= 0.5 * (lo - d))
    s4 = (x > 0.5 * (lo - d)) & (x <= 0.5 * lo)
    y[s0], dydx[s0], seg[s0] = hk, 0.0, 0
    u = x[s1] + 0.5 * (so - dk)
    y[s1] = af - rh * math.sin(ao) + np.sqrt(rh ** 2 - u ** 2)
    dydx[s1] = -u / np.sqrt(rh ** 2 - u ** 2)
    seg[s1] = 1
    y[s2], dydx[s2], seg[s2] = math.tan(0.5 * math.pi + ao) * x[s2], math.tan(0.5 * math.pi + ao), 2
    u = 0.5 * (lo - d) - x[s3]
    root = np.sqrt(np.maximum(rc ** 2 - u ** 2, 1e-300))
    y[s3] = -at + rc * math.sin(ao) - root
    dydx[s3] = -u / root
    seg[s3] = 3
    y[s4], dydx[s4], seg[s4] = -hf, 0.0, 4
    k = -(dydx * y + x)
    t = k / ro
    xg = (x + k) * np.cos(t) - (y + ro) * np.sin(t)
    yg = (x + k) * np.sin(t) + (y + ro) * np.cos(t) - ro
    aot = so / (2 * ro) if fix_aot else so / (4 * math.pi * ro)
    xgt = math.cos(aot) * xg + math.sin(aot) * yg
    ygt = -math.sin(aot) * xg + math.cos(aot) * yg
    return xgt + 0.5 * so, ygt + hf, seg


@dataclass
class Tooth:
    z: int
    x: np.ndarray   # the flank (tooth frame), root to tip
    y: np.ndarray
    seg: np.ndarray
    p1: np.ndarray  # polynomial fit of 1/t(y), t = 2 x
    p3: np.ndarray  # polynomial fit of 1/t(y)^3
    tf: float       # root thickness: 2 x at the trochoid's first point, on the root circle


def tooth(z, v, n=4001, degree=8):
    xc, yc, seg = gear_v4(z, M, AO, CF, CK, CC, CH_RACK, CS, n, v.aot)
    # the flank below the tip circle r_k = ro + C_k m (the rack flank generates points beyond
    # it, the thesis' "false points"; the tip circle is the blank's)
    keep = np.isfinite(xc) & (seg >= 1) & (seg <= 3) & (radius(xc, yc, z) <= 0.5 * z * M + CK * M)
    xc, yc, seg = xc[keep], yc[keep], seg[keep]
    order = np.argsort(yc)
    xc, yc, seg = xc[order], yc[order], seg[order]
    # the generated flank is single-valued in y above the root circle (no undercut at z 20);
    # the thickness fits run from the root circle (y = 0) to the tip
    up = yc >= 0.0
    xs, ys = xc[up], yc[up]
    t = 2.0 * xs
    tf = float(2.0 * xc[seg == 3][np.argmin(yc[seg == 3])])  # the trochoid's first point
    p1 = np.polyfit(ys, 1.0 / t, degree)
    p3 = np.polyfit(ys, 1.0 / t ** 3, degree)
    return Tooth(z, xc, yc, seg, p1, p3, tf)


def radius(x, y, z):
    """The listing's radius of a tooth-frame point: sqrt((y + ro - Cf m)^2 + x^2)."""
    return np.sqrt((y + 0.5 * z * M - CF * M) ** 2 + x ** 2)


def point_at_radius(th, r):
    """The involute point of the flank at the radius r (interpolated along the flank)."""
    inv = th.seg == 2
    rr = radius(th.x[inv], th.y[inv], th.z)
    o = np.argsort(rr)
    return np.interp(r, rr[o], th.x[inv][o]), np.interp(r, rr[o], th.y[inv][o])


def compliance1(xinv, yinv, z, p1, p3, tf, n, fix_w):
    """The listing's compliance1: bending Cb and foundation Cfnd (and f, Y)."""
    ro = 0.5 * z * M
    to = math.pi * M
    so = CS * to
    rg = ro * math.cos(AO)
    invao = math.tan(AO) - AO
    r = np.sqrt((yinv + ro - CF * M) ** 2 + xinv ** 2)
    a = np.arccos(rg / r)
    inva = np.tan(a) - a
    s = r * (so / ro + 2 * (invao - inva))
    w = s / (2 * r) if fix_w else (0.25 * s) / (math.pi * r)
    f = a - w
    yy = yinv - np.tan(f) * xinv
    i1 = np.empty_like(yy)
    i2 = np.empty_like(yy)
    for i, yi in enumerate(yy):
        dy = yi / (n - 1)
        y = np.linspace(0.0, yi, n)
        q1 = np.polyval(p1, y)
        q1[0] = 0.0
        q3 = np.polyval(p3, y)
        m2 = (y - yi) ** 2 * q3
        m2[0] = 0.0
        i1[i] = q1.sum() * dy
        i2[i] = m2.sum() * dy
    v = 0.3
    cb = 12 * np.cos(f) ** 2 * (i2 + i1 * (0.2 * (1 + v) + np.tan(f) ** 2 / 12))
    aa = 50 / (3 * math.pi)
    bb = (2 * (1 - 2 * v)) / (1 - v)
    cc = 1 + np.tan(f) ** 2 / (2.4 + 2.4 * v)
    xx = yy / tf
    cfnd = (1 - v ** 2) * np.cos(f) ** 2 * (aa * xx ** 2 + bb * xx + (4.82 / math.pi) * cc)
    return cb, cfnd, f, yy


def curv_rad_h1(x, y, yy, z):
    ro = 0.5 * z * M
    rg = ro * math.cos(AO)
    r = np.sqrt((y + ro - CF * M) ** 2 + x ** 2)
    a = np.arccos(rg / r)
    return rg * np.tan(a), np.sqrt((y - yy) ** 2 + x ** 2)


def pmax_hertz(v, e, b, w, rc1, rc2, fix):
    r = (rc1 * rc2) / (rc1 + rc2)
    if fix:
        return np.sqrt((w * e) / (math.pi * b * 2 * (1 - v ** 2) * r))
    return np.sqrt((w * r * e) / (math.pi * b * 2 * (1 - v ** 2)))


def ch(v, e, pmax, rc1, rc2, h1, h2):
    r = (rc1 * rc2) / (rc1 + rc2)
    c = (4 / e) * r * (1 - v ** 2) * pmax
    return (2 / math.pi) * (1 - v ** 2) * (np.log((4 * h1 * h2) / c ** 2) - v / (1 - v))


class Pair:
    """The pair's contact path and the compliance parts along it for one variant."""

    def __init__(self, v, n_path=241, n_int=400):
        self.v = v
        self.t1, self.t2 = tooth(Z1, v), tooth(Z2, v)
        rb1, rb2 = 0.5 * Z1 * M * math.cos(AO), 0.5 * Z2 * M * math.cos(AO)
        ra1, ra2 = 0.5 * Z1 * M + CK * M, 0.5 * Z2 * M + CK * M
        # path of contact on the line of action, from the pinion's root (A) to its tip (D)
        g1 = math.sqrt(ra2 ** 2 - rb2 ** 2) - rb2 * math.tan(AO)  # length A -> pitch point
        g2 = math.sqrt(ra1 ** 2 - rb1 ** 2) - rb1 * math.tan(AO)  # pitch point -> D
        self.length = g1 + g2
        self.pb = 2 * math.pi * rb1 / Z1
        self.rb1 = rb1
        s = np.linspace(-g1, g2, n_path)  # distance from the pitch point, + towards the pinion tip
        self.s = s
        r1 = np.sqrt(rb1 ** 2 + (rb1 * math.tan(AO) + s) ** 2)
        r2 = np.sqrt(rb2 ** 2 + (rb2 * math.tan(AO) - s) ** 2)
        x1, y1 = point_at_radius(self.t1, r1)
        x2, y2 = point_at_radius(self.t2, r2)
        self.cb1, self.cf1, self.f1, yy1 = compliance1(x1, y1, Z1, self.t1.p1, self.t1.p3, self.t1.tf, n_int, v.w)
        self.cb2, self.cf2, self.f2, yy2 = compliance1(x2, y2, Z2, self.t2.p1, self.t2.p3, self.t2.tf, n_int, v.w)
        self.rc1, self.h1 = curv_rad_h1(x1, y1, yy1, Z1)
        self.rc2, self.h2 = curv_rad_h1(x2, y2, yy2, Z2)
        self.cbf = self.cb1 + self.cf1 + self.cb2 + self.cf2

    def compliance(self, w, idx):
        if not self.v.hertz:
            return self.cbf[idx]
        p = pmax_hertz(NU, E, B, w, self.rc1[idx], self.rc2[idx], self.v.pmax)
        return self.cbf[idx] + ch(NU, E, p, self.rc1[idx], self.rc2[idx], self.h1[idx], self.h2[idx])

    def mesh_cycle(self, n_pos=121):
        """Mesh stiffness [N/m] over one base pitch from the start of contact A: pinion roll
        angle (rad), stiffness, pairs in contact. The load W_TOTAL is shared as 1/C_i with
        the Hertz part at each pair's load (fixed point)."""
        pos = np.linspace(0.0, self.pb, n_pos, endpoint=False)
        k_out, npairs = [], []
        for p in pos:
            # pairs at p, p + pb, ... along the path (distance from A)
            d = [p + j * self.pb for j in range(3) if p + j * self.pb <= self.length + 1e-12]
            idx = [int(round(di / self.length * (len(self.s) - 1))) for di in d]
            w = np.full(len(idx), W_TOTAL / len(idx))
            for _ in range(50):
                c = np.array([self.compliance(wi, ii) for wi, ii in zip(w, idx)])
                w_new = W_TOTAL * (1 / c) / np.sum(1 / c)
                if np.max(np.abs(w_new - w)) < 1e-9 * W_TOTAL:
                    break
                w = w_new
            k_out.append(float(np.sum(E * B / c) * 1e3))
            npairs.append(len(idx))
        return pos / self.rb1, np.array(k_out), np.array(npairs)


def zone_means(k, npairs):
    return float(np.mean(k[npairs == 2])), float(np.mean(k[npairs == 1]))


def thesis_means():
    c1 = np.linspace(0.0, A_SPLIT, 2001)
    c2 = np.linspace(A_SPLIT, PITCH, 2001)
    return float(np.mean(kth1(c1))), float(np.mean(kth2(c2)))


def run(v):
    pair = Pair(v)
    th, k, npairs = pair.mesh_cycle()
    dbl, sgl = zone_means(k, npairs)
    return pair, {"double_mean": dbl, "single_mean": sgl,
                  "double_range": [float(k[npairs == 2].min()), float(k[npairs == 2].max())],
                  "single_range": [float(k[npairs == 1].min()), float(k[npairs == 1].max())]}


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else "."
    os.makedirs(out, exist_ok=True)
    res = {}
    pair0 = pairc = None
    for name, v in VARIANTS.items():
        pair, r = run(v)
        res[name] = r
        if name == "listing":
            pair0 = pair
        if name == "corrected":
            pairc = pair
    d_th, s_th = thesis_means()
    i0 = int(np.argmin(np.abs(pair0.s)))
    parts = {}
    for name, p in (("listing", pair0), ("corrected", pairc)):
        parts[name] = {"Cb1": float(p.cb1[i0]), "Cf1": float(p.cf1[i0]), "Cb2": float(p.cb2[i0]),
                       "Cf2": float(p.cf2[i0]), "CH": float(p.compliance(W_TOTAL, i0) - p.cbf[i0]),
                       "f1": float(p.f1[i0]), "tf1": p.t1.tf, "tf2": p.t2.tf}
    doc = {"thesis": {"double_mean": d_th, "single_mean": s_th,
                      "double_range": [float(kth1(0.0)), 1.269e9], "single_range": [float(kth2(A_SPLIT)), 7.82e8],
                      "contact_ratio": 1 + A_SPLIT / PITCH},
           "contact_ratio": pair0.length / pair0.pb, "load_N": W_TOTAL,
           "variants": res, "pitch_point_parts": parts}
    path = os.path.join(out, "compliance_replica.json")
    with open(path, "w") as f:
        json.dump(doc, f, indent=1)
    print("thesis fits: double %.4g, single %.4g N/m (means)" % (d_th, s_th))
    for name, r in res.items():
        print("%-10s double %.4g (%.3g x thesis)  single %.4g (%.3g x thesis)" % (
            name, r["double_mean"], r["double_mean"] / d_th, r["single_mean"], r["single_mean"] / s_th))
    for name, p in parts.items():
        print(name, "pitch point:", ", ".join("%s %.4g" % kv for kv in p.items()))


if __name__ == "__main__":
    main()
