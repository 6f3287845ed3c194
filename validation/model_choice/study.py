#!/usr/bin/env python3
"""Accuracy-driven model choice (README.md): run `gearfem solve` with `Solve/Target` and no
Mesh settings (`auto`) beside a converged reference (`ref`) and a ladder of fixed meshes on five
pairs, and the demo, into results/<pair>/<run>/.

    study.py [--pairs parker,demo,fzg_c,seed001,rand1,rand2] [--reuse] [--draw-only] [--repeat N]

Pairs: the three of validation/speed_vs_error/pairs.py, each at its three torques, and two
drawn at random (numpy default_rng(36)): z 17-80 and x -0.3..0.6 per gear, m from ISO 54,
b = 10 m, E 206 GPa, nu 0.3, three torques from F/b = 25 m, 50 m and 100 m N/mm. A drawn
design is kept when every input of its study passes `gearfem solve --validate` and its
transverse contact ratio (computed here, and printed by gearfem) is at least 1.15; the draw is
written to results/designs.json. Each run: full gears, Q2, Lagrange, plane stress, 40
positions over one pitch from A, the pair's three torques in one `Solve/Torques` list (one
gearfem run per model). The demo keeps its single torque (200 N m). A run's cost is the CPU
time (user + system) of the whole `gearfem solve` process, read from os.wait4
(results/<pair>/<run>/cost.json); every input but the references is run twice in a row and
costs the smaller (--repeat N: N runs). With --reuse a run whose folder has `done` (exit 0 and
run.json written) and the same case.prm is not run again. --draw-only: draw and validate the
random designs, run nothing else.
"""
import argparse
import importlib.util
import json
import math
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time

sys.dont_write_bytecode = True  # no __pycache__ next to the imported speed_vs_error modules

import numpy as np  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.abspath(os.path.join(HERE, "..", ".."))
SVE = os.path.join(ROOT, "validation", "speed_vs_error")
sys.path.append(SVE)
from analyse import read_csv, ste_metrics  # noqa: E402  (speed_vs_error's metrics)
from pairs import PAIRS as SVE_PAIRS  # noqa: E402  (speed_vs_error's pairs)
_spec = importlib.util.spec_from_file_location("sve_study", os.path.join(SVE, "study.py"))
_sve_study = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(_sve_study)
merge = _sve_study.merge  # {section: {entry: value}} overrides, speed_vs_error's

GEARFEM = os.path.join(os.environ.get("GEARFEM_BUILD_DIR", os.path.join(ROOT, "build")), "app", "gearfem")
OUT = os.path.join(HERE, "results")
DEMO = os.path.join(ROOT, "inputs", "demo.prm")

POSITIONS = 40
SEED = 36
N_RANDOM = 2
ISO54 = (1.0, 1.25, 1.5, 2.0, 2.5, 3.0, 4.0, 5.0, 6.0, 8.0)  # ISO 54 series I modules [mm]
Z_RANGE = (17, 80)
X_RANGE = (-0.3, 0.6)
MIN_CONTACT_RATIO = 1.15
ALPHA = math.radians(20.0)
E_RANDOM, NU_RANDOM = 206.0, 0.3  # steel [GPa], [-]
FACE_PER_MODULE = 10.0            # b = 10 m
LOADS_PER_MODULE = (25.0, 50.0, 100.0)  # F/b = 25 m, 50 m, 100 m N/mm: the three torques
H_FILLET_DEFAULT = 0.25           # gearfem's Mesh/h_fillet default [mm]
LADDER = (10, 15, 30, 45)         # h_contact = m/n; m/30 is gearfem's default (left unset)

TARGET = {"mean_ste": 0.01, "pp_ste": 0.01, "root_stress": 0.03}  # relative
TARGET_TEXT = "mean STE 1, p-p STE 1, root stress 3"
COST_CAP = 1800  # Solve/Cost cap [s wall]
# Mesh draws of the automatic choice: the same input with Mesh/Growth ratio moved about its
# default 1.2. The grading of the size field changes every non-uniform mesh (nodes, topology)
# while the sizes the choice sets stay, so the draws show how the choice's levels, cost and
# true errors vary with mesh-to-mesh scatter.
DRAW_GROWTH = (1.18, 1.19, 1.21, 1.22)
QUANTITIES = [("mean_ste", "mean STE"), ("pp_ste", "p-p STE"), ("root_stress", "max root stress"),
              ("p_max", "max p_max")]
