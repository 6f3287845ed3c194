#!/usr/bin/python3
"""Round trip of `gearfem export` (docs/export.md): sources written here with h5py
(independently of lib/io), exported by gearfem, read back with numpy/json/csv only and
compared with the source re-interpolated here.

    export_roundtrip.py GEARFEM SRC_DIR

Pair: inputs/demo_fixed_mesh.prm (Parker 50/50, m 3, standard, a = 150 mm). Sources:
  tt1  one-sided torque table T = r_b1 k0 (1 + a cos z1 theta) (delta + delta^2/d0), 48 x 25
  tt2  the same, two-sided (format 2), backlash 80 um, its own back branch
  kt   stiffness table k(theta, F) = k0 (1 + a cos z1 theta)(1 + F/F0), 48 x 9
  sr   results.h5 of a one-cycle sweep (40 positions from A, 2 torques)
  hunt results.h5 of a 3-pitch sweep (120 positions from A)
Tolerances: copies 1e-12 (relative to the largest value of the table); the back-contact branch
mapped from a one-sided table against the analytic source within the linear-interpolation
bound h^2/8 max|d2T/dtheta2| (h the theta step).
"""
import csv
import json
import math
import os
import re
import shutil
import subprocess
import sys
import tempfile

import h5py
import numpy as np

gearfem, src = sys.argv[1], sys.argv[2]
work = tempfile.mkdtemp(prefix="gearfem_export_")
z1, rb1 = 50, 0.075 * math.cos(math.radians(20))
period = 2 * math.pi / z1
k0, a, d0, F0 = 4e8, 0.15, 20e-6, 5000.0
fails = []


def check(name, ok, detail=""):
    print(("PASS " if ok else "FAIL ") + name + (": " + detail if detail else ""))
    if not ok:
        fails.append(name)


def rel_err(x, y):
    x, y = np.asarray(x, float), np.asarray(y, float)
    return float(np.max(np.abs(x - y)) / max(np.max(np.abs(y)), 1e-300))


def geometry_lines():
    lines, keep = [], False
    for line in open(os.path.join(src, "inputs", "demo_fixed_mesh.prm")):
        if line.startswith("subsection Material"):
            break
        if line.startswith("subsection Rack"):
            keep = True
        if keep:
            lines.append(line)
    return "".join(lines)


def run_export(name, entries, expect=0):
    prm = os.path.join(work, name + ".prm")
    with open(prm, "w") as f:
        f.write(geometry_lines() + "subsection Export\n" + "".join(f"  set {k} = {v}\n" for k, v in entries.items()) + "end\n")
    out = os.path.join(work, "out_" + name)
    p = subprocess.run([gearfem, "export", prm, "--output-dir", out], capture_output=True, text=True)
    if p.returncode != expect:
        print(p.stdout, p.stderr)
    check(f"{name}: exit status {expect}", p.returncode == expect, f"got {p.returncode}")
    return out, p


def theta_grid(n, start):
    return start + period * np.arange(n) / n


def write_table(path, kind, theta, second, values, hsh, backlash=None):
    with h5py.File(path, "w") as f:
        f.attrs["format"] = "gearfem-mesh-table"
        f.attrs["format_version"] = 2 if backlash is not None else 1
        f.attrs["geometry_hash"] = hsh
        f.attrs["source"] = "tests/regression/export_roundtrip.py"
        f.attrs["created"] = "2026-11-21T00:00:00Z"
        g = f.create_group("table")
        g.attrs.update(period=period, base_radius=rb1, valid_min=second[0], valid_max=second[-1])
        if backlash is not None:
            g.attrs["backlash"] = backlash
        g.create_dataset("theta", data=theta).attrs["unit"] = "rad"
        name, unit = {"torque": ("delta", "m"), "stiffness": ("load", "N")}[kind]
        g.create_dataset(name, data=second).attrs["unit"] = unit
        v = g.create_dataset("values", data=values)
        v.attrs.update(unit={"torque": "N*m", "stiffness": "N/m"}[kind], quantity=kind)


