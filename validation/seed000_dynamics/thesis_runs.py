#!/usr/bin/python3
"""Gkimisis 2019 Table 1 cases with the thesis' own run set-up, and the helpers the other
scripts of this case share (variants of a case file, running gearfem dynamics, log figures).

The thesis' set-up (its dynamics listing, Appendix): torques ramped linearly over
t_res = T_tot/10 = 100 ms; x(0) = 0; fixed-step RK4 with dt = 1e-5 s and no event location
over T_tot = 1 s; initial speeds dw1/dt(0) = n0 and dw2/dt(0) = dw1/dt(0) R_b2/R_b1 (eq. 5.2).
The last is not the kinematic ratio (R_b1/R_b2): the gear starts 3.5x too fast, the pair
meets in back contact and, with balanced torques (T_out = T_in R_b2/R_b1), keeps
R_g2 I1 w1 + R_g1 I2 w2 (I ~ R^4 b), so it settles at w1 = n0 (1 + r^4)/(1 + r^2),
r = z2/z1 (momentum.py integrates this). `gearfem dynamics` starts from kinematic speeds
(no gear-speed input), so the thesis' ICs are run as their settled speed.

Usage: thesis_runs.py <gearfem> <out dir> <case file>...   (writes thesis_runs.csv)
"""
import csv
import os
import re
import subprocess
import sys
import time

R_RATIO = 60 / 32  # z2/z1 of the Table 1 pair (= R_b2/R_b1 = R_g2/R_g1)


def thesis_speed(n0, r=R_RATIO):
    """Settled pinion speed after the thesis' initial conditions (momentum, balanced torques)."""
    return n0 * (1 + r ** 4) / (1 + r ** 2)


def read_prm(path):
    with open(path) as f:
        return f.read()


def set_entry(text, name, value):
    """Replace `set <name> = ...` (first occurrence); insert into the subsection if absent."""
    pat = re.compile(r"^(\s*)set " + re.escape(name) + r"\s*=.*$", re.M)
    if pat.search(text):
        return pat.sub(lambda m: f"{m.group(1)}set {name} = {value}", text, count=1)
    raise KeyError(f"entry '{name}' not in the case file")


def add_entry(text, subsection, name, value):
    """Add `set name = value` right after `subsection <subsection>` (entry must be new)."""
    pat = re.compile(r"^(\s*)subsection " + re.escape(subsection) + r"\s*$", re.M)
    m = pat.search(text)
    if not m:
        raise KeyError(f"subsection '{subsection}' not in the case file")
    return text[:m.end()] + f"\n{m.group(1)}  set {name} = {value}" + text[m.end():]


def entry(text, name):
    m = re.search(r"^\s*set " + re.escape(name) + r"\s*=\s*(.*?)\s*$", text, re.M)
    return m.group(1) if m else None


def variant(base_text, *, law=None, torque=None, speed=None, ramp_ms=None, rest=None,
            steps=None, event=None, periods=None, never_settle=False, extra=()):
    """A case-file text with the given entries replaced (None: unchanged)."""
    t = base_text
    if law is not None:
        t = set_entry(t, "Law", law)
    if torque is not None:
        t = set_entry(t, "Input torque", f"{torque:g}")
    if speed is not None:
        t = set_entry(t, "Pinion speed", f"{speed:.6g}")
    if ramp_ms is not None:
        t = set_entry(t, "Torque ramp time", f"{ramp_ms:g}")
    if steps is not None:
        t = set_entry(t, "Steps per period", str(int(steps)))
    if periods is not None:
        t = set_entry(t, "Periods per speed", str(int(periods)))
    if rest is not None:
        t = add_entry(t, "Operating", "Start from rest deflection", "true" if rest else "false")
    if event is not None:
        t = add_entry(t, "Integrator", "Event location", "true" if event else "false")
    if never_settle:
        t = add_entry(t, "Analysis", "Steady-state tolerance", "1e-300")
    for sub, name, value in extra:
        t = add_entry(t, sub, name, value)
    return t