DEMO_TORQUE = 200.0  # inputs/demo.prm's single torque [N m]; its errors against Parker's reference there
ALL_KEYS = ["parker", "demo", "fzg_c", "seed001"] + [f"rand{i + 1}" for i in range(N_RANDOM)]


# ---------------------------------------------------------------- involute geometry (random draws)
def inv(a):
    return math.tan(a) - a


def working_pressure_angle(z1, z2, x1, x2, alpha=ALPHA):
    """alpha_w of the zero-backlash centre distance: inv a_w = inv a + 2 tan a (x1 + x2)/(z1 + z2)."""
    target = inv(alpha) + 2 * math.tan(alpha) * (x1 + x2) / (z1 + z2)
    a = alpha
    for _ in range(60):  # Newton on inv(a) = target; d inv/da = tan^2 a
        step = (inv(a) - target) / math.tan(a) ** 2
        a -= step
        if abs(step) < 1e-15:
            break
    return a


def contact_ratio(m, z1, z2, x1, x2, addendum=1.0, alpha=ALPHA):
    """Transverse contact ratio eps_alpha of an external involute pair at the zero-backlash centre
    distance (tip radius m (z/2 + h_a + x), no tip shortening), and that centre distance [mm]."""
    aw = working_pressure_angle(z1, z2, x1, x2, alpha)
    a = 0.5 * m * (z1 + z2) * math.cos(alpha) / math.cos(aw)
    rb = [0.5 * m * z * math.cos(alpha) for z in (z1, z2)]
    ra = [m * (z / 2 + addendum + x) for z, x in ((z1, x1), (z2, x2))]
    g = sum(math.sqrt(r * r - b * b) for r, b in zip(ra, rb)) - a * math.sin(aw)
    return g / (math.pi * m * math.cos(alpha)), a


def random_geometry(d):
    """gearfem parameter text of a drawn design (the default rack, written out)."""
    m, b = d["module"], d["face_width"]
    gears = "".join(f"""subsection Gear {i + 1}
  set Number of teeth           = {d['teeth'][i]}
  set Profile shift coefficient = {d['shift'][i]:g}
  set Face width                = {b:g}
end
""" for i in range(2))
    mats = "".join(f"""  subsection Gear {i + 1}
    set Young's modulus = {E_RANDOM:g}
    set Poisson ratio   = {NU_RANDOM:g}
  end
""" for i in range(2))
    return f"""subsection Rack
  set Module                  = {m:g}
  set Pressure angle          = 20
  set Addendum coefficient    = 1
  set Dedendum coefficient    = 1.25
  set Root radius coefficient = 0.25
end
{gears}subsection Material
{mats}end
"""


def random_torque(m, z1, load_per_module):
    """T1 [N m] with F/b = load_per_module m N/mm: F = (F/b) b, T1 = F r_b1, r_b1 = m z1 cos 20 / 2
    (4 significant digits)."""
    b = FACE_PER_MODULE * m
    F = load_per_module * m * b
    return float(f"{F * 0.5 * m * z1 * math.cos(ALPHA) * 1e-3:.4g}")


def random_torques(m, z1):
    """The three T1 [N m] of a random pair: F/b = 25 m, 50 m and 100 m N/mm."""
    return [random_torque(m, z1, q) for q in LOADS_PER_MODULE]


def torques_text(torques, sep=" / "):
    return sep.join(f"{t:g}" for t in torques)


# ---------------------------------------------------------------- pairs and runs
def fmt(v):
    return f"{v:.6g}"


def sve_pair(key):
    p = SVE_PAIRS[key]
    return dict(key=key, title=p["title"], geometry=p["geometry"], module=p["module"], teeth=p["teeth"],
                shift=p["shift"], face_width=p["face_width"], torques=tuple(float(t) for t in p["torques"]),
                ref_mesh={"h_contact": 0.05, "h_fillet": p["module"] / 60},
                ref_note=f"h_contact 0.05 mm (validation/speed_vs_error's reference), h_fillet m/60 = "
                         f"{fmt(p['module'] / 60)} mm, tiled teeth",
                source="validation/speed_vs_error/pairs.py")


