#!/usr/bin/python3
"""Mutation fuzzer for gearfem input files.

Mutates every inputs/*.prm with a fixed seed and runs each mutant through
`gearfem <command> --validate`; a fraction also gets a real run (only for the commands
that finish in about a second on the example cases; the others are validated only).
Every exit must be 0 or 2 (exit 3, a solver failure, is allowed for real runs only):
never 1, a signal, or a hang past the time limit. An exit 2 must print a
"gearfem: error:" line and no "internal error"; an exit 0 of a real run must leave no
nan/inf in its CSV files.

Mutations: a number scaled by 0, -1, 1e6, 1e-6, or shifted by +-1; a special value
(${X}, 1e-320, 1e400, inf, nan, {1|2}, 0x10, 1.5x, empty, a long number, true); a deleted,
duplicated or junk line; a stray `end` or `subsection`.

  tests/fuzz/fuzz_inputs.py --gearfem build/app/gearfem --src . --mutants 300 --seed 13
  scripts/fuzz_inputs [N] [SEED]     (the longer run)

Prints one line per failing mutant (and keeps its file in --keep), then a summary with the
exit counts. Exit status 0 when every mutant passed, 1 otherwise.
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
# Commands whose real run on the example cases takes a few seconds (mostly the plots), and
# the inputs excluded from real runs because they take much longer (B-spline rack: ~30 s).
FAST_RUN = {"profile", "rate"}
SLOW_INPUTS = ("bspline",)


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


def csv_has_nonfinite(folder):
    for f in glob.glob(os.path.join(folder, "**", "*.csv"), recursive=True):
        with open(f, errors="replace") as h:
            for line in h:
                if re.search(r"(^|,)\s*[-+]?(nan|inf)", line, re.I):
                    return f
    return None


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--gearfem", required=True)
    ap.add_argument("--src", required=True, help="source folder (inputs/*.prm are mutated)")
    ap.add_argument("--mutants", type=int, default=300)
    ap.add_argument("--seed", type=int, default=13)
    ap.add_argument("--run-fraction", type=float, default=0.1,
                    help="fraction of mutants of the fast commands that also get a real run")
    ap.add_argument("--timeout", type=float, default=30.0, help="seconds per gearfem call")
    ap.add_argument("--jobs", type=int, default=2, help="gearfem processes at a time")
    ap.add_argument("--keep", default="", help="folder where failing mutants are copied")
    args = ap.parse_args()

    gearfem = os.path.abspath(args.gearfem)
    inputs = sorted(glob.glob(os.path.join(args.src, "inputs", "*.prm")))
    if not inputs:
        print("no inputs found under", args.src)
        return 1
    texts = {f: open(f).read().split("\n") for f in inputs}
    rng = random.Random(args.seed)
    work = tempfile.mkdtemp(prefix="gearfem_fuzz.")
    exits = collections.Counter()
    by_command = collections.Counter()
    failures = []
    lock = threading.Lock()
    t0 = time.time()

    # All mutants first (deterministic for a seed), then the calls, `--jobs` at a time.
    jobs = []
    for k in range(args.mutants):
        src = inputs[k % len(inputs)]
        cmd = command_of(src)
        lines, what = mutate(texts[src], rng)
        if rng.random() < 0.2:  # sometimes two mutations at once
            lines, what2 = mutate(lines, rng)
            what += "; " + what2
        mutant = os.path.join(work, "m%04d_%s" % (k, os.path.basename(src)))
        with open(mutant, "w") as f:
            f.write("\n".join(lines))
        real = (cmd[0] in FAST_RUN and not any(w in src for w in SLOW_INPUTS) and
                rng.random() < args.run_fraction)
        jobs.append((k, src, cmd, what, mutant, real))

    def execute(job):
        k, src, cmd, what, mutant, real = job
        calls = [("validate", [gearfem] + cmd + ["--validate", mutant])]
        out = os.path.join(work, "out%04d" % k)
        if real:
            calls.append(("run", [gearfem] + cmd + [mutant, "--output-dir", out]))
        for mode, argv in calls:
            try:
                p = subprocess.run(argv, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                                   timeout=args.timeout, cwd=work,
                                   env=dict(os.environ, MPLBACKEND="Agg"))
                rc = p.returncode
                err = p.stderr.decode(errors="replace")
            except subprocess.TimeoutExpired:
                rc, err = "timeout", ""
            problem = None
            if rc == "timeout":
                problem = "hang past %.0f s" % args.timeout
            elif rc < 0:
                problem = "signal %d" % -rc
            elif rc not in (0, 2) and not (mode == "run" and rc == 3):
                problem = "exit %d" % rc
            elif rc == 2 and ("gearfem: error:" not in err or "internal error" in err):
                problem = "exit 2 without a named error"
            elif rc == 0 and mode == "run":
                bad = csv_has_nonfinite(out)
                if bad:
                    problem = "nan/inf in " + os.path.basename(bad)
            if mode == "run":
                shutil.rmtree(out, ignore_errors=True)
            with lock:
                exits[rc] += 1
                by_command[" ".join(cmd) + " " + mode] += 1
                if problem:
                    last = err.strip().split("\n")[-1][:200] if err.strip() else ""
                    failures.append("%s %s [%s] %s: %s | %s" % (
                        os.path.basename(src), mode, " ".join(cmd), what, problem, last))
                    if args.keep:
                        os.makedirs(args.keep, exist_ok=True)
                        shutil.copy(mutant, args.keep)

    try:
        with concurrent.futures.ThreadPoolExecutor(max_workers=max(1, args.jobs)) as pool:
            list(pool.map(execute, jobs))
    finally:
        shutil.rmtree(work, ignore_errors=True)
    runs = sum(v for k, v in by_command.items() if k.endswith(" run"))
    wall = time.time() - t0
    for f in sorted(failures):
        print("FAIL:", f)
    print("fuzz: %d mutants of %d inputs (seed %d), %d calls (%d real runs) in %.1f s" % (
        args.mutants, len(inputs), args.seed, sum(exits.values()), runs, wall))
    print("exits: " + ", ".join("%s: %d" % (k, v) for k, v in sorted(exits.items(), key=str)))
    print("calls by command: " + ", ".join("%s: %d" % kv for kv in sorted(by_command.items())))
    print("%d failing" % len(failures))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
