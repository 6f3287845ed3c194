#!/usr/bin/python3
"""Closed-form statics and deflection of a statically determinate stepped shaft, independent of
lib/ (validation/system_deflection/README.md).

A shaft runs along z from 0 to its length, made of segments (length, outer and inner diameter).
It sits on two radially rigid supports (no tilting stiffness), one of them axially rigid, and is
held in torsion at one station. Point forces F = (F_x, F_y, F_z) and couples C = (C_x, C_y, C_z)
act at stations z_i. The reactions follow from statics; the deflection from the bending-moment
line integrated exactly over every piece between stations (the moment is linear there and the
section constant):

- xz-plane: EI u_x'' = M_x(z),  M_x(z) = sum_{z_j < z} [F_x,j (z - z_j) - C_y,j]  (reactions
  included), so that the far end is moment-free; the shear adds u_x,s' = -M_x'/(kappa G A);
  the section's rotation theta_y = u_x' - gamma_x (the slope of the bending part);
- yz-plane: EI u_y'' = M_y(z),  M_y(z) = sum_{z_j < z} [F_y,j (z - z_j) + C_x,j],
  theta_x = -(u_y' - gamma_y);
- axial: EA u_z' = -N(z),  N(z) = sum_{z_j < z} F_z,j;  torsion: GJ theta_z' = -T(z),
  T(z) = sum_{z_j < z} C_z,j;
- u_x = u_y = 0 at both supports, u_z = 0 at the axial support, theta_z = 0 where torsion is held.

kappa is Cowper's shear coefficient of a (hollow) circle, 6(1+nu)(1+m^2)^2 / ((7+6nu)(1+m^2)^2 +
(20+12nu) m^2), m = bore/outer diameter (Cowper, J. Appl. Mech. 33, 1966, table 1). Units: SI.
"""
import math


class Shaft:
    def __init__(self, segments, E, nu):
        """segments: [(length, outer, inner)] in m; E in Pa."""
        self.segments = segments
        self.E, self.nu = E, nu
        self.G = E / (2 * (1 + nu))
        self.ends = [0.0]
        for L, _, _ in segments:
            self.ends.append(self.ends[-1] + L)

    @property
    def length(self):
        return self.ends[-1]

    def section(self, z):
        """(A, I, J, kappa) of the segment that holds the open piece around z."""
        for k, (L, D, d) in enumerate(self.segments):
            if z <= self.ends[k + 1] or k == len(self.segments) - 1:
                A = math.pi / 4 * (D * D - d * d)
                I = math.pi / 64 * (D**4 - d**4)
                m2 = (d / D) ** 2
                nu = self.nu
                kappa = 6 * (1 + nu) * (1 + m2) ** 2 / ((7 + 6 * nu) * (1 + m2) ** 2 + (20 + 12 * nu) * m2)
                return A, I, 2 * I, kappa
        raise ValueError(z)


def reactions(supports, axial_at, torsion_at, loads):
    """Reaction forces and couples of two radial supports z_a < z_b (axial and torsional ones at
    the named stations) under loads [(z, F(3), C(3))]: [(z, F, C)] for the supports."""
    za, zb = supports
    L = zb - za
    R = {za: [0.0, 0.0, 0.0, 0.0, 0.0, 0.0], zb: [0.0, 0.0, 0.0, 0.0, 0.0, 0.0]}
    sum_f = [sum(l[1][i] for l in loads) for i in range(3)]
    # Moment balance about z_a of the xz- and yz-planes, in the M_x, M_y convention above:
    # far-end moment sum_j F_x,j (z_end - z_j) - sum_j C_y,j = 0 with sum F_x = 0, i.e.
    # sum_j F_x,j z_j + sum_j C_y,j = 0;  yz: sum_j F_y,j z_j - sum_j C_x,j = 0.
    mx = sum(l[1][0] * (l[0] - za) + l[2][1] for l in loads)
    my = sum(l[1][1] * (l[0] - za) - l[2][0] for l in loads)
    R[zb][0] = -mx / L
    R[za][0] = -sum_f[0] - R[zb][0]
    R[zb][1] = -my / L
    R[za][1] = -sum_f[1] - R[zb][1]
    R[axial_at][2] = -sum_f[2]
    R[torsion_at][5] = -sum(l[2][2] for l in loads)
    return [(z, R[z][:3], R[z][3:]) for z in (za, zb)]


def deflection(shaft, supports, axial_at, torsion_at, loads, stations):
    """Displacements and rotations (u_x, u_y, u_z, theta_x, theta_y, theta_z) at `stations` and
    the support reactions, for loads [(z, F, C)] on a shaft (SI)."""
    rs = reactions(supports, axial_at, torsion_at, loads)
    allp = list(loads) + [(z, F, C) for z, F, C in rs]
    cuts = sorted(set([0.0, shaft.length] + [p[0] for p in allp] + list(stations) + shaft.ends))
    # Integrate from z = 0 with zero start values, then add the rigid-body line the supports fix.
    state = dict(ux=0.0, dux=0.0, uy=0.0, duy=0.0, sx=0.0, sy=0.0, uz=0.0, tz=0.0)
    at = {}

    def loads_left(z):
        """Moments, shears, normal force and torque just right of z (loads at z_j <= z)."""
        Mx = My = Vx = Vy = N = T = 0.0
        for zj, F, C in allp:
            if zj <= z:
                Mx += F[0] * (z - zj) - C[1]
                My += F[1] * (z - zj) + C[0]
                Vx += F[0]
                Vy += F[1]
                N += F[2]
                T += C[2]
        return Mx, My, Vx, Vy, N, T

    def record(z):
        at[z] = dict(state)

    record(cuts[0])
    for a, b in zip(cuts[:-1], cuts[1:]):
        h = b - a
        if h <= 0:
            continue
        A, I, J, kappa = shaft.section(0.5 * (a + b))
        E, G = shaft.E, shaft.G
        Mx, My, Vx, Vy, N, T = loads_left(a + 0.0)
        # On (a, b): M = M(a+) + V (z - a), linear; EI u'' = M.
        for u, du, M, V, s in (("ux", "dux", Mx, Vx, "sx"), ("uy", "duy", My, Vy, "sy")):
            state[u] += state[du] * h + (M * h * h / 2 + V * h**3 / 6) / (E * I)
            state[du] += (M * h + V * h * h / 2) / (E * I)
            state[s] += -V * h / (kappa * G * A)  # shear deflection, u_s' = -M'/(kappa G A)
        state["uz"] += -N * h / (E * A)
        state["tz"] += -T * h / (G * J)
        record(b)

    za, zb = supports

    def line(key_u, key_s):
        ua, ub = at[za][key_u] + at[za][key_s], at[zb][key_u] + at[zb][key_s]
        slope = (ub - ua) / (zb - za)
        return ua, slope

    cx, kx = line("ux", "sx")
    cy, ky = line("uy", "sy")
    out = []
    for z in stations:
        s = at[z]
        A, I, J, kappa = shaft.section(z)
        ux = s["ux"] + s["sx"] - cx - kx * (z - za)
        uy = s["uy"] + s["sy"] - cy - ky * (z - za)
        ty = s["dux"] - kx          # bending slope of the xz-plane
        tx = -(s["duy"] - ky)
        uz = s["uz"] - at[axial_at]["uz"]
        tz = s["tz"] - at[torsion_at]["tz"]
        out.append((ux, uy, uz, tx, ty, tz))
    return out, rs