def random_pair(key, d):
    m = d["module"]
    return dict(key=key, title=f"random {key[4:]}: {d['teeth'][0]}/{d['teeth'][1]} m {m:g}", geometry=random_geometry(d),
                module=m, teeth=tuple(d["teeth"]), shift=tuple(d["shift"]), face_width=d["face_width"],
                torques=tuple(d["torques"]), ref_mesh={"h_contact": m / 60, "h_fillet": m / 60},
                ref_note=f"h_contact = h_fillet = m/60 = {fmt(m / 60)} mm, tiled teeth",
                source=f"drawn, seed {SEED}", design=d)


def pairs(designs):
    """key -> pair of the study (the demo is not a pair: it uses parker's reference)."""
    out = {k: sve_pair(k) for k in ("parker", "fzg_c", "seed001")}
    for i, d in enumerate(designs):
        out[f"rand{i + 1}"] = random_pair(f"rand{i + 1}", d)
    return out


def fixed_rungs(pair):
    """name -> (label, Mesh entries) of the fixed ladder: h_contact m/10, m/15, m/30 (unset: the
    default), m/45, each with the default h_fillet and with h_fillet m/12 (not repeated where
    m/12 is the default 0.25 mm, i.e. m 3); full gears by tiles, as the choice meshes them."""
    m = pair["module"]
    out = {}
    for n in LADDER:
        for f12 in (False, True):
            if f12 and abs(m / 12 - H_FILLET_DEFAULT) < 1e-9:
                continue
            mesh = {} if n == 30 else {"h_contact": fmt(m / n)}
            if f12:
                mesh["h_fillet"] = fmt(m / 12)
            mesh["Tiled teeth"] = "true"  # as the automatic choice meshes (docs/fem.md)
            hc = f"m/{n} = {fmt(m / n)} mm" + (" (default)" if n == 30 else "")
            hf = f"m/12 = {fmt(m / 12)} mm" if f12 else f"{H_FILLET_DEFAULT:g} mm (default)"
            out[f"m{n}" + ("_f12" if f12 else "")] = (f"h_contact {hc}, h_fillet {hf}, tiled teeth", mesh)
    return out


def draw_name(g):
    """Run name of the mesh draw at Growth ratio g ("auto_g1.18")."""
    return f"auto_g{g:g}"


def is_auto(name):
    """The automatic choice: `auto` and its mesh draws."""
    return name == "auto" or name.startswith("auto_g")


def runs(pair):
    """name -> (label, {section: {entry: value}}) of every run of a pair."""
    r = {name: (label, {"Mesh": mesh} if mesh else {}) for name, (label, mesh) in fixed_rungs(pair).items()}
    r["auto"] = (f"Solve/Target = {TARGET_TEXT}, Cost cap {COST_CAP}, no Mesh settings",
                 {"Solve": {"Target": TARGET_TEXT, "Cost cap": str(COST_CAP)}})
    for g in DRAW_GROWTH:
        r[draw_name(g)] = (f"as auto, Mesh/Growth ratio {g:g} (a mesh draw; default 1.2), one run",
                           {"Solve": {"Target": TARGET_TEXT, "Cost cap": str(COST_CAP)},
                            "Mesh": {"Growth ratio": f"{g:g}"}})
    r["ref"] = (f"reference: {pair['ref_note']}",
                # Tiled teeth: gmsh meshes a 50-tooth gear with m/60 fillets whole in more than 6 min
                # (its subdivision fallback), by tiles in under a second; the two agree within
                # 0.01 % on the STE and 0.09 % on the root stress (Parker, README).
                {"Mesh": {**{k: fmt(v) for k, v in pair["ref_mesh"].items()}, "Tiled teeth": "true"}})
    return r


def base_sections(pair):
    return {"Material": {"Plane model": "plane stress"},
            "Solve": {"Positions": "cycle", "Number of positions": str(POSITIONS), "Start": "A",
                      "Torques": torques_text(pair["torques"], ", "), "VTU": "none", "Plots": "false"}}


