#!/usr/bin/python3
"""Write a gearfem mesh-table file (docs/mesh-tables.md, format version 1) with h5py, as an
independent writer for the CLI checks of `gearfem dynamics` (Law = table file).

Usage: write_mesh_table.py OUT.h5 VARIANT
  The pair is the Parker pair (z1 50, m 3 mm, alpha 20 deg): period 2 pi/50, r_b1 = 75 cos 20 mm.
  T(theta, delta) = r_b1 k(theta) delta with k = 5e8 N/m (1 + a cos(50 theta)),
  32 positions x 16 compressions from 0 to 50 um.
  VARIANT: constant (a = 0) | ripple (a = 0.1) | bad_unit (values in N*mm) |
           no_delta (the delta axis is missing) | hash (geometry hash "0123456789abcdef") |
           two_sided (format version 2: constant k0 on both flanks, backlash 100 um, so delta
           runs from -150 um to 50 um with T = 0 on [-100, 0] um)
"""
import math
import sys

import h5py
import numpy as np

out, variant = sys.argv[1], sys.argv[2]
z1, rb1, k0 = 50, 0.075 * math.cos(math.radians(20)), 5e8
a = 0.1 if variant == "ripple" else 0.0
period = 2 * math.pi / z1
theta = -0.5 * period + period * np.arange(32) / 32
delta = 50e-6 * np.arange(16) / 15
T = rb1 * k0 * (1 + a * np.cos(z1 * theta))[:, None] * delta[None, :]
b = 100e-6
if variant == "two_sided":
    delta = np.concatenate([-b - delta[::-1], delta])
    delta[len(delta) // 2 - 1] = -b
    T = rb1 * k0 * np.where(delta > 0, delta, np.where(delta < -b, delta + b, 0.0))[None, :] * np.ones((32, 1))
with h5py.File(out, "w") as f:
    f.attrs["format"] = "gearfem-mesh-table"
    f.attrs["format_version"] = 2 if variant == "two_sided" else 1
    f.attrs["geometry_hash"] = "0123456789abcdef" if variant == "hash" else ""
    f.attrs["source"] = "tests/regression/write_mesh_table.py " + variant
    f.attrs["created"] = "2026-11-21T00:00:00Z"
    g = f.create_group("table")
    g.attrs["period"] = period
    g.attrs["base_radius"] = rb1
    g.attrs["valid_min"] = float(delta[0])
    if variant == "two_sided":
        g.attrs["backlash"] = b
    g.attrs["valid_max"] = float(delta[-1])
    g.create_dataset("theta", data=theta).attrs["unit"] = "rad"
    if variant != "no_delta":
        g.create_dataset("delta", data=delta).attrs["unit"] = "m"
    v = g.create_dataset("values", data=T * (1e3 if variant == "bad_unit" else 1.0))
    v.attrs["unit"] = "N*mm" if variant == "bad_unit" else "N*m"
    v.attrs["quantity"] = "torque"
