#!/usr/bin/python3
"""Mutation fuzzer for gearfem input files, over every command.

Mutates every inputs/*.prm and the small seeds of tests/fuzz/seeds/ (one per command that
has no input cheap enough to run: solve, condense, batch, optimise, calibrate, tolerance, export,
solve with manufacturing deviations and solve with friction) with a fixed
seed, and runs each mutant through `gearfem <command> --validate`. A fraction of the mutants
of the cheap inputs (the seeds, and the inputs that finish in seconds: CHEAP) also get a real
run; mutants of the solve seed are re-solved on a condensed cycle (`--condensed`) half the
time. The set-up solves and condenses the solve seed once (the calibrate seed's results file,
@RESULTS@, and the cycle).

Every exit must be 0 or 2, or 3 for a real run (4 for a batch that ran with failed designs
and merged them, or a tolerance study with samples recorded as failed); never 1, a signal, or a run past the time limit. An exit 2 must print a "gearfem: error:" line naming the parameter and no "internal
error", an exit 3 a "gearfem: solver failure:" line with the solver's reason; an exit 0 of a real run must leave no nan/inf in its CSV
files.

Mutations (--mode text, the default): a number scaled by 0, -1, 1e6, 1e-6, or shifted by +-1;
a special value (${X}, 1e-320, 1e400, inf, nan, {1|2}, 0x10, 1.5x, empty, a long number, true);
a deleted, duplicated or junk line; a stray `end` or `subsection`.

Structure-aware mutations (--mode structured): exactly one declared entry of the input's command
(`gearfem <command> --print-parameters json`: the entries the file sets, and half the time any
other entry of the command, added in its subsection) set to an edge value: 0, -1, its value
times +-1e12 or +-1e-12, nan, 2^31; for a list, empty, reversed or doubled; for a keyword,
another option of its selection or a keyword of another entry. --mode both alternates.

  tests/fuzz/fuzz_inputs.py --gearfem build/app/gearfem --src . --mutants 300 --seed 13
  scripts/fuzz_inputs [N] [SEED] [MODE]  (the long run: 10 000 structure-aware mutants)

Prints one line per failing mutant (and keeps its file in --keep), then a summary with the
exit counts per command. Exit status 0 when every mutant passed, 1 otherwise.
"""
import argparse
import collections
import concurrent.futures
import glob
import os
import random
import re
import shutil
import subprocess
import sys
import tempfile
import threading
import time

