#!/usr/bin/python3
"""Gkimisis 2019, its dynamic listing ("Αλγόριθμος Δυναμικής Προσομοίωσης", Appendix) replicated
in numpy from the thesis' text, independent of gearfem: the geometric model's torque tables
(listing_geometry.py), the listing's inertias (solid discs of the operating pitch radii),
Kmean = mean(Ktotal) of the table's last entry, damping 2 0.02 epsilon R_g sqrt(Kmean m_x),
torques ramped over t_res = T_tot/10 and then held, x(0) = 0, dx/dt(0) = 0, dw1/dt(0) = n0,
dw2/dt(0) = n0 R_b2/R_b1, the pinion angle wrapped into one pitch about the middle of AB at
every stage, the contact state s (1, 0, -1 with the reverse-flank mapping phit1 - p1) taken
from x at every stage, fixed-step RK4 with dt = 1e-5 s over T_tot = 1 s, MATLAB interp2
(bilinear) of the tables.

All runs integrate at once (numpy over runs). Each ingredient the text leaves open is switched
per run (SETUPS): the initial gear speed (as coded, or the kinematic ratio of eq. 5.2's
intent), the step (1e-5 s of the listing, 1/60000 s), the ramp (100 ms of the listing, 10 ms),
the damping (with the listing's factor epsilon, or eq. 4.x without it) and the torque of the
a12 + 1 mm run (40 N m of the caption of Fig. 26, 20 N m).

Classification as check.py does for gearfem (its `outcome`): contact loss = a fraction of the
record with -b12 < x <= 0 above zero; period = the smallest lag p in 1..4 with which the
Poincaré samples (x, x' T/2pi, once per mesh pitch of the pinion angle) of the record repeat
within PERIOD_TOL of the record's peak-to-peak (0: none). Record: the last 0.25 s.

Usage: listing_replica.py <out dir>   (writes <out>/listing_replica.csv, listing_replica.json)
"""
import csv
import itertools
import json
import math
import os
import sys
import time

import numpy as np

import listing_geometry as lg

T_TOT, RECORD_S, PERIOD_TOL = 1.0, 0.25, 0.02
CASES = (  # name, T_in [N m], n0 [rpm], centre distance change [mm]
    ("case1_5Nm_600rpm", 5.0, 600.0, 0.0),
    ("case2_20Nm_1200rpm", 20.0, 1200.0, 0.0),
    ("case3_40Nm_1200rpm", 40.0, 1200.0, 0.0),
    ("case4_40Nm_1200rpm_a+1mm", 40.0, 1200.0, 1.0),
)
# ingredient: (the listing's value, the alternatives)
INGREDIENTS = {
    "ics": ("coded", ("kinematic",)),        # dw2/dt(0) = n0 Rb2/Rb1 (coded) or n0 Rb1/Rb2
    "dt": (1e-5, (1 / 60000,)),
    "ramp": (0.1, (0.01,)),
    "damping": ("epsilon", ("plain",)),      # 2 zeta eps sqrt(K m) (listing) or 2 zeta sqrt(K m)
    "case4_torque": (40.0, (20.0,)),
}


def setups():
    """Every combination of the ingredients (the listing's set-up first)."""
    keys = list(INGREDIENTS)
    values = [(INGREDIENTS[k][0],) + INGREDIENTS[k][1] for k in keys]
    return [dict(zip(keys, combo)) for combo in itertools.product(*values)]


class Tables:
    """The geometric model per centre distance: stacked torque tables and pair constants."""

    def __init__(self, changes):
        self.geo, self.tab = {}, {}
        for da in changes:
            g = lg.geometry(da)
            self.geo[da], self.tab[da] = g, lg.torque_table(g)

    def constants(self, da):
        g, t = self.geo[da], self.tab[da]
        rho, b = 7.86e3, 30.0
        m1 = math.pi * g["Rb1"] ** 2 * b * rho / 1e9
        m2 = math.pi * g["Rb2"] ** 2 * b * rho / 1e9
        I1, I2 = 0.5 * m1 * g["Rb1"] ** 2 / 1e6, 0.5 * m2 * g["Rb2"] ** 2 / 1e6
        mx = I1 * I2 / (I2 * (g["Rg1"] / 1e3) ** 2 + I1 * (g["Rg2"] / 1e3) ** 2)
        return dict(I1=I1, I2=I2, mx=mx, Kmean=t["Kmean"], fn=math.sqrt(t["Kmean"] / mx) / 2 / math.pi)


def build_runs(tables):
    runs = []
    for s in setups():
        for name, T, n0, da in CASES:
            if da and s["case4_torque"] != INGREDIENTS["case4_torque"][0]:
                T = s["case4_torque"]
            elif not da and s["case4_torque"] != INGREDIENTS["case4_torque"][0]:
                continue  # the case-4 torque switch changes case 4 only
            runs.append(dict(case=name, T=T, n0=n0, da=da, **s))
    return runs


