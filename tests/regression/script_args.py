#!/usr/bin/python3
"""The argument handling of every validation and study script, from a clean copy of the tree.

Copies the tracked files (git ls-files; without git: validation/, scripts/, inputs/ without
results) to a temporary folder, so that no result of an earlier run exists, then runs each
validation/<case>/*.sh, scripts/validate and scripts/fuzz_inputs
  - with --help: exit 0 and the script's header on stdout;
  - with an argument it does not take: exit 2 naming it, before any work: no file of the copy
    changes and none is created (the class of defect of a script that tees into a folder it
    has not created yet, or stops on its first step from a clean clone).

  script_args.py SRC_DIR
"""
import os
import shutil
import subprocess
import sys
import tempfile


def tracked(src):
    try:
        out = subprocess.run(["git", "-C", src, "ls-files"], capture_output=True, text=True, check=True).stdout
        files = [f for f in out.splitlines() if f]
        if files:
            return files
    except (OSError, subprocess.CalledProcessError):
        pass
    files = []
    for top in ("validation", "scripts", "inputs"):
        for d, dirs, fs in os.walk(os.path.join(src, top)):
            dirs[:] = [x for x in dirs if x not in ("results",) and not x.startswith("out")]
            files += [os.path.relpath(os.path.join(d, f), src) for f in fs]
    return files


def snapshot(root):
    out = {}
    for d, _, fs in os.walk(root):
        for f in fs:
            p = os.path.join(d, f)
            st = os.stat(p)
            out[os.path.relpath(p, root)] = (st.st_size, st.st_mtime_ns)
    return out


def main():
    src = os.path.abspath(sys.argv[1])
    work = tempfile.mkdtemp(prefix="gearfem_script_args.")
    try:
        for f in tracked(src):
            if f.startswith(("validation/", "scripts/", "inputs/")) and os.path.isfile(os.path.join(src, f)):
                os.makedirs(os.path.dirname(os.path.join(work, f)), exist_ok=True)
                shutil.copy2(os.path.join(src, f), os.path.join(work, f))
        scripts = sorted(os.path.relpath(os.path.join(d, f), work)
                         for d, _, fs in os.walk(os.path.join(work, "validation")) for f in fs
                         if f.endswith(".sh") and os.path.basename(d) != "lib")
        scripts += ["scripts/validate", "scripts/fuzz_inputs"]
        env = dict(os.environ, GEARFEM_BUILD_DIR=os.path.join(work, "no-build"))
        failures = []
        before = snapshot(work)
        for s in scripts:
            h = subprocess.run(["bash", s, "--help"], cwd=work, capture_output=True, text=True, timeout=60, env=env)
            if h.returncode != 0 or len(h.stdout.strip()) < 20:
                failures.append(f"{s} --help: exit {h.returncode}, {len(h.stdout)} characters of help")
            b = subprocess.run(["bash", s, "--no-such-argument"], cwd=work, capture_output=True, text=True, timeout=60,
                               env=env)
            if b.returncode != 2 or "--no-such-argument" not in b.stderr:
                failures.append(f"{s} --no-such-argument: exit {b.returncode} (expected 2 naming it): "
                                f"{(b.stderr.strip().splitlines() or [''])[-1][:160]}")
            after = snapshot(work)
            if after != before:
                changed = sorted(set(after) ^ set(before) | {k for k in after if k in before and after[k] != before[k]})
                failures.append(f"{s}: the refused or --help call changed files: {changed[:5]}")
                before = after
        for f in failures:
            print("FAIL:", f)
        print(f"script_args: {len(scripts)} scripts, --help and a refused argument each from a clean copy; "
              f"{len(failures)} failing")
        return 1 if failures else 0
    finally:
        shutil.rmtree(work, ignore_errors=True)


if __name__ == "__main__":
    sys.exit(main())
