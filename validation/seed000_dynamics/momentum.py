#!/usr/bin/python3
"""Settled speed of the Gkimisis 2019 2-DOF model from the thesis' initial conditions.

An independent 2-DOF integration (not gearfem): eqs. 4.1-4.2 with a mesh stiffness that is
either constant (`constant`: 19.2 N/(mm um) x b, the analytical table's mean) or
piecewise constant (`zones`: single/double-pair zones of the contact ratio, same mean), backlash with contact loss and back contact, damping 2 zeta sqrt(k m_eq)
only in contact, torques ramped over 100 ms with T_out = T_in R_b2/R_b1, RK4 dt = 1e-5 s for
1 s, and the thesis' initial speeds dw1/dt = n0, dw2/dt = n0 R_b2/R_b1 (eq. 5.2, listing).
Prints the mean pinion speed of the last 0.1 s and the closed form n0 (1+r^4)/(1+r^2).

Usage: momentum.py <n0 rpm> <torque N m> <constant|zones>   (prints `settled speed [rpm] = ...`)
"""
import math
import sys

z1, z2, m, b, rho = 32, 60, 3e-3, 30e-3, 7860.0
alpha = math.radians(20)
R1, R2 = m * z1 / 2, m * z2 / 2                      # operating pitch radii (nominal)
Rg1, Rg2 = R1 * math.cos(alpha), R2 * math.cos(alpha)
I1 = 0.5 * math.pi * R1 ** 4 * b * rho              # eq. 4.3
I2 = 0.5 * math.pi * R2 ** 4 * b * rho
m_eq = I1 * I2 / (I2 * Rg1 ** 2 + I1 * Rg2 ** 2)
eps = 1.726                                         # contact ratio of the pair
kbar = 19.16e6 * b * 1e3                            # N/m (19.16 N/(mm um) x 30 mm)
k_single = kbar / (1 + (eps - 1))                   # k_double = 2 k_single, mean = kbar
backlash = 177e-6
zeta = 0.02
c = 2 * zeta * math.sqrt(kbar * m_eq)
pitch = 2 * math.pi / z1


ZONES = False


def stiffness(theta):
    if not ZONES:
        return kbar
    frac = (theta % pitch) / pitch
    return 2 * k_single if frac < eps - 1 else k_single


def rhs(t, y, T_in, ramp):
    th1, th2, w1, w2 = y
    r = min(1.0, t / ramp)
    x = Rg1 * th1 - Rg2 * th2
    v = Rg1 * w1 - Rg2 * w2
    if x > 0:
        F = stiffness(th1) * x + c * v
    elif x <= -backlash:
        F = stiffness(-th1) * (x + backlash) + c * v
    else:
        F = 0.0
    T_out = T_in * R2 / R1
    return (w1, w2, (T_in * r - Rg1 * F) / I1, (-T_out * r + Rg2 * F) / I2)


def main():
    global ZONES
    n0, T_in = float(sys.argv[1]), float(sys.argv[2])
    if sys.argv[3] not in ("constant", "zones"):
        sys.exit("momentum.py: third argument must be constant or zones")
    ZONES = sys.argv[3] == "zones"
    dt, t_end, ramp = 1e-5, 1.0, 0.1
    w10 = n0 * math.pi / 30
    y = (0.0, 0.0, w10, w10 * R2 / R1)               # eq. 5.2 as the listing codes it
    t, n, acc, cnt, vmax = 0.0, int(round(t_end / dt)), 0.0, 0, 0.0
    for i in range(n):
        k1 = rhs(t, y, T_in, ramp)
        k2 = rhs(t + dt / 2, tuple(a + dt / 2 * b_ for a, b_ in zip(y, k1)), T_in, ramp)
        k3 = rhs(t + dt / 2, tuple(a + dt / 2 * b_ for a, b_ in zip(y, k2)), T_in, ramp)
        k4 = rhs(t + dt, tuple(a + dt * b_ for a, b_ in zip(y, k3)), T_in, ramp)
        y = tuple(a + dt / 6 * (p + 2 * q + 2 * r + s) for a, p, q, r, s in zip(y, k1, k2, k3, k4))
        t += dt
        if t > t_end - 0.1:
            acc += y[2]
            cnt += 1
            vmax = max(vmax, abs(Rg1 * y[2] - Rg2 * y[3]))
    r = z2 / z1
    print(f"initial speeds [rpm] = {n0:g}, {n0 * R2 / R1:g} (kinematic gear speed {n0 * R1 / R2:g})")
    print(f"settled speed [rpm] = {acc / cnt * 30 / math.pi:.6g}")
    print(f"closed form [rpm] = {n0 * (1 + r ** 4) / (1 + r ** 2):.6g}")
    print(f"max relative speed over the last 0.1 s [m/s] = {vmax:.4g} (initial {abs(Rg1 - Rg2 * R2 / R1) * w10:.4g})")
    print(f"final DTE [um] = {(Rg1 * y[0] - Rg2 * y[1]) * 1e6:.4g} (static {T_in / Rg1 / kbar * 1e6:.4g})")


if __name__ == "__main__":
    main()