NUMBER = re.compile(r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?")
SPECIAL = ["${X}", "1e-320", "-1e-320", "1e400", "-1e400", "inf", "nan", "{1|2}", "0x10", "1.5x",
           "", "1" + "0" * 400, "true", "-0", "1e-300", "1e300", "2147483648", "-2147483649",
           "4.9e-324"]
JUNK = ["garbage line", "set Nonexistent entry = 3", "set = 1", "=", "set Module", "subsection",
        "end end", "set Face width == 2", "include other.prm", "\tset\t", "#" * 50,
        "subsection Rack\nset Module = ${M}\nend"]
# Inputs whose real run takes a few seconds (measured on the 2-core machine): the seeds, and
# these. The others (FE sweeps of 10-40 s, the B-spline rack) are validated only.
CHEAP = {"fzg_c.prm", "seed000_32_60.prm", "seed001_23_69.prm", "seed003_19_55.prm", "tip_relief.prm",
         "tip_rounding.prm", "seed001_23_69_rate.prm", "seed001_23_69_rate_thesis_kh.prm",
         "dynamics_kahraman_singh.prm", "dynamics_seed000_ricker.prm", "dynamics_seed000_table1.prm",
         "dynamics_seed004.prm", "seed001_gearbox.prm", "seed001_gearbox_thesis_stresses.prm",
         "mesh_demo.prm", "condense_demo.prm", "tip_relief_opt.prm"}


def command_of(path):
    with open(path) as f:
        first = f.readline()
    m = re.match(r"#\s*gearfem\s+([a-z]+(?:\s+[a-z]+)?)\s*$", first)
    return m.group(1).split() if m else ["profile"]


def mutate(lines, rng):
    """One mutation of the list of lines; returns (new lines, description)."""
    lines = list(lines)
    sets = [i for i, l in enumerate(lines) if re.match(r"\s*set\s+[^=]+=", l)]
    kind = rng.choice(["scale", "scale", "scale", "special", "special", "delete", "duplicate",
                       "junk", "end", "subsection"])
    if kind in ("scale", "special") and sets:
        i = rng.choice(sets)
        key, value = lines[i].split("=", 1)
        if kind == "scale":
            numbers = list(NUMBER.finditer(value))
            if numbers:
                m = rng.choice(numbers)
                op = rng.choice(["*0", "*-1", "*1e6", "*1e-6", "+1", "-1"])
                x = float(m.group(0))
                y = x * float(op[1:]) if op[0] == "*" else x + float(op)
                new = "%.17g" % y
                value = value[:m.start()] + new + value[m.end():]
                lines[i] = key + "= " + value.strip()
                return lines, "line %d: %s %s -> %s" % (i + 1, key.strip(), op, value.strip())
        special = rng.choice(SPECIAL)
        items = value.split(",")
        if len(items) > 1 and rng.random() < 0.5:
            items[rng.randrange(len(items))] = " " + special
            value = ",".join(items)
        else:
            value = " " + special
        lines[i] = key + "=" + value
        return lines, "line %d: %s= %s" % (i + 1, key.strip(), value.strip()[:40])
    i = rng.randrange(len(lines) + 1)
    if kind == "delete" and lines:
        i = min(i, len(lines) - 1)
        d = lines.pop(i)
        return lines, "line %d deleted: %s" % (i + 1, d.strip()[:40])
    if kind == "duplicate" and lines:
        i = min(i, len(lines) - 1)
        lines.insert(i, lines[i])
        return lines, "line %d duplicated: %s" % (i + 1, lines[i].strip()[:40])
    if kind == "end":
        lines.insert(i, "end")
        return lines, "stray end at line %d" % (i + 1)
    if kind == "subsection":
        name = rng.choice(["Rack", "Gear 1", "Nonexistent", "Solve", ""])
        lines.insert(i, "subsection " + name)
        return lines, "stray 'subsection %s' at line %d" % (name, i + 1)
    junk = rng.choice(JUNK)
    lines.insert(i, junk)
    return lines, "junk at line %d: %s" % (i + 1, junk.replace("\n", "|")[:40])


def decode(name):
    """deal.II's mangled JSON names: _XX is the character of hex XX."""
    return re.sub(r"_([0-9a-f]{2})", lambda m: chr(int(m.group(1), 16)), name)


def declared_entries(gearfem, command, cache={}):
    """[(subsection path, entry name, default value, pattern description)] of a command."""
    key = tuple(command)
    if key not in cache:
        import json
        p = subprocess.run([gearfem] + command + ["--print-parameters", "json"], stdout=subprocess.PIPE,
                           stderr=subprocess.DEVNULL, timeout=60)
        entries = []

        def walk(node, path):
            for k, v in node.items():
                if not isinstance(v, dict):
                    continue
                if "pattern_description" in v:
                    entries.append((tuple(path), decode(k), v.get("default_value", ""), v["pattern_description"]))
                else:
                    walk(v, path + [decode(k)])
        try:
            walk(json.loads(p.stdout.decode()), [])
        except ValueError:
            pass
        cache[key] = entries
    return cache[key]


def options_of(pattern):
    """The options of a deal.II selection pattern ("[Selection a|b ]"); [] for other patterns."""
    m = re.match(r"\[(?:Multiple)?Selection (.*) \]", pattern)
    return [o for o in m.group(1).split("|") if o] if m else []


def file_entries(lines):
    """{(subsection path, entry name): line index} of the `set` lines of a .prm text."""
    out, stack = {}, []
    for i, l in enumerate(lines):
        t = l.split("#", 1)[0].strip()
        if t.startswith("subsection "):
            stack.append(t[len("subsection "):].strip())
        elif t == "end":
            if stack:
                stack.pop()
        else:
            m = re.match(r"set\s+([^=]+?)\s*=", t)
            if m:
                out[(tuple(stack), m.group(1))] = i
    return out


def edge_values(value, pattern, keywords, rng):
    """The structure-aware edge values of one entry with `value` and deal.II `pattern`."""
    numbers = list(NUMBER.finditer(value))
    items = [v.strip() for v in re.split(r"[,;]", value) if v.strip()]
    out = ["0", "-1", "nan", "2147483648"]
    if numbers:
        m = rng.choice(numbers)
        x = float(m.group(0)) or 1.0
        for f in (1e12, -1e12, 1e-12, -1e-12):
            out.append(value[:m.start()] + "%.17g" % (x * f) + value[m.end():])
    else:
        for f in (1e12, -1e12, 1e-12, -1e-12):
            out.append("%.17g" % f)
    sep = ";" if ";" in value else ","
    out += ["", (sep + " ").join(reversed(items)) if len(items) > 1 else value,
            (sep + " ").join(items + items) if items else value]
    options = [o for o in options_of(pattern) if o != value.strip()]
    out.append(rng.choice(options) if options and rng.random() < 0.6 else rng.choice(keywords or ["none"]))
    return out


def mutate_structured(lines, rng, entries, keywords):
    """One structure-aware mutation: one entry of the command to one edge value."""
    lines = list(lines)
    present = file_entries(lines)
    candidates = [e for e in entries if (e[0], e[1]) in present]
    if not candidates or rng.random() < 0.5:
        candidates = entries or candidates
    if not candidates:
        return mutate(lines, rng)
    path, name, default, pattern = rng.choice(candidates)
    i = present.get((path, name))
    value = lines[i].split("=", 1)[1].split("#", 1)[0].strip() if i is not None else default
    new = rng.choice(edge_values(value, pattern, keywords, rng))
    where = "/".join(path + (name,))
    if i is not None:
        lines[i] = lines[i].split("=", 1)[0] + "= " + new
        return lines, "%s: %s -> %s" % (where, value[:30], new[:40])
    lines += ["subsection " + s for s in path] + ["set %s = %s" % (name, new)] + ["end"] * len(path)
    return lines, "%s (default %s) added: %s" % (where, default[:30], new[:40])


def csv_has_nonfinite(folder):
    for f in glob.glob(os.path.join(folder, "**", "*.csv"), recursive=True):
        with open(f, errors="replace") as h:
            for line in h:
                if re.search(r"(^|,)\s*[-+]?(nan|inf)", line, re.I):
                    return f
    return None


def set_up(gearfem, seeds, work):
    """Solve and condense the solve seed once: the calibrate seed's results file and the
    cycle of the --condensed mutants. Returns {placeholder: path}."""
    solve = os.path.join(seeds, "solve_small.prm")
    for cmd, out in (("solve", "base"), ("condense", "cycle")):
        p = subprocess.run([gearfem, cmd, solve, "--output-dir", os.path.join(work, out)],
                           stdout=subprocess.PIPE, stderr=subprocess.STDOUT, timeout=300, cwd=work)
        if p.returncode != 0:
            raise SystemExit("fuzz set-up: gearfem %s %s failed:\n%s" % (cmd, solve, p.stdout.decode()[-2000:]))
    return {"@RESULTS@": os.path.join(work, "base", "results.h5"),
            "@CYCLE@": os.path.join(work, "cycle", "condensed.h5")}


def classify(rc, err, mode, out, command):
    """The problem of one call, or None."""
    if rc == "timeout":
        return "over its time limit"
    if rc < 0:
        return "signal %d" % -rc
    if command == "batch" and mode == "run" and rc == 4:  # the documented partial failure
        return None if os.path.exists(os.path.join(out, "batch.csv")) else "exit 4 without batch.csv"
    if command == "tolerance" and mode == "run" and rc == 4:  # samples recorded as failed
        return None if os.path.exists(os.path.join(out, "samples.csv")) else "exit 4 without samples.csv"
    if rc not in (0, 2) and not (mode == "run" and rc == 3):
        return "exit %d" % rc
    if rc == 2 and ("gearfem: error:" not in err or "internal error" in err):
        return "exit 2 without a named error"
    if rc == 3 and "gearfem: solver failure:" not in err:
        return "exit 3 without the solver's reason"
    if rc == 0 and mode == "run":
        bad = csv_has_nonfinite(out)
        if bad:
            return "nan/inf in " + os.path.basename(bad)
    return None


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--gearfem", required=True)
    ap.add_argument("--src", required=True, help="source folder (inputs/*.prm and tests/fuzz/seeds/*.prm are mutated)")
    ap.add_argument("--mutants", type=int, default=300)
    ap.add_argument("--seed", type=int, default=13)
    ap.add_argument("--run-fraction", type=float, default=0.1,
                    help="fraction of the mutants of the cheap inputs that also get a real run")
    ap.add_argument("--timeout", type=float, default=60.0, help="time limit [s] of one --validate call")
    ap.add_argument("--run-timeout", type=float, default=120.0, help="time limit [s] of one real run")
    ap.add_argument("--jobs", type=int, default=2, help="gearfem processes at a time")
    ap.add_argument("--keep", default="", help="folder where failing mutants are copied")
    ap.add_argument("--mode", choices=["text", "structured", "both"], default="text",
                    help="text mutations, structure-aware ones (one declared entry to an edge value), or both")
    args = ap.parse_args()

    gearfem = os.path.abspath(args.gearfem)
    seeds = os.path.join(os.path.abspath(args.src), "tests", "fuzz", "seeds")
    inputs = sorted(glob.glob(os.path.join(args.src, "inputs", "*.prm"))) + sorted(glob.glob(os.path.join(seeds, "*.prm")))
    if not inputs:
        print("no inputs found under", args.src)
        return 1
    work = tempfile.mkdtemp(prefix="gearfem_fuzz.")
    t0 = time.time()
    try:
        files = set_up(gearfem, seeds, work)
        # The files the inputs name relative to themselves (a batch's design table): the
        # mutants are written to the work folder, beside copies of them.
        for aux in glob.glob(os.path.join(args.src, "inputs", "*")):
            if os.path.isfile(aux) and not aux.endswith((".prm", ".md")):
                shutil.copy(aux, work)
        texts = {}
        for f in inputs:
            t = open(f).read()
            for k, v in files.items():
                t = t.replace(k, v)
            texts[f] = t.split("\n")
        rng = random.Random(args.seed)
        # The keywords of every selection of every command: "another keyword" of a structured mutant.
        keywords = sorted({o for f in inputs for e in declared_entries(gearfem, command_of(f)) for o in options_of(e[3])})
        exits = collections.Counter()
        by_command = collections.defaultdict(collections.Counter)
        mutants_of = collections.Counter()
        failures = []
        lock = threading.Lock()
        done = [0]

        # All mutants first (deterministic for a seed), then the calls, `--jobs` at a time.
        jobs = []
        for k in range(args.mutants):
            src = inputs[k % len(inputs)]
            cmd = command_of(src)
            if args.mode == "structured" or (args.mode == "both" and k % 2 == 1):
                lines, what = mutate_structured(texts[src], rng, declared_entries(gearfem, cmd), keywords)
            else:
                lines, what = mutate(texts[src], rng)
                if rng.random() < 0.2:  # sometimes two mutations at once
                    lines, what2 = mutate(lines, rng)
                    what += "; " + what2
            mutant = os.path.join(work, "m%05d_%s" % (k, os.path.basename(src)))
            with open(mutant, "w") as f:
                f.write("\n".join(lines))
            cheap = src.startswith(seeds) or os.path.basename(src) in CHEAP
            real = cheap and rng.random() < args.run_fraction
            extra = []
            if os.path.basename(src) == "solve_small.prm" and rng.random() < 0.5:
                extra = ["--condensed", files["@CYCLE@"]]
            name = " ".join(cmd) + (" --condensed" if extra else "")
            mutants_of[name] += 1
            jobs.append((k, src, cmd, extra, name, what, mutant, real))

        def execute(job):
            k, src, cmd, extra, name, what, mutant, real = job
            calls = [("validate", [gearfem] + cmd + ["--validate", mutant] + extra, args.timeout)]
            out = os.path.join(work, "out%05d" % k)
            if real:
                calls.append(("run", [gearfem] + cmd + [mutant, "--output-dir", out] + extra, args.run_timeout))
            for mode, argv, limit in calls:
                try:
                    p = subprocess.run(argv, stdout=subprocess.PIPE, stderr=subprocess.PIPE, timeout=limit, cwd=work,
                                       env=dict(os.environ, MPLBACKEND="Agg"))
                    rc = p.returncode
                    err = p.stderr.decode(errors="replace")
                except subprocess.TimeoutExpired:
                    rc, err = "timeout", ""
                    subprocess.run(["pkill", "-KILL", "-f", mutant], stderr=subprocess.DEVNULL)  # its batch workers
                problem = classify(rc, err, mode, out, cmd[0])
                if mode == "run":
                    shutil.rmtree(out, ignore_errors=True)
                with lock:
                    exits[rc] += 1
                    by_command[name][(mode, rc)] += 1
                    if problem:
                        last = err.strip().split("\n")[-1][:200] if err.strip() else ""
                        failures.append("%s %s [%s] %s: %s | %s" % (
                            os.path.basename(src), mode, name, what, problem, last))
                        if args.keep:
                            os.makedirs(args.keep, exist_ok=True)
                            shutil.copy(mutant, args.keep)
            os.remove(mutant)
            with lock:
                done[0] += 1
                n = done[0]
                if args.mutants >= 1000 and n % (args.mutants // 20) == 0:
                    el = time.time() - t0
                    print("fuzz: %d/%d mutants, %d failing, elapsed %.0f s, ETA %.0f s" % (
                        n, args.mutants, len(failures), el, el / n * (args.mutants - n)), flush=True)

        with concurrent.futures.ThreadPoolExecutor(max_workers=max(1, args.jobs)) as pool:
            list(pool.map(execute, jobs))
    finally:
        shutil.rmtree(work, ignore_errors=True)
    runs = sum(v for c in by_command.values() for (m, _), v in c.items() if m == "run")
    calls = sum(exits.values())
    wall = time.time() - t0
    for f in sorted(failures):
        print("FAIL:", f)
    print("fuzz (%s mutations): %d mutants of %d inputs (seed %d), %d calls, %d real runs (%.1f %% of the mutants), %.1f s" % (
        args.mode, args.mutants, len(inputs), args.seed, calls, runs, 100.0 * runs / max(1, args.mutants), wall))
    print("exits: " + ", ".join("%s: %d" % (k, v) for k, v in sorted(exits.items(), key=str)))
    print("| command | mutants | --validate exits | real runs: exits |")
    print("|---|---|---|---|")
    for name in sorted(mutants_of):
        c = by_command[name]
        fmt = lambda m: ", ".join("%s: %d" % (rc, v) for (mm, rc), v in sorted(c.items(), key=str) if mm == m) or "-"
        print("| %s | %d | %s | %s |" % (name, mutants_of[name], fmt("validate"), fmt("run")))
    print("%d failing" % len(failures))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