def prm_text(sections):
    """{section: {entry: value}} -> parameter-file text."""
    lines = []
    for sec, entries in sections.items():
        lines.append(f"subsection {sec}")
        lines += [f"  set {k} = {v}" for k, v in entries.items()]
        lines.append("end")
    return "\n".join(lines) + "\n"


def case_text(pair, overrides):
    return ("# gearfem solve\n# generated by validation/model_choice/study.py\n" + pair["geometry"] +
            prm_text(merge(base_sections(pair), overrides)))


def without_subsection(text, name):
    """A parameter text without its top-level `subsection <name>` blocks."""
    out, depth, skip = [], 0, False
    for line in text.splitlines(keepends=True):
        s = line.strip()
        opens = s.startswith("subsection ")
        if depth == 0 and opens and s[len("subsection "):].strip() == name:
            skip = True
        if opens:
            depth += 1
        if not skip:
            out.append(line)
        if s == "end":
            depth -= 1
            if depth == 0 and skip:
                skip = False
    return "".join(out)


def demo_text():
    """inputs/demo.prm as the study runs it, and a note: unchanged when it asks for a target
    already; otherwise without its Mesh section and with Solve/Target added."""
    text = open(DEMO).read()
    if re.search(r"^\s*set\s+Target\s*=", text, re.M):
        return text, "inputs/demo.prm unchanged (it sets Solve/Target)"
    text = without_subsection(text, "Mesh")
    text = re.sub(r"^(subsection Solve[ \t]*\n)", rf"\1  set Target              = {TARGET_TEXT}\n", text, count=1,
                  flags=re.M)
    if "set Target" not in text:
        text += f"subsection Solve\n  set Target = {TARGET_TEXT}\nend\n"
    note = ("# generated by validation/model_choice/study.py from inputs/demo.prm: Mesh section removed,\n"
            "# Solve/Target added (the demo as it will be)\n")
    first, _, rest = text.partition("\n")
    text = first + "\n" + note + rest if first.startswith("# gearfem") else note + text
    return text, "inputs/demo.prm without its Mesh section, with Solve/Target"


# ---------------------------------------------------------------- running and timing
def timed(cmd, log, cwd):
    """Run cmd (niced); (exit status, wall s, CPU s = user + system of the process and its
    waited-for children, from os.wait4, peak RSS MB)."""
    t0 = time.time()
    with open(log, "w") as f:
        p = subprocess.Popen(["nice", "-n", "15"] + cmd, stdout=f, stderr=subprocess.STDOUT, cwd=cwd)
        _, status, ru = os.wait4(p.pid, 0)
    rc = os.waitstatus_to_exitcode(status)
    p.returncode = rc
    return rc, time.time() - t0, ru.ru_utime + ru.ru_stime, ru.ru_maxrss / 1024.0


def run_case(d, text, reuse, repeat=1):
    """Write d/case.prm and run `gearfem solve` on it into d/out; 'reused' when --reuse finds the
    same input finished. With `repeat` > 1 a finished run is run again that many times in all
    (into d/out_repeat, removed after), and its cost is the smallest CPU and wall time of the
    runs: the shared machine only ever adds time, so the minimum is the run's own cost.
    cost.json: exit, wall_s, cpu_s, rss_mb, loadavg, cpu_runs, wall_runs."""
    prm = os.path.join(d, "case.prm")
    if reuse and os.path.exists(os.path.join(d, "done")) and os.path.exists(prm) and open(prm).read() == text:
        return "reused"
    shutil.rmtree(d, ignore_errors=True)
    os.makedirs(d)
    with open(prm, "w") as f:
        f.write(text)
    rc, wall, cpu, rss = timed([GEARFEM, "solve", prm, "--output-dir", os.path.join(d, "out")],
                               os.path.join(d, "solve.log"), d)
    cpus, walls = [cpu], [wall]
    for _ in range(1, repeat if rc == 0 else 1):
        again = os.path.join(d, "out_repeat")
        rc2, w2, c2, _ = timed([GEARFEM, "solve", prm, "--output-dir", again], os.path.join(d, "repeat.log"), d)
        shutil.rmtree(again, ignore_errors=True)
        if rc2 == 0:
            cpus.append(c2), walls.append(w2)
    wall, cpu = min(walls), min(cpus)
    cost = dict(exit=rc, wall_s=wall, cpu_s=cpu, rss_mb=rss, loadavg=os.getloadavg()[0], cpu_runs=cpus,
                wall_runs=walls)
    with open(os.path.join(d, "cost.json.tmp"), "w") as f:
        json.dump(cost, f, indent=1)
    os.replace(os.path.join(d, "cost.json.tmp"), os.path.join(d, "cost.json"))
    if rc == 0 and os.path.exists(os.path.join(d, "out", "run.json")):
        open(os.path.join(d, "done"), "w").close()
    elif rc == 0:
        rc = -1  # exit 0 without run.json: not a finished run
    runs = f" (smallest of {len(cpus)})" if len(cpus) > 1 else ""
    return f"exit {rc}, {wall:.1f} s wall, {cpu:.1f} s CPU{runs}"


