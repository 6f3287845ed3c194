#!/usr/bin/python3
"""The NTUA tooth-mass thesis' dynamic model, as its MATLAB listing `model_solve` has it
(README.md, "The thesis' stiffness vector"), and its stiffness written as gearfem mesh tables.

- `model_solve(w1, tmax, n, overwrite)`: the listing line by line in numpy: pitch radii
  r1 = 25 mm, r2 = 50 mm, J1 = 1.445009902188274e-4 + 4.5631e-6, J2 = 0.002312015843501 +
  1.8743e-5 kg m^2, M_in = 100 N m, M_out = 200 N m, zero initial state, fixed-step RK4 with
  h = tmax/n and the stiffness K(i) frozen over step i. The loop
      for i=1:N+1, if c(i)<=a; K=feval(Kth1,c); elseif c(i)>a; K=feval(Kth2,c); end; end
  overwrites the whole vector K on every pass, so the last pass decides: overwrite=True
  reproduces that; overwrite=False is the evident intent K(i) = Kth1(c(i)) or Kth2(c(i)).
- `stiffness(c, overwrite, c_last)`: the thesis' K at c = rem(theta1, pi/10) [N/m].
- `write_table(path, overwrite, c_last)`: T(theta, delta) = r_b1 (K/cos^2 alpha) delta as a
  gearfem mesh table (docs/mesh-tables.md, format version 1). The thesis applies K at the
  pitch radii r = r_b/cos(alpha); at gearfem's base radii the same equations of motion need
  K/cos^2(alpha) along the line of action (the angles are identical, the mesh force is
  K r delta_pitch / r_b).

Besides the listing's run (n = 50000 steps of 1 us), a variant with K at the pinion's actual
angle and 0.25 us steps (not the listing) isolates the difference to gearfem.

Usage: thesis_model.py OUT_DIR   (writes thesis_k_overwrite.h5, thesis_k_intended.h5 and
thesis_runs.json with the replica's figures)
"""
import json
import math
import os
import sys

import numpy as np

ALPHA = math.radians(20)
R1, R2 = 0.025, 0.05
J1 = 1.445009902188274e-04 + 4.5631e-06
J2 = 0.002312015843501 + 1.8743e-05
A_SPLIT, PERIOD = 0.228, math.pi / 10


def kth1(c):
    return 1.269e09 * np.sin(3.174 * c + 1.195)


def kth2(c):
    return 7.82e08 * np.sin(3.957 * c + 6.628)


def rem(x, y):
    """MATLAB rem: x - fix(x/y) y."""
    return x - np.trunc(x / y) * y


def stiffness(c, overwrite, c_last):
    """The K vector of model_solve at c; with the overwrite the branch of the last sample."""
    if overwrite:
        return kth1(c) if c_last <= A_SPLIT else kth2(c)
    return np.where(c <= A_SPLIT, kth1(c), kth2(c))


def model_solve(w1=160.0, tmax=0.05, n=50000, overwrite=True, actual_angle=False):
    """Returns t, theta1, theta2 (vibratory angles [rad]) and c_last of the thesis' run.
    actual_angle=True is not the listing: K at c = rem(w1 t + theta1, pi/10), the pinion's
    actual angle at the step start, as gearfem evaluates the mesh position (the listing
    uses the nominal w1 t)."""
    t = np.linspace(0.0, tmax, n + 1)
    h = tmax / n
    c = rem(w1 * t, PERIOD)
    K = stiffness(c, overwrite, c[-1])
    f = np.array([0.0, 100 / J1, 0.0, -200 / J2])
    x = np.zeros(4)
    w = np.zeros((4, n + 1))
    for i in range(n):  # listing: i = 1..N+1 writes w(:, i+1); the last pass is past tmax
        k = K[i]
        if actual_angle:
            k = float(stiffness(np.array([rem(w1 * t[i] + x[0], PERIOD)]), overwrite, c[-1])[0])
        A = np.array([[0, 1, 0, 0], [-(k * R1**2) / J1, 0, (k * R1 * R2) / J1, 0],
                      [0, 0, 0, 1], [(k * R1 * R2) / J2, 0, -(k * R2**2) / J2, 0]])
        F = lambda y: A @ y + f  # noqa: E731
        k1 = h * F(x)
        k2 = h * F(x + k1 / 2)
        k3 = h * F(x + k2 / 2)
        k4 = h * F(x + k3)
        x = x + (k1 + 2 * k2 + 2 * k3 + k4) / 6
        w[:, i + 1] = x
    return t, w[0], w[2], float(c[-1])