def write_results(path, theta_deg, torques, ste_um, hsh):
    with h5py.File(path, "w") as f:
        f.attrs.update(format="gearfem-solve-results", format_version="1", program="export_roundtrip.py",
                       geometry_hash=hsh, method="none", input="none")
        g = f.create_group("sweep")
        T = np.repeat(torques, len(theta_deg))
        g["torque [N m]"] = T
        g["position [-]"] = np.tile(np.arange(len(theta_deg)), len(torques)).astype(float)
        g["roll angle [deg]"] = np.tile(theta_deg, len(torques))
        g["STE [um]"] = ste_um.T.reshape(-1)
        g["F_n [N]"] = T / rb1


def torque_fn(theta, delta):
    return rb1 * k0 * (1 + a * np.cos(z1 * theta))[:, None] * (delta + delta ** 2 / d0)[None, :]


def read_csv(path):
    with open(path) as f:
        r = list(csv.reader(f))
    return r[0], np.array([[float(x) for x in row] for row in r[1:]])


def periodic_interp(x, y, per, xq):
    xs = np.concatenate([x, [x[0] + per]])
    ys = np.concatenate([y, [y[0]]])
    return np.interp(x[0] + np.mod(np.asarray(xq) - x[0], per), xs, ys)


# --- the geometry hash of the demo pair: a probe table with a foreign hash is refused, and the
# message names the expected hash (read_mesh_table: "allowed: <hash>").
theta48, delta25 = theta_grid(48, -0.37 * period), np.linspace(0.0, 60e-6, 25)
write_table(os.path.join(work, "probe.h5"), "torque", theta48, delta25, torque_fn(theta48, delta25), "probe")
_, p = run_export("probe", {"Source": os.path.join(work, "probe.h5"), "Source kind": "mesh table", "Torques": "100"}, 2)
m = re.search(r"allowed: ([0-9a-f]{16})", p.stderr)
check("probe: the refusal names the expected geometry hash", m is not None, p.stderr.strip())
if m is None:
    sys.exit(1)
hsh = m.group(1)
theta_A_expected = None

# --- 1. one-sided torque table: grid by inversion, ROSS, spline, TE, force with Backlash.
T1 = torque_fn(theta48, delta25)
write_table(os.path.join(work, "tt1.h5"), "torque", theta48, delta25, T1, hsh)
torques = [100.0, 250.0, 400.0]
out, _ = run_export("tt1", {"Source": os.path.join(work, "tt1.h5"), "Source kind": "mesh table",
                            "Torques": "100, 250, 400", "Backlash": "80"})
# reference: STE = the compression where the piecewise-linear T(theta_i, .) reaches T
ste_ref = np.array([[np.interp(T, T1[i], delta25) for T in torques] for i in range(48)])
k_ref = (np.array(torques) / rb1)[None, :] / ste_ref
hdr, s = read_csv(os.path.join(out, "spline_ste.csv"))
check("tt1 spline_ste.csv: header with units", hdr[0] == "roll angle [deg]" and hdr[1] == "STE at 100 N m [um]", str(hdr))
check("tt1 spline_ste.csv: angles are the table's nodes, closed by theta_0 + period",
      rel_err(np.radians(s[:-1, 0]), theta48) < 1e-12 and abs(math.radians(s[-1, 0]) - theta48[0] - period) < 1e-12)
check("tt1 spline_ste.csv: STE = inverse of T(theta, .) (1e-12)", rel_err(s[:-1, 1:] * 1e-6, ste_ref) < 1e-12,
      f"{rel_err(s[:-1, 1:] * 1e-6, ste_ref):.2e}")
hdr, s = read_csv(os.path.join(out, "spline_stiffness.csv"))
check("tt1 spline_stiffness.csv: k = F/STE (1e-12)", rel_err(s[:-1, 1:], k_ref) < 1e-12, f"{rel_err(s[:-1, 1:], k_ref):.2e}")
check("tt1 spline_stiffness.csv: last row repeats the first", rel_err(s[-1, 1:], s[0, 1:]) == 0)

r = json.load(open(os.path.join(out, "ross_mesh.json")))
th = np.array(r["theta_range"])
theta_A = r["theta_A_rad"]
check("ross: theta_range closed over one mesh period from 0",
      th[0] == 0 and abs(th[-1] - period) < 1e-15 and np.all(np.diff(th) > 0) and r["n_mesh_period"] == 1)
