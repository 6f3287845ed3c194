#!/usr/bin/python3
"""Every sample run that gearfem prints or documents runs.

    sample_runs.py GEARFEM SOURCE_DIR

Collects the sample command lines of `gearfem <command> --help` (the "Sample run(s)"
block of every command that `gearfem --help` lists), of README.md (lines starting with
`build/app/gearfem` or `mpirun ... gearfem`) and of inputs/README.md (the back-quoted
`gearfem ...` of each row). Each is run from SOURCE_DIR with `--validate` (the input parsed
and checked, nothing written) and must exit 0; the cheap ones (CHEAP below: seconds, no FE
sweep) also run for real into a temporary folder and must exit 0. Options that only make
sense for a real run (--output-dir DIR, --resume, --merge, --slice K/N) are dropped for the
--validate run; `mpirun -np N` is dropped (the batch driver validates serially).
Exit 1 on the first failure, naming the sample and where it is printed.
"""
import os, re, shlex, subprocess, sys, tempfile

gearfem, src = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2])
# Sample runs cheap enough to run for real in the quick tier (seconds each).
# Samples that read the results of an earlier run (documented beside the sample): from a
# clean clone the prerequisite is absent, and the sample must then fail exactly on it (exit
# 2 naming the entry and "file not found"), not on anything else.
NEEDS = {'calibrate validation/analytical_vs_fe/calibrate.prm':
         ('validation/parker_ste/results/plane_stress/results.h5', 'Calibration/Results files'),
         'solve inputs/demo_fixed_mesh.prm --condensed results/demo_condensed/condensed.h5':
         ('results/demo_condensed/condensed.h5', 'condensed cycle file'),
         'solve inputs/condense_demo.prm --condensed results/condense_demo/condensed.h5':
         ('results/condense_demo/condensed.h5', 'condensed cycle file')}
CHEAP = {'profile inputs/demo.prm', 'rate inputs/seed001_23_69_rate.prm', 'gearbox inputs/seed001_gearbox.prm',
         'gearbox inputs/seed001_gearbox_thesis_stresses.prm', 'profile inputs/fzg_c.prm',
         'dynamics inputs/dynamics_seed004.prm', 'mesh inputs/mesh_demo.prm',
         'rate inputs/internal_rate.prm'}


def run(args, **kw):
    return subprocess.run([gearfem] + args, cwd=src, capture_output=True, text=True, timeout=600, **kw)


def samples_of_help():
    out = run(['--help']).stdout
    commands = sorted(set(re.findall(r'^\s+([a-z]+)\s{2,}', out, flags=re.M)))
    found = []
    for c in commands:
        h = run([c, '--help']).stdout
        block = re.search(r'Sample runs?:\n((?:[ \t]+.*\n?)*)', h)
        if not block:
            continue
        for line in block.group(1).splitlines():
            m = re.match(r'\s+(?:mpirun -np \d+ )?gearfem (.*)', line)
            if m:
                found.append((f'gearfem {c} --help', m.group(1)))
    return commands, found


def samples_of_readmes():
    found = []
    for line in open(os.path.join(src, 'README.md')):
        m = re.match(r'(?:mpirun -np \d+ )?build/app/gearfem (.*)', line.strip())
        if m:
            found.append(('README.md', m.group(1).split('#')[0]))
    for line in open(os.path.join(src, 'inputs', 'README.md')):
        for m in re.finditer(r'`gearfem ([a-z]+ [^`]*inputs/[^`]*)`', line):
            found.append(('inputs/README.md', m.group(1)))
    return found


def clean(sample):
    """The command's arguments without the real-run-only options and trailing notes."""
    s = re.sub(r'\s+\(.*$', '', sample.strip())        # "(aggregate the slices)" notes
    a = shlex.split(s)
    out, i = [], 0
    while i < len(a):
        if a[i] in ('--output-dir', '--slice'):
            i += 2
            continue
        if a[i] in ('--resume', '--merge', '--validate'):
            i += 1
            continue
        out.append(a[i])
        i += 1
    return out


commands, found = samples_of_help()
found += samples_of_readmes()
if len(found) < 20:
    print(f'sample_runs: only {len(found)} samples found (commands {commands}): the parsing broke')
    sys.exit(1)
seen, failures, real = set(), [], 0
for where, sample in found:
    args = clean(sample)
    key = ' '.join(args)
    if not args or key in seen or '<' in key:  # a placeholder such as <file>.prm
        continue
    seen.add(key)
    if '--print-parameters' in args:
        r = run(args)
    else:
        r = run(args + ['--validate'])
    if key in NEEDS and not os.path.exists(os.path.join(src, NEEDS[key][0])):
        text = r.stderr + r.stdout
        if not (r.returncode == 2 and NEEDS[key][1] in text and 'file not found' in text):
            failures.append(f'{where}: gearfem {sample.strip()} without {NEEDS[key][0]}: exit {r.returncode} '
                            f'(expected 2 naming {NEEDS[key][1]}): {text.strip()[:300]}')
        continue
    if r.returncode != 0:
        failures.append(f'{where}: gearfem {sample.strip()} (--validate) exit {r.returncode}: '
                        f'{(r.stderr or r.stdout).strip()[:300]}')
        continue
    if key in CHEAP:
        with tempfile.TemporaryDirectory() as d:
            r = run(args + ['--output-dir', d], env=dict(os.environ, MPLBACKEND='Agg'))
        real += 1
        if r.returncode != 0:
            failures.append(f'{where}: gearfem {sample.strip()} exit {r.returncode}: {r.stderr.strip()[:300]}')
for f in failures:
    print('FAIL', f)
print(f'sample_runs: {len(seen)} distinct samples from {len(commands)} commands\' --help, README.md and '
      f'inputs/README.md; {len(seen) - len(failures)} passed --validate, {real} of them also ran for real; '
      f'{len(failures)} failed')
sys.exit(1 if failures else 0)