def validate(text, tmp, name):
    """`gearfem solve --validate` of an input text: (exit status, contact ratio printed or None,
    warnings, last line of the output)."""
    prm = os.path.join(tmp, name + ".prm")
    with open(prm, "w") as f:
        f.write(text)
    p = subprocess.run([GEARFEM, "solve", prm, "--validate"], capture_output=True, text=True, cwd=tmp)
    out = p.stdout + p.stderr
    m = re.search(r"contact ratio ([0-9.eE+-]+)", out)
    warns = [line.strip() for line in out.splitlines() if line.strip().startswith("warning")]
    last = (out.strip().splitlines() or [""])[-1].strip()
    return p.returncode, (float(m.group(1)) if m else None), warns, last


def draw_designs(seed=SEED, n=N_RANDOM, max_attempts=200):
    """The random designs and the record of every draw (accepted or why rejected)."""
    rng = np.random.default_rng(seed)
    designs, draws = [], []
    tmp = tempfile.mkdtemp(prefix="model_choice_draw.")
    try:
        while len(designs) < n:
            if len(draws) >= max_attempts:
                raise RuntimeError(f"no {n} valid designs in {max_attempts} draws")
            z = [int(v) for v in rng.integers(Z_RANGE[0], Z_RANGE[1] + 1, size=2)]
            m = float(rng.choice(ISO54))
            x = [round(float(v), 2) + 0.0 for v in rng.uniform(X_RANGE[0], X_RANGE[1], size=2)]
            eps, a = contact_ratio(m, z[0], z[1], x[0], x[1])
            d = dict(draw=len(draws) + 1, teeth=z, module=m, shift=x, face_width=FACE_PER_MODULE * m,
                     torques=random_torques(m, z[0]), centre_distance_mm=round(a, 6), contact_ratio=round(eps, 5))
            d["loads_per_width"] = [T * 1e3 / (0.5 * m * z[0] * math.cos(ALPHA)) / d["face_width"]
                                    for T in d["torques"]]
            why = None
            if eps < MIN_CONTACT_RATIO:
                why = f"contact ratio {eps:.3f} < {MIN_CONTACT_RATIO}"
            else:
                pair = random_pair("rand0", d)
                for name, (_, ov) in runs(pair).items():
                    if is_auto(name):  # Solve/Target is the feature under test: not a reason to redraw
                        continue
                    rc, eps_g, warns, last = validate(case_text(pair, ov), tmp, name)
                    if rc != 0:
                        why = f"gearfem solve --validate refused the {name} input (exit {rc}): {last[:300]}"
                        break
                    if name == "m30":
                        d["contact_ratio_gearfem"] = eps_g
                        d["warnings_default_mesh"] = warns
                        if eps_g is not None and eps_g < MIN_CONTACT_RATIO:
                            why = f"gearfem's contact ratio {eps_g:.3f} < {MIN_CONTACT_RATIO}"
                            break
            d["accepted"] = why is None
            if why:
                d["rejected"] = why
            else:
                designs.append(d)
            draws.append(d)
            print(f"draw {d['draw']}: z {z[0]}/{z[1]}, m {m:g}, x {x[0]:+.2f}/{x[1]:+.2f}, eps_alpha {eps:.3f}"
                  + (f" (gearfem {d['contact_ratio_gearfem']:.4g})" if d.get("contact_ratio_gearfem") else "")
                  + (f": rejected, {why}" if why else f": accepted as rand{len(designs)}, b {d['face_width']:g} mm, "
                     f"a {a:.4f} mm, T1 {torques_text(d['torques'])} N m (F/b "
                     f"{' / '.join(f'{q:.4g}' for q in d['loads_per_width'])} N/mm)"), flush=True)
    finally:
        shutil.rmtree(tmp, ignore_errors=True)
    return designs, draws


