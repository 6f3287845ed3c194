"""Mesh stiffness over a mesh cycle from the FE, handed to a SciPy solve_ivp model of the dynamic
transmission error, as a ROSS user would (docs/python.md): m x'' + c x' + k(theta) x = F with the
FE's secant mesh stiffness k(theta), so that at low speed x is the FE's static TE."""
import numpy as np
from scipy.integrate import solve_ivp

import gearfem

demo = gearfem.read_input("inputs/demo_fixed_mesh.prm", set={"Solve/Plots": False})
s = gearfem.solve(demo).sweep
roll = np.deg2rad(s["roll angle [deg]"])   # pinion roll over one pitch [rad]
k = s["k_secant [N/m]"]                    # secant mesh stiffness along the line of action
ste = s["STE [um]"] * 1e-6                 # static TE [m] at the design load
pair = gearfem.pair(demo)
z1 = pair["teeth"][0]
pitch = 2 * np.pi / z1
rb = 1e-3 * pair["base pitch [mm]"] * z1 / (2 * np.pi)  # base radius [m]
J = 0.5 * 7850 * np.pi * rb**4 * 20e-3     # each gear as a steel disc of the base radius [kg m^2]
m_e = J / (2 * rb**2)                      # equivalent mass on the line of action [kg]
F = s["F_n [N]"][0]                        # the design load along the line of action [N]
c = 2 * 0.05 * np.sqrt(k.mean() * m_e)     # 5 % damping


def k_of(theta):
    return np.interp(theta % pitch, roll - roll[0], k, period=pitch)


def rhs(t, y, omega):
    x, v = y
    return [v, (F - c * v - k_of(omega * t) * x) / m_e]


fn = np.sqrt(k.mean() / m_e) / (2 * np.pi)
print(f"mesh natural frequency {fn:.0f} Hz; static TE p-p {np.ptp(ste) * 1e6:.3f} um")
for ratio in (0.05, 0.5, 1.0):
    f_mesh = ratio * fn
    omega = 2 * np.pi * f_mesh / z1          # pinion speed [rad/s]
    T = 80 / f_mesh
    sol = solve_ivp(rhs, (0, T), [F / k.mean(), 0.0], args=(omega,), max_step=1 / (60 * f_mesh), rtol=1e-8)
    x = sol.y[0][sol.t > T / 2]
    print(f"mesh frequency {f_mesh:6.0f} Hz ({ratio:.2f} f_n): dynamic TE p-p {np.ptp(x) * 1e6:.3f} um")