def thesis_setup(base_text, n0, law=None, torque=None, t_total=1.0, dt=1e-5):
    """The thesis' run set-up (module docstring) for initial pinion speed n0 [rpm]."""
    n = thesis_speed(n0)
    f_mesh = 32 * n / 60
    return variant(base_text, law=law, torque=torque, speed=n, ramp_ms=100.0 * t_total, rest=True,
                   steps=max(8, round(1 / (dt * f_mesh))), event=False,
                   periods=round(f_mesh * t_total))


def figures(log_text):
    """Figures of a gearfem dynamics console log."""
    def num(pattern):
        m = re.search(pattern, log_text)
        return float(m.group(1)) if m else None
    return {
        "rms": num(r"RMS DTE \[um\] = ([-+0-9.eE]+)"),
        "p2p": num(r"peak-to-peak DTE \[um\] = ([-+0-9.eE]+)"),
        "loss": num(r"contact loss fraction \[-\] = ([-+0-9.eE]+)"),
        "back": num(r"back contact fraction \[-\] = ([-+0-9.eE]+)"),
        "period": num(r"period \[mesh periods\] = ([0-9.eE+-]+)"),
        "settled": (re.search(r"settled \[-\] = (\w+)", log_text) or [None, None])[1],
        "fn": num(r"linear natural frequency \[Hz\] = ([-+0-9.eE]+)"),
        "fmesh": num(r"mesh frequency \[Hz\] = ([-+0-9.eE]+)"),
        "wall": num(r"results in .*\(([0-9.eE+-]+) s\)"),
    }


def run(gearfem, prm_text, folder, cwd=None, plots=True):
    """Write <folder>.prm, run gearfem dynamics into <folder>, return (figures, wall seconds).
    plots=False: no sweep/phase/spectrum figures (gearfem looks for its plot script under
    $GEARFEM_SOURCE_DIR/scripts; an empty folder there makes it skip them with a warning)."""
    os.makedirs(os.path.dirname(folder), exist_ok=True)
    prm = folder + ".prm"
    with open(prm, "w") as f:
        f.write(prm_text)
    t0 = time.perf_counter()
    env = dict(os.environ)
    if not plots:
        env["GEARFEM_SOURCE_DIR"] = os.path.join(os.path.dirname(folder), ".no_plots")
    p = subprocess.run([gearfem, "dynamics", prm, "--output-dir", folder], cwd=cwd,
                       capture_output=True, text=True, env=env)
    wall = time.perf_counter() - t0
    with open(folder + ".log", "w") as f:
        f.write(p.stdout + p.stderr)
    if p.returncode != 0:
        raise RuntimeError(f"gearfem dynamics {prm} failed ({p.returncode}): {p.stderr.strip()[-400:]}")
    return figures(p.stdout), wall


def main():
    gearfem, out, cases = sys.argv[1], sys.argv[2], sys.argv[3:]
    rows = []
    for path in cases:
        name = os.path.basename(path)[:-4]
        base = read_prm(path)
        n0 = float(entry(base, "Pinion speed"))
        for law, tag in (("analytical table", "table"), ("Ricker", "Ricker")):
            fig, _ = run(gearfem, thesis_setup(base, n0, law=law), os.path.join(out, "thesis_ics", tag, name),
                         plots=False)
            rows.append({"case": name, "law": tag, "n0 [rpm]": n0, "settled speed [rpm]": thesis_speed(n0),
                         **{k: fig[k] for k in ("loss", "back", "period", "settled", "rms", "fmesh")}})
            print(f"{name}, {tag} law, thesis set-up (settled speed {thesis_speed(n0):.1f} rpm): "
                  f"loss {fig['loss']:g}, period {fig['period']:g}, RMS {fig['rms']:.4g} um")
    with open(os.path.join(out, "thesis_runs.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0]))
        w.writeheader()
        w.writerows(rows)


if __name__ == "__main__":
    main()