check("ross: theta_A is the start of contact of the pair (about -6.3 deg)", -0.12 < theta_A < -0.10, f"{theta_A}")
kr = np.array(r["stiffness_range"])
check("ross: one stiffness_range per torque", kr.shape == (3, len(th)) and r["torque"] == torques)
# ROSS's own reading: numpy.interp of theta mod max(theta_range); against the source re-interpolated
q = np.linspace(-0.3, 2.7, 997) * period
for j in range(3):
    ross = np.interp(np.mod(q, th[-1]), th, kr[j])
    ref = periodic_interp(theta48, k_ref[:, j], period, q + theta_A)
    e = rel_err(ross, ref)
    check(f"ross: numpy.interp of stiffness_range at {torques[j]:g} N m = source k (1e-12)", e < 1e-12, f"{e:.2e}")

for name in ("te_mesh_cycle.txt", "te_revolution.txt"):
    txt = open(os.path.join(out, name)).read()
    d = np.loadtxt(os.path.join(out, name), comments="%")
    means = [float(x) for x in re.findall(r"mean STE (\S+) m", txt)]
    span = period * (z1 if "revolution" in name else 1)
    ok = abs(d[0, 0]) == 0 and abs(d[-1, 0] - span) < 1e-12 and len(means) == 3
    e = max(rel_err(d[:, 1 + j] + means[j], periodic_interp(theta48, ste_ref[:, j], period, d[:, 0] + theta_A))
            for j in range(3))
    check(f"tt1 {name}: angle from A over {span:.4g} rad, STE - mean re-interpolated (1e-12)", ok and e < 1e-12, f"{e:.2e}")
    check(f"tt1 {name}: means are the mean STE over the nodes",
          rel_err(means, ste_ref.mean(axis=0)) < 1e-12)

hdr, f = read_csv(os.path.join(out, "force_table.csv"))
check("tt1 force_table.csv: header",
      hdr == ["roll angle [deg]", "compression [um]", "force [N]", "contact (1 drive; 0 clearance; -1 back) [-]"], str(hdr))
b = 80e-6
dl = np.unique(f[:, 1]) * 1e-6
F = f[:, 2].reshape(48, -1)
cs = f[:, 3].reshape(48, -1)
drive, back = dl > 0, dl < -b - 1e-12
check("tt1 force: delta axis -b - drive (reversed), 0, drive", len(dl) == 2 * 25 and abs(dl[24] + b) < 1e-15 and dl[25] == 0)
check("tt1 force: drive branch = T/r_b1 (1e-12)", rel_err(F[:, 25:], T1 / rb1) < 1e-12)
check("tt1 force: zero in the clearance", np.all(F[:, (dl >= -b - 1e-15) & (dl <= 0)] == 0))
psi = math.pi / z1 - b / (2 * rb1)  # pinion tooth thickness angle at the pitch circle (x = 0), thinned by b/(2 r_b1)
back_ref = np.array([-periodic_interp(theta48, T1[:, d], period, psi - theta48) / rb1 for d in range(24, 0, -1)]).T
e = rel_err(F[:, :24], back_ref)
check("tt1 force: back branch = -F(psi - theta, -delta - b), re-interpolated (1e-12)", e < 1e-12, f"{e:.2e}")
exact = -torque_fn(psi - theta48, -dl[:24] - b) / rb1
h = period / 48
bound = h ** 2 / 8 * rb1 * k0 * a * z1 ** 2 * np.max(dl[25:] + dl[25:] ** 2 / d0) / rb1
e_abs = float(np.max(np.abs(F[:, :24] - exact)))
check("tt1 force: back branch against the analytic law within h^2/8 max|F''|", e_abs <= bound * 1.0001,
      f"{e_abs:.3g} N <= {bound:.3g} N")
check("tt1 force: contact flags", np.all(cs[:, drive] == 1) and np.all(cs[:, back] == -1) and
      np.all(cs[:, ~drive & ~back] == 0))

# --- 2. two-sided table: copied, its own backlash; a different Backlash is refused.
bb = 80e-6
dd = np.concatenate([-bb - delta25[::-1], [0.0], delta25[1:]])
T2 = np.where(dd[None, :] > 0, torque_fn(theta48, np.maximum(dd, 0)),
              np.where(dd[None, :] < -bb, -0.9 * torque_fn(theta48 + 0.01, np.maximum(-dd - bb, 0)), 0.0))