def _bilinear(tab, x, p):
    """interp2(STE, POS1, MELG1/2, x, p) for runs that share one table."""
    P, S = tab["POS1"], tab["STE"]
    fi = (p - P[0]) / (P[1] - P[0])
    i = np.clip(np.floor(fi).astype(int), 0, P.size - 2)
    u = fi - i
    j = np.clip(np.searchsorted(S, x, side="right") - 1, 0, S.size - 2)
    w = (x - S[j]) / (S[j + 1] - S[j])
    out = []
    for M in (tab["MELG1"], tab["MELG2"]):
        out.append((1 - u) * ((1 - w) * M[i, j] + w * M[i, j + 1]) + u * ((1 - w) * M[i + 1, j] + w * M[i + 1, j + 1]))
    return out


class Batch:
    """Runs sharing one time step, integrated together as the listing's RK4."""

    def __init__(self, tables, runs):
        self.tables, self.runs = tables, runs
        n = len(runs)
        col = lambda f: np.array([f(r) for r in runs], dtype=float)  # noqa: E731
        self.da = col(lambda r: r["da"])
        self.groups = {da: np.flatnonzero(self.da == da) for da in sorted(set(self.da))}
        geo = lambda k: col(lambda r: tables.geo[r["da"]][k])  # noqa: E731
        con = lambda k: col(lambda r: tables.constants(r["da"])[k])  # noqa: E731
        self.Rg1, self.Rg2, self.blsh, self.w20 = geo("Rg1"), geo("Rg2"), geo("blsh"), geo("w20")
        self.phit1 = col(lambda r: tables.geo[r["da"]]["g1"]["phit"])
        self.top = col(lambda r: (tables.geo[r["da"]]["w1LoA2"] + tables.geo[r["da"]]["w1LoA1"]) / 2 + math.pi / lg.Z1)
        self.I1, self.I2, mx, Km = con("I1"), con("I2"), con("mx"), con("Kmean")
        eps = geo("epsilon") * col(lambda r: r["damping"] == "epsilon") + col(lambda r: r["damping"] != "epsilon")
        self.C1 = 2 * 0.02 * eps * self.Rg1 / 1e3 * np.sqrt(Km * mx) / 1e3
        self.C2 = 2 * 0.02 * eps * self.Rg2 / 1e3 * np.sqrt(Km * mx) / 1e3
        Rb1, Rb2 = geo("Rb1"), geo("Rb2")
        self.M1c = col(lambda r: r["T"])
        self.M2c = self.M1c * Rb2 / Rb1
        self.tres = col(lambda r: r["ramp"])
        w10 = col(lambda r: r["n0"]) * math.pi / 30
        coded = col(lambda r: r["ics"] == "coded").astype(bool)
        self.state0 = (np.zeros(n), self.w20.copy(), w10, np.where(coded, w10 * Rb2 / Rb1, w10 * Rb1 / Rb2))
        self.pitch1, self.pitch2 = 2 * math.pi / lg.Z1, 2 * math.pi / lg.Z2

    def wrap(self, p1, p2):
        k = np.floor((self.top - p1) / self.pitch1)
        return p1 + k * self.pitch1, p2 + k * self.pitch2

    def forces(self, x, p1):
        """State s and elastic torques (Mel1, Mel2) from x and the wrapped pinion angle."""
        ss = np.where(x > 0, 1.0, np.where(x <= -self.blsh, -1.0, 0.0))
        pR = self.phit1 - p1
        pR = pR + np.floor((self.top - pR) / self.pitch1) * self.pitch1
        pR1 = np.where(ss < 0, pR, p1)
        xR = np.where(ss > 0, x, np.where(ss < 0, -(x + self.blsh), 0.0))
        M1, M2 = np.zeros_like(x), np.zeros_like(x)
        for da, idx in self.groups.items():
            a, b = _bilinear(self.tables.tab[da], xR[idx], pR1[idx])
            M1[idx], M2[idx] = a, b
        on = ss != 0
        return ss, np.where(on, M1, 0.0), np.where(on, M2, 0.0)

    def accel(self, M1, M2, x, dxdt, p1):
        ss, Mel1, Mel2 = self.forces(x, p1)
        a1 = (M1 - np.abs(ss) * self.C1 * dxdt - ss * Mel1) / self.I1
        a2 = (-M2 + np.abs(ss) * self.C2 * dxdt + ss * Mel2) / self.I2
        return a1, a2, ss

    def run(self, dt, label=""):
        n = len(self.runs)
        NN = int(round(T_TOT / dt)) + 1
        nrec = int(round(RECORD_S / dt))
        p1, p2, w1, w2 = (a.copy() for a in self.state0)
        x, dxdt = np.zeros(n), np.zeros(n)
        M1, M2 = np.zeros(n), np.zeros(n)
        rec = {k: np.zeros((nrec, n)) for k in ("x", "v", "theta", "ss")}
        theta = np.zeros(n)
        t0 = time.perf_counter()
        for k in range(NN):
            t = k * dt
            ramp = t < self.tres
            M1 = np.where(ramp, self.M1c * t / self.tres, M1)
            M2 = np.where(ramp, self.M2c * t / self.tres, M2)
            p1, p2 = self.wrap(p1, p2)
            w1o, w2o, p1o, p2o = w1, w2, p1, p2
            K = []
            for stage, frac in enumerate((0.5, 0.5, 1.0, None)):
                a1, a2, ss = self.accel(M1, M2, x, dxdt, p1)
                K.append((dt * a1, dt * a2, dt * w1, dt * w2))
                if frac is not None:
                    w1, w2 = w1o + K[-1][0] * frac, w2o + K[-1][1] * frac
                    p1, p2 = p1o + K[-1][2] * frac, p2o + K[-1][3] * frac
                else:
                    comb = [(K[0][i] + 2 * K[1][i] + 2 * K[2][i] + K[3][i]) / 6 for i in range(4)]
                    w1, w2 = w1o + comb[0], w2o + comb[1]
                    p1, p2 = p1o + comb[2], p2o + comb[3]
                    theta = theta + comb[2]
                p1, p2 = self.wrap(p1, p2)
                x = p1 * self.Rg1 - (p2 - self.w20) * self.Rg2
                dxdt = w1 * self.Rg1 - w2 * self.Rg2
            r = k - (NN - nrec)
            if r >= 0:
                rec["x"][r], rec["v"][r], rec["theta"][r], rec["ss"][r] = x, dxdt, theta, ss
            if k % 10000 == 0 and k:
                print(f"  {label}: t = {t:.2f} s of {T_TOT:g} s ({time.perf_counter() - t0:.0f} s)", flush=True)
        rec["w1_end"] = w1
        return rec