def half_p2p(v):
    return 0.5 * float(np.max(v) - np.min(v))


def write_table(path, overwrite, c_last, n_theta=2048):
    import h5py
    rb1 = R1 * math.cos(ALPHA)
    theta = PERIOD * np.arange(n_theta) / n_theta
    delta = np.array([0.0, 1e-4])  # T is linear in delta: two nodes are exact
    K = stiffness(theta, overwrite, c_last) / math.cos(ALPHA) ** 2
    T = rb1 * K[:, None] * delta[None, :]
    with h5py.File(path, "w") as f:
        f.attrs["format"] = "gearfem-mesh-table"
        f.attrs["format_version"] = 1
        f.attrs["geometry_hash"] = ""
        f.attrs["source"] = ("validation/seed004_dynamics/thesis_model.py: NTUA tooth-mass thesis model_solve K "
                             + ("after the loop's overwrite (Kth1 over the whole period)" if overwrite else
                                "as intended (Kth1 for c <= 0.228, Kth2 above)") + ", divided by cos^2(alpha)")
        f.attrs["created"] = "2026-11-26T00:00:00Z"
        g = f.create_group("table")
        g.attrs["period"] = PERIOD
        g.attrs["base_radius"] = rb1
        g.attrs["valid_min"] = 0.0
        g.attrs["valid_max"] = float(delta[-1])
        g.create_dataset("theta", data=theta).attrs["unit"] = "rad"
        g.create_dataset("delta", data=delta).attrs["unit"] = "m"
        v = g.create_dataset("values", data=T)
        v.attrs["unit"] = "N*m"
        v.attrs["quantity"] = "torque"


def closed_form(K):
    """Constant-K step response: theta1 = A (1 - cos w t), theta2 = -(r2 J1/(r1 J2)) theta1,
    A = M_in m_eq/(J1 K), m_eq = J1 J2/(J2 r1^2 + J1 r2^2) (pitch radii, as the thesis)."""
    meq = J1 * J2 / (J2 * R1**2 + J1 * R2**2)
    A = 100 * meq / (J1 * K)
    return A, A * R2 * J1 / (R1 * J2)


def main():
    out = sys.argv[1]
    os.makedirs(out, exist_ok=True)
    res = {}
    f_mesh = 20 * 160 / (2 * math.pi)
    t_win = 25 / f_mesh  # the gearfem record: 25 mesh periods (49.1 ms of the thesis' 50 ms)
    for name, ow in (("overwrite", True), ("intended", False)):
        t, th1, th2, c_last = model_solve(overwrite=ow)
        first = t <= 1e-4  # the first swing (about one natural period, 79 us)
        win = t <= t_win + 1e-12
        res[name] = {"c_last": c_last, "theta1_first": half_p2p(th1[first]), "theta2_first": half_p2p(th2[first]),
                     "theta1_25": half_p2p(th1[win]), "theta2_25": half_p2p(th2[win]),
                     "theta1_mean_25": float(np.mean(th1[win]))}
        # The explanation of the remaining difference to gearfem: K at the actual angle, and
        # h = 0.25 us (the listing's K is frozen over each 1 us step).
        t, th1, th2, _ = model_solve(n=200000, overwrite=ow, actual_angle=True)
        win = t <= t_win + 1e-12
        res[name].update({"actual_theta1_25": half_p2p(th1[win]), "actual_theta2_25": half_p2p(th2[win])})
        write_table(os.path.join(out, f"thesis_k_{name}.h5"), ow, c_last)
    # The mean of the stiffness the thesis ran, over one period, and its closed forms.
    c = PERIOD * (np.arange(100000) + 0.5) / 100000
    for name, ow in (("overwrite", True), ("intended", False)):
        Kbar = float(np.mean(stiffness(c, ow, res["overwrite"]["c_last"])))
        A1, A2 = closed_form(Kbar)
        res[name].update({"K_mean": Kbar, "closed_theta1": A1, "closed_theta2": A2})
    # The 600 rpm run (20 pi rad/s for 50 ms): c_last = rem(pi, pi/10) = 0 <= a keeps Kth1.
    res["c_last_600rpm"] = float(rem(600 * 2 * math.pi / 60 * 0.05, PERIOD))
    with open(os.path.join(out, "thesis_runs.json"), "w") as f:
        json.dump(res, f, indent=1)
    print(json.dumps(res, indent=1))


if __name__ == "__main__":
    main()