write_table(os.path.join(work, "tt2.h5"), "torque", theta48, dd, T2, hsh, backlash=bb)
out, _ = run_export("tt2", {"Source": os.path.join(work, "tt2.h5"), "Source kind": "mesh table", "Formats": "force"})
hdr, f = read_csv(os.path.join(out, "force_table.csv"))
check("tt2 force: the two-sided table copied (1e-12)", rel_err(f[:, 2].reshape(48, -1), T2 / rb1) < 1e-12 and
      rel_err(np.unique(f[:, 1]) * 1e-6, dd) < 1e-12)
run_export("tt2_bad", {"Source": os.path.join(work, "tt2.h5"), "Source kind": "mesh table", "Formats": "force",
                       "Backlash": "50"}, 2)

# --- 3. stiffness table: k at the load nodes copied.
loads = np.linspace(0.0, 8000.0, 9)
K = k0 * (1 + a * np.cos(z1 * theta48))[:, None] * (1 + loads / F0)[None, :]
write_table(os.path.join(work, "kt.h5"), "stiffness", theta48, loads, K, hsh)
out, _ = run_export("kt", {"Source": os.path.join(work, "kt.h5"), "Source kind": "mesh table", "Formats": "ross, spline"})
hdr, s = read_csv(os.path.join(out, "spline_stiffness.csv"))
check("kt spline_stiffness.csv: the load nodes F > 0 as torques F r_b1",
      len(hdr) == 9 and abs(float(re.search(r"at (\S+) N m", hdr[1]).group(1)) - 1000 * rb1) < 1e-6, str(hdr[:3]))
check("kt spline_stiffness.csv: k copied (1e-12)", rel_err(s[:-1, 1:], K[:, 1:]) < 1e-12, f"{rel_err(s[:-1, 1:], K[:, 1:]):.2e}")
check("kt: no TE or force files (Formats = ross, spline)", not os.path.exists(os.path.join(out, "te_mesh_cycle.txt")))
run_export("kt_force", {"Source": os.path.join(work, "kt.h5"), "Source kind": "mesh table", "Formats": "force"}, 2)

# --- 4. solve results, one cycle from A, and a hunting sweep of 3 pitches.
for name, pitches in (("sr", 1), ("hunt", 3)):
    n = 40 * pitches
    th_deg = np.degrees(theta_A + pitches * period * np.arange(n) / n)
    ste = np.array([[T / (rb1 * k0) * (1 + 0.2 * math.sin(z1 * math.radians(x)) + 0.01 * (i % 7)) * 1e6
                     for i, x in enumerate(th_deg)] for T in (100.0, 200.0)]).T
    write_results(os.path.join(work, name + ".h5"), th_deg, np.array([100.0, 200.0]), ste, hsh)
    out, _ = run_export(name, {"Source": os.path.join(work, name + ".h5")})
    hdr, s = read_csv(os.path.join(out, "spline_ste.csv"))
    check(f"{name} spline_ste.csv: STE copied (1e-12)", rel_err(s[:-1, 1:], ste) < 1e-12 and
          rel_err(s[:-1, 0], th_deg) < 1e-12, f"{rel_err(s[:-1, 1:], ste):.2e}")
    r = json.load(open(os.path.join(out, "ross_mesh.json")))
    th = np.array(r["theta_range"])
    kref = (np.array([100.0, 200.0]) / rb1)[None, :] / (ste * 1e-6)
    check(f"{name} ross: {pitches} mesh period(s), a node at A, stiffness copied (1e-12)",
          r["n_mesh_period"] == pitches and len(th) == n + 1 and abs(th[-1] - pitches * period) < 1e-13 and
          rel_err(np.array(r["stiffness_range"])[:, :-1].T, kref) < 1e-12)
    d = np.loadtxt(os.path.join(out, "te_revolution.txt"), comments="%")
    span = period * (z1 if pitches == 1 else pitches)
    check(f"{name} te_revolution.txt: spans {span / (2 * math.pi):.3g} revolution(s)", abs(d[-1, 0] - span) < 1e-12)
run_export("sr_torque", {"Source": os.path.join(work, "sr.h5"), "Torques": "150"}, 2)
run_export("sr_force", {"Source": os.path.join(work, "sr.h5"), "Formats": "force"}, 2)

shutil.rmtree(work, ignore_errors=True)
print(f"export round trip: {'FAIL (' + ', '.join(fails) + ')' if fails else 'PASS'}")
sys.exit(1 if fails else 0)