def classify(x, v, theta, ss, blsh, pitch=2 * math.pi / lg.Z1):
    """Loss / back-contact fractions, Poincaré period and cycle-to-cycle change of one record."""
    loss = float(np.mean((x <= 0) & (x > -blsh)))
    back = float(np.mean(x <= -blsh))
    k0 = math.ceil(theta[0] / pitch)
    marks = np.arange(k0, math.floor(theta[-1] / pitch) + 1) * pitch
    xs, vs = np.interp(marks, theta, x), np.interp(marks, theta, v)
    tm = RECORD_S / max(marks.size, 1)                      # mean mesh period of the record
    vs = vs * tm / (2 * math.pi)
    p2p = float(x.max() - x.min()) or 1e-300
    changes = {}
    for p in (1, 2, 3, 4):
        if xs.size <= p + 8:
            changes[p] = math.inf
            continue
        d = np.maximum(np.abs(xs[p:] - xs[:-p]), np.abs(vs[p:] - vs[:-p]))
        changes[p] = float(d[-32:].max() / p2p)
    period = next((p for p in (1, 2, 3, 4) if changes[p] <= PERIOD_TOL and (p == 1 or changes[1] > 1e-3)), 0)
    return dict(loss=loss, back=back, period=period, change1=changes[1], change2=changes[2], p2p_um=p2p * 1e3,
                rms_um=float(np.std(x)) * 1e3, mean_um=float(np.mean(x)) * 1e3,
                speed_rpm=float((theta[-1] - theta[0]) / (RECORD_S - 0) * 30 / math.pi))


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(os.path.abspath(__file__)), "results")
    os.makedirs(out, exist_ok=True)
    t0 = time.perf_counter()
    tables = Tables(sorted({c[3] for c in CASES}))
    runs = build_runs(tables)
    print(f"geometric model tables built ({time.perf_counter() - t0:.1f} s); {len(runs)} runs")
    rows = []
    for dt in sorted({r["dt"] for r in runs}, reverse=True):
        sel = [r for r in runs if r["dt"] == dt]
        batch = Batch(tables, sel)
        rec = batch.run(dt, label=f"dt = {dt:.3g} s, {len(sel)} runs")
        for i, r in enumerate(sel):
            c = classify(rec["x"][:, i], rec["v"][:, i], rec["theta"][:, i], rec["ss"][:, i], batch.blsh[i])
            rows.append({**r, **c})
    fields = list(rows[0])
    with open(os.path.join(out, "listing_replica.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=fields)
        w.writeheader()
        w.writerows(rows)
    info = {}
    for da in tables.geo:
        g, cst = tables.geo[da], tables.constants(da)
        info[f"{da:g}"] = dict(epsilon=g["epsilon"], blsh_mm=g["blsh"], Rk1=g["g1"]["Rk"], Rk2=g["g2"]["Rk"],
                               AB_deg=[math.degrees(g["w1LoA1"]), math.degrees(g["w1LoA2"])], **cst)
    with open(os.path.join(out, "listing_replica.json"), "w") as f:
        json.dump(info, f, indent=1)
    for r in rows:
        print(f"{r['case']:26s} T {r['T']:4g} ics {r['ics']:9s} dt {r['dt']:.3g} ramp {r['ramp']:g} "
              f"damp {r['damping']:7s}: loss {r['loss']:.3f} back {r['back']:.3f} period {r['period']} "
              f"(change {r['change1']:.2g}/{r['change2']:.2g}) speed {r['speed_rpm']:.0f} rpm")
    print(f"listing replica: {len(rows)} runs in {time.perf_counter() - t0:.0f} s")


if __name__ == "__main__":
    main()