def load_designs(out=OUT):
    p = os.path.join(out, "designs.json")
    if not os.path.exists(p):
        return None
    return json.load(open(p))


# ---------------------------------------------------------------- metrics (check.py)
def metrics(d, torque):
    """Metrics of a finished run folder at one torque, the way speed_vs_error/analyse.py reads
    sweep.csv (its read_csv and ste_metrics): mean and p-p STE [um], max root stress pinion/gear
    and max p_max [MPa] over the positions, and the roll angles. None when sweep.csv has no row
    at that torque."""
    s = read_csv(os.path.join(d, "out", "sweep.csv"))
    m = np.isclose(s["torque"], torque)
    if not m.any():
        return None
    r = ste_metrics(s["STE"][m])
    r["root_stress_1"] = s["root stress pinion"][m].max()
    r["root_stress_2"] = s["root stress gear"][m].max()
    r["p_max"] = s["p_max"][m].max()
    r["roll"] = s["roll angle"][m]
    r["pp_resolution"] = pp_resolution(r["roll"], s["STE"][m])
    return r


def pp_resolution(roll, ste):
    """The resolution of a swept p-p as gearfem states it (model_choice::ste_ripple,
    docs/model-choice.md step 3), computed here independently with numpy: at each position
    with two neighbours on each side, |STE - the least-squares quadratic through those four
    (numpy.polyfit)|; twice the median of these, relative to the p-p. nan with fewer than four."""
    x, y = np.asarray(roll, dtype=float), np.asarray(ste, dtype=float)
    r = [abs(y[i] - np.polyval(np.polyfit(x[[i - 2, i - 1, i + 1, i + 2]] - x[i], y[[i - 2, i - 1, i + 1, i + 2]], 2), 0))
         for i in range(2, len(y) - 2)]
    return 2 * float(np.median(r)) / float(y.max() - y.min()) if len(r) >= 4 else float("nan")


def true_errors(r, ref):
    """Relative |error| against the reference (p-p relative to the reference's p-p; root stress:
    the larger of the pinion's and the gear's)."""
    return dict(mean_ste=abs(r["mean_ste"] / ref["mean_ste"] - 1),
                pp_ste=abs(r["pp_ste"] - ref["pp_ste"]) / abs(ref["pp_ste"]),
                root_stress=max(abs(r[f"root_stress_{i}"] / ref[f"root_stress_{i}"] - 1) for i in (1, 2)),
                p_max=abs(r["p_max"] / ref["p_max"] - 1))


def metrics_by_torque(d, torques):
    """{torque: metrics(d, torque)} of a finished run folder (None values where a torque is missing)."""
    return {T: metrics(d, T) for T in torques}


def max_errors(res, ref):
    """True error of a run at several torques: per quantity the largest over the torques of
    true_errors at each torque (res, ref: {torque: metrics}), and the torque of that largest
    error ({quantity: torque}). A torque missing from the run or the reference gives nan (the
    run then meets no target)."""
    per = {T: (true_errors(res[T], ref[T]) if res.get(T) is not None and ref.get(T) is not None else None)
           for T in ref}
    err, worst = {}, {}
    for q, _ in QUANTITIES:
        vals = [(e[q], T) if e is not None else (float("nan"), T) for T, e in per.items()]
        if not vals or any(not math.isfinite(v) for v, _ in vals):
            err[q], worst[q] = float("nan"), None
        else:
            err[q], worst[q] = max(vals)
    return err, worst, per


def meets(err):
    return all(err[q] <= TARGET[q] for q in TARGET)


def read_run(d):
    """(cost.json, run.json) of a finished run folder, or None."""
    if not os.path.exists(os.path.join(d, "done")):
        return None
    return json.load(open(os.path.join(d, "cost.json"))), json.load(open(os.path.join(d, "out", "run.json")))


# ---------------------------------------------------------------- main
def single_run(name):
    """Runs measured once: the references and the mesh draws (their cost is indicative)."""
    return name == "ref" or name.startswith("auto_g")


def weight(pair, name):
    """Rough relative cost of a run, for the ETA only."""
    if is_auto(name):
        return 4.0
    if name == "ref":
        return 3.0
    n = int(re.match(r"m(\d+)", name).group(1))
    return 0.5 + n / 30


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--pairs", default=",".join(ALL_KEYS), help="comma-separated, of " + ",".join(ALL_KEYS))
    ap.add_argument("--reuse", action="store_true", help="keep finished runs with the same input")
    ap.add_argument("--draw-only", action="store_true", help="draw and validate the random designs only")
    ap.add_argument("--repeat", type=int, default=2,
                    help="runs of each input but the references; its cost is the smallest (default 2)")
    a = ap.parse_args()
    keys = [k for k in a.pairs.split(",") if k]
    bad = [k for k in keys if k not in ALL_KEYS]
    if bad:
        ap.error(f"unknown pair {', '.join(bad)} (of {', '.join(ALL_KEYS)})")
    if not os.access(GEARFEM, os.X_OK):
        print(f"study: no gearfem at {GEARFEM} (GEARFEM_BUILD_DIR)")
        return 2
    os.makedirs(OUT, exist_ok=True)

    print(f"== random designs: numpy.random.default_rng({SEED}), z {Z_RANGE[0]}-{Z_RANGE[1]}, m from ISO 54 "
          f"{', '.join(f'{m:g}' for m in ISO54)}, x {X_RANGE[0]:g}..{X_RANGE[1]:g}, b 10 m, F/b "
          f"{' / '.join(f'{q:g}' for q in LOADS_PER_MODULE)} m N/mm; "
          f"kept: gearfem solve --validate exit 0 and eps_alpha >= {MIN_CONTACT_RATIO}", flush=True)
    designs, draws = draw_designs()
    tmp = os.path.join(OUT, "designs.json.tmp")
    with open(tmp, "w") as f:
        json.dump(dict(seed=SEED, generator="numpy.random.default_rng", numpy=np.__version__, designs=designs,
                       draws=draws), f, indent=1)
    os.replace(tmp, os.path.join(OUT, "designs.json"))
    if a.draw_only:
        print("study: designs written to", os.path.join(OUT, "designs.json"))
        return 0

    P = pairs(designs)
    jobs = []  # (key, name, folder, text)
    for key in keys:
        if key == "demo":
            text, _ = demo_text()
            jobs.append(("demo", "auto", os.path.join(OUT, "demo"), text, 2.0 * a.repeat))
            continue
        pair = P[key]
        for name, (_, ov) in runs(pair).items():
            w = weight(pair, name) * (1 if single_run(name) else a.repeat)
            jobs.append((key, name, os.path.join(OUT, key, name), case_text(pair, ov), w))
    total_w = sum(j[4] for j in jobs)
    done_w, t_all, failed = 0.0, time.time(), 0
    last_key = None
    for i, (key, name, d, text, w) in enumerate(jobs, 1):
        if key != last_key:
            what = "inputs/demo.prm with Solve/Target" if key == "demo" else \
                f"{P[key]['title']}, T1 {torques_text(P[key]['torques'])} N m, reference {P[key]['ref_note']}"
            print(f"== {key}: {what}", flush=True)
            last_key = key
        t = time.time()
        msg = run_case(d, text, a.reuse, 1 if single_run(name) else a.repeat)
        failed += msg.startswith("exit") and not msg.startswith("exit 0")
        if msg == "reused":  # no time spent: not part of the rate
            total_w -= w
        else:
            done_w += w
        el = time.time() - t_all
        eta = el / done_w * (total_w - done_w) if done_w else 0.0
        print(f"[{i}/{len(jobs)}] {key} {name}: {msg} ({time.time() - t:.1f} s; elapsed {el:.0f} s, "
              f"ETA {eta:.0f} s)", flush=True)
    print(f"study: {len(jobs)} runs, {failed} failed, {time.time() - t_all:.0f} s")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
