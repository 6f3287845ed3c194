#!/usr/bin/env bash
# Quick checks of `gearfem batch` on the tiny study of data/batch:
# sector models of a 20/40 pair, 3 designs x 2 torques x 5 positions.
#   batch_checks.sh mpi     GEARFEM SRC_DIR  mpirun -np 2 equals the serial run; the numbers of
#                                            one design equal `gearfem solve` of that design
#                                            written by hand, and its batch.csv row equals the
#                                            statistics computed here from that solve's sweep.csv
#                                            (and batch.h5 equals batch.csv; slices 1/2 and 2/2
#                                            merged by --merge equal the whole batch)
#   batch_checks.sh restart GEARFEM SRC_DIR  a batch killed with SIGKILL after its first job,
#                                            re-run, skips the finished job and completes
#   batch_checks.sh failure GEARFEM SRC_DIR  an invalid design and a failing solve are recorded
#                                            in the status column, the good design completes,
#                                            exit status 4; --validate lists the invalid one
#   batch_checks.sh shared  GEARFEM SRC_DIR  with Contact/Micro-geometry = gap, designs that differ
#                                            only in tip relief share one factorised model (job.txt
#                                            shared_model), and each job's sweep equals `gearfem
#                                            solve` of its design.prm (a fresh model) to 1e-9 of
#                                            each column's scale (Batch/Condensed cycle = off);
#                                            with the default (auto) the three sharing designs run
#                                            on one condensed cycle
#                                            (job.txt route) within 0.1 % STE and 0.5 % root
#                                            stress of those fresh solves
#   batch_checks.sh isolation GEARFEM SRC_DIR  a design that crashes its worker on purpose
#                                            (GEARFEM_TEST_FAULT=shift:segv, and :abort under
#                                            mpirun -np 2) and one that hangs past Batch/Job time
#                                            limit (10 s) are failed jobs naming the signal or the limit;
#                                            the others finish, equal to a run without the fault
#                                            and to Job isolation = none, the merge runs, exit 4
#   batch_checks.sh routes  GEARFEM SRC_DIR  designs that carry Solve/Target or a Deviations grade
#                                            take route::run's route (job.txt route target /
#                                            hunting, record.json "route"), the plain design the
#                                            full FE; each equals `gearfem solve` of its design.prm
#                                            to 1e-9 of each column's scale (the same library call)
#   batch_checks.sh bad     GEARFEM SRC_DIR  unknown parameter path, malformed row, value that
#                                            is not a number: exit 2 naming column and row,
#                                            before any job (no jobs folder), also under mpirun
set -uo pipefail
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
mode=$1 gearfem=$2 src=$3
fail() { echo "FAIL: $*" >&2; exit 1; }
work=$(mktemp -d "${TMPDIR:-/tmp}/gearfem_batch.XXXXXX")
trap 'rm -rf "$work"' EXIT
data=$src/tests/regression/data/batch
# study TABLE: the tiny study with its design table replaced, in $work/study.prm
study() { sed -e "s|Design table = designs.csv|Design table = $data/$1|" "$data/study.prm" > "$work/study.prm"; }

case $mode in
  mpi)
    study designs.csv
    "$gearfem" batch "$work/study.prm" --output-dir "$work/serial" > "$work/serial.log" 2>&1 ||
      { cat "$work/serial.log"; fail "serial batch failed"; }
    mpirun -np 2 "$gearfem" batch "$work/study.prm" --output-dir "$work/mpi" > "$work/mpi.log" 2>&1 ||
      { cat "$work/mpi.log"; fail "mpirun -np 2 batch failed"; }
    cat "$work/mpi.log"
    # Rank 0 alone prints: one line per job, one final summary.
    [ "$(grep -c '^batch: job ' "$work/mpi.log")" -eq 3 ] || fail "expected 3 job lines from rank 0 only"
    [ "$(grep -c '^results in ' "$work/mpi.log")" -eq 1 ] || fail "more than one rank wrote the run record"
    grep -q 'rank 1,' "$work/mpi.log" || fail "rank 1 ran no job"
    # Independent case of design 'soft': the study with E2 = 100 GPa appended by hand (a later
    # `set` overrides an earlier one), solved by `gearfem solve`.
    { cat "$work/study.prm"; printf 'subsection Material\n  subsection Gear 2\n    set Young'"'"'s modulus = 100\n  end\nend\nsubsection Solve\n  set VTU = none\nend\n'; } > "$work/soft.prm"
    "$gearfem" solve "$work/soft.prm" --output-dir "$work/soft" > "$work/soft.log" 2>&1 ||
      { cat "$work/soft.log"; fail "solve of the soft design failed"; }
    /usr/bin/python3 - "$work" <<'PY' || fail "batch results differ"
import csv, sys
w = sys.argv[1]
def rows(path):
    r = list(csv.reader(open(path)))
    return r[0], r[1:]
def close(u, v, rel=1e-12):
    return abs(u - v) <= rel * max(1.0, abs(u), abs(v))
# 1. np=2 equals np=1, every column but the wall times.
hs, rs = rows(f"{w}/serial/batch.csv")
hm, rm = rows(f"{w}/mpi/batch.csv")
assert hs == hm and len(rs) == len(rm) == 6, (len(rs), len(rm))
for a, b in zip(rs, rm):
    for h, u, v in zip(hs, a, b):
        if h in ("wall time [s]",):
            continue
        if h.endswith("[text]"):
            assert u == v, (h, u, v)
        else:
            assert close(float(u), float(v)), (h, u, v)
assert all(r[-1] == "ok" for r in rs), [r[-1] for r in rs]
for job in ("base", "shift", "soft"):
    hj, a = rows(f"{w}/serial/jobs/{job}/sweep.csv")
    _, b = rows(f"{w}/mpi/jobs/{job}/sweep.csv")
    assert len(a) == len(b) == 10, (job, len(a), len(b))
    t = hj.index("time [s]")
    for x, y in zip(a, b):
        assert all(close(float(u), float(v)) for i, (u, v) in enumerate(zip(x, y)) if i != t), job
print("np=2 equals np=1: 6 rows of batch.csv, 3 x 10 rows of sweep.csv")
# 2. Design 'soft' equals gearfem solve of the hand-written case.
hj, a = rows(f"{w}/serial/jobs/soft/sweep.csv")
hs2, b = rows(f"{w}/soft/sweep.csv")
assert hj == hs2 and len(a) == len(b)
t = hj.index("time [s]")
for x, y in zip(a, b):
    assert all(close(float(u), float(v), 1e-10) for i, (u, v) in enumerate(zip(x, y)) if i != t)
# 3. Its batch.csv rows equal the statistics of that solve's sweep.csv.
col = {n: i for i, n in enumerate(hs2)}
agg = {n: i for i, n in enumerate(hs)}
for T in (100.0, 200.0):
    sel = [r for r in b if float(r[col["torque [N m]"]]) == T]
    ste = [float(r[col["STE [um]"]]) for r in sel]
    k = [float(r[col["k_secant per width [N/(mm um)]"]]) for r in sel]
    row = [r for r in rs if r[agg["id [text]"]] == "soft" and float(r[agg["torque [N m]"]]) == T][0]
    want = {"positions [-]": len(sel), "STE mean [um]": sum(ste) / len(ste),
            "STE peak-to-peak [um]": max(ste) - min(ste),
            "k_secant per width mean [N/(mm um)]": sum(k) / len(k),
            "k_secant per width min [N/(mm um)]": min(k), "k_secant per width max [N/(mm um)]": max(k),
            "p_max [MPa]": max(float(r[col["p_max [MPa]"]]) for r in sel),
            "root stress pinion [MPa]": max(float(r[col["root stress pinion [MPa]"]]) for r in sel),
            "root stress gear [MPa]": max(float(r[col["root stress gear [MPa]"]]) for r in sel),
            "Material/Gear 2/Young's modulus [GPa]": 100.0}
    for n, v in want.items():
        assert close(float(row[agg[n]]), v, 1e-8), (n, row[agg[n]], v)
    assert 1.3 < float(row[agg["contact ratio [-]"]]) < 2.0
# 4. Physics: the softer gear gives the larger mean STE at each torque.
for T in ("100", "200"):
    m = {r[agg["id [text]"]]: float(r[agg["STE mean [um]"]]) for r in rs if r[agg["torque [N m]"]] == T}
    assert m["soft"] > 1.2 * m["base"], m
print("design 'soft' equals gearfem solve of its case; its batch.csv rows equal the sweep statistics")
# 5. batch.h5 holds the same numbers as batch.csv (if h5py is there).
try:
    import h5py
except ImportError:
    sys.exit(0)
with h5py.File(f"{w}/serial/batch.h5", "r") as f:
    assert f.attrs["format"] in ("gearfem-batch", b"gearfem-batch")
    g = f["batch"]
    for h in hs:
        name = h.replace("/", "|") if h.startswith(("Gear", "Material")) else h.replace("/", " per ")
        v = g[name][()]
        assert len(v) == 6, h
        for x, r in zip(v, rs):
            x = x.decode() if isinstance(x, bytes) else x
            assert (x == r[hs.index(h)]) if h.endswith("[text]") else close(float(x), float(r[hs.index(h)]), 1e-9), (h, x)
print("batch.h5 equals batch.csv")
PY
    # Job-array slices 1/2 and 2/2, then --merge: the same table as the whole batch.
    "$gearfem" batch "$work/study.prm" --slice 1/2 --output-dir "$work/sliced" > "$work/s1.log" 2>&1 || { cat "$work/s1.log"; fail "slice 1/2"; }
    [ ! -e "$work/sliced/batch.csv" ] || fail "a slice wrote batch.csv"
    "$gearfem" batch "$work/study.prm" --slice 2/2 --output-dir "$work/sliced" > "$work/s2.log" 2>&1 || { cat "$work/s2.log"; fail "slice 2/2"; }
    grep -q "slice 2/2 holds 1" "$work/s2.log" || fail "slice 2/2 does not hold 1 design"
    "$gearfem" batch "$work/study.prm" --merge --output-dir "$work/sliced" > "$work/merge.log" 2>&1 || { cat "$work/merge.log"; fail "--merge"; }
    diff <(cut -d, -f1-15,17 "$work/serial/batch.csv") <(cut -d, -f1-15,17 "$work/sliced/batch.csv") || fail "merged slices differ from the whole batch"
    echo "slices 1/2 + 2/2 merged equal the whole batch"
    ;;
  restart)
    study designs.csv
    # 20 positions per torque (a later `set` overrides the study's 5): jobs long enough to
    # kill the batch between two jobs.
    printf 'subsection Solve\n  set Number of positions = 20\nend\n' >> "$work/study.prm"
    "$gearfem" batch "$work/study.prm" --output-dir "$work/out" > "$work/kill.log" 2>&1 &
    pid=$!
    for _ in $(seq 1 2400); do
      n=$(ls "$work"/out/jobs/*/job.txt 2> /dev/null | wc -l)
      [ "$n" -ge 1 ] && break
      kill -0 $pid 2> /dev/null || break
      sleep 0.05
    done
    kill -9 $pid 2> /dev/null || fail "the batch ended before it could be killed"
    wait $pid 2> /dev/null
    done_before=$(ls "$work"/out/jobs/*/job.txt | wc -l)
    [ "$done_before" -ge 1 ] && [ "$done_before" -lt 3 ] || fail "$done_before jobs finished before the kill (expected 1 or 2)"
    [ ! -e "$work/out/batch.csv" ] || fail "a killed batch wrote batch.csv"
    ls -R "$work/out" | grep -q '\.tmp\.' && fail "temporary file left at the kill point is visible as a result"
    finished=$(for f in "$work"/out/jobs/*/job.txt; do basename "$(dirname "$f")"; done)
    sums=$(cd "$work/out/jobs" && md5sum */job.txt */results.h5)
    "$gearfem" batch "$work/study.prm" --output-dir "$work/out" > "$work/restart.log" 2>&1 ||
      { cat "$work/restart.log"; fail "restarted batch failed"; }
    cat "$work/restart.log"
    grep -q "$done_before finished before (skipped)" "$work/restart.log" || fail "the restart did not skip the $done_before finished jobs"
    [ "$(grep -c '^batch: job ' "$work/restart.log")" -eq $((3 - done_before)) ] || fail "the restart ran more jobs than were unfinished"
    for j in $finished; do
      grep -q "($j," "$work/restart.log" && fail "finished job $j ran again"
    done
    (cd "$work/out/jobs" && echo "$sums" | md5sum -c --quiet) || fail "the files of a finished job changed"
    [ "$(tail -n +2 "$work/out/batch.csv" | grep -c ',ok$')" -eq 6 ] || fail "batch.csv does not hold 6 ok rows"
    # A changed design re-runs alone: change E2 of 'soft' only.
    sed -e 's/^soft,0,100$/soft,0,110/' "$data/designs.csv" > "$work/changed.csv"
    sed -e "s|Design table = .*|Design table = $work/changed.csv|" "$work/study.prm" > "$work/changed.prm"
    "$gearfem" batch "$work/changed.prm" --output-dir "$work/out" > "$work/changed.log" 2>&1 ||
      { cat "$work/changed.log"; fail "batch with one changed design failed"; }
    grep -q "2 finished before (skipped)" "$work/changed.log" || { cat "$work/changed.log"; fail "the unchanged designs were not skipped"; }
    grep -q "(soft," "$work/changed.log" || fail "the changed design did not re-run"
    ;;
  failure)
    study failing.csv
    "$gearfem" batch "$work/study.prm" --output-dir "$work/out" > "$work/log" 2>&1
    rc=$?
    cat "$work/log"
    [ $rc -eq 4 ] || fail "exit status $rc (expected 4: some jobs failed)"
    grep -qi "terminate\|Traceback\|internal error" "$work/log" && fail "crash text"
    /usr/bin/python3 - "$work/out/batch.csv" <<'PY' || fail "batch.csv does not record the failures"
import csv, sys
r = list(csv.reader(open(sys.argv[1])))
h, rows = r[0], r[1:]
i, s = h.index("id [text]"), h.index("status [text]")
st = {}
for row in rows:
    st.setdefault(row[i], []).append(row)
assert len(st["good"]) == 2 and all(x[s] == "ok" for x in st["good"]), st["good"]
assert all(float(x[h.index("STE mean [um]")]) > 0 for x in st["good"])
bad = st["interfering"][0][s]
assert bad.startswith("failed: invalid design") and "interference" in bad, bad
nc = st["nocontact"][0][s]
assert nc.startswith("failed: solver failure") and "no contact" in nc, nc
# A failed design has its torques but no numbers.
assert [x[h.index("torque [N m]")] for x in st["interfering"]] == ["100", "200"]
assert st["interfering"][0][h.index("STE mean [um]")] == ""
print("good: ok; interfering:", bad[:90], "...; nocontact:", nc[:70], "...")
PY
    [ -s "$work/out/jobs/good/results.h5" ] || fail "the good design's results.h5 is missing"
    grep -q "^status failed" "$work/out/jobs/interfering/job.txt" || fail "no failed record for the invalid design"
    "$gearfem" batch "$work/study.prm" --validate > "$work/v.log" 2>&1
    rc=$?
    cat "$work/v.log"
    [ $rc -eq 2 ] || fail "--validate: exit status $rc (expected 2)"
    grep -q "1 of 3 designs are invalid" "$work/v.log" || fail "--validate does not count the invalid design"
    grep -q "design interfering (row 5 of" "$work/v.log" || fail "--validate does not name the design and its row"
    ;;
  shared)
    study relief_designs.csv
    printf 'subsection Contact\n  set Micro-geometry = gap\nend\n' >> "$work/study.prm"
    cp "$work/study.prm" "$work/study_auto.prm"
    printf 'subsection Batch\n  set Condensed cycle = off\nend\n' >> "$work/study.prm"
    "$gearfem" batch "$work/study.prm" --output-dir "$work/out" > "$work/log" 2>&1 ||
      { cat "$work/log"; fail "gap-route batch failed"; }
    cat "$work/log"
    grep -q "4 jobs (2 distinct models)" "$work/log" || fail "the plan does not count 2 distinct models"
    for j in none soft; do grep -q "^shared_model 0" "$work/out/jobs/$j/job.txt" || fail "$j did not build its model"; done
    for j in short long; do grep -q "^shared_model 1" "$work/out/jobs/$j/job.txt" || fail "$j did not re-use the model of 'none'"; done
    for j in none short long soft; do
      "$gearfem" solve "$work/out/jobs/$j/design.prm" --output-dir "$work/solo_$j" > "$work/solo_$j.log" 2>&1 ||
        { cat "$work/solo_$j.log"; fail "solve of $j failed"; }
    done
    /usr/bin/python3 - "$work" <<'PY' || fail "a job on a re-used model differs from a fresh solve"
import csv, sys
w = sys.argv[1]
def rows(path):
    r = list(csv.reader(open(path)))
    return r[0], r[1:]
ste = {}
for j in ("none", "short", "long", "soft"):
    h, a = rows(f"{w}/out/jobs/{j}/sweep.csv")
    h2, b = rows(f"{w}/solo_{j}/sweep.csv")
    assert h == h2 and len(a) == len(b) == 10, (j, len(a), len(b))
    t = h.index("time [s]")
    # To the contact tolerance, 1e-9 of each column's scale: a re-used model's cached
    # flexibility columns differ in their last bits from a fresh model's (see cli_checks.sh
    # resume), which moves the results by about 1e-12 of a column's scale.
    scale = [max([1.0] + [abs(float(r[i])) for r in a]) for i in range(len(h))]
    for x, y in zip(a, b):
        for i, (u, v) in enumerate(zip(x, y)):
            if i != t:
                assert abs(float(u) - float(v)) <= 1e-9 * scale[i], (j, h[i], u, v)
    ste[j] = [float(r[h.index("STE [um]")]) for r in a]
# The relief changes the STE where it acts (the re-targeting is not a no-op), and the longer
# relief at the same amount removes more material, so its mean STE is at least that of the short.
assert max(abs(u - v) for u, v in zip(ste["none"], ste["long"])) > 0.1, (ste["none"], ste["long"])
assert sum(ste["long"]) >= sum(ste["short"]) >= sum(ste["none"]), ste
print("re-used models: short and long equal fresh solves of their design.prm to 1e-9 of each column")
PY
    # The default route: none, short and long share a model and ask for 6 torque sweeps, so
    # they run on one condensed cycle; soft has its own model and 2 sweeps: a full solve.
    "$gearfem" batch "$work/study_auto.prm" --output-dir "$work/auto" > "$work/auto.log" 2>&1 ||
      { cat "$work/auto.log"; fail "gap-route batch with the condensed cycle failed"; }
    for j in none short long; do grep -q "^route condensed" "$work/auto/jobs/$j/job.txt" || fail "$j did not run on the condensed cycle"; done
    grep -q "^route full" "$work/auto/jobs/soft/job.txt" || fail "soft (its own model, 2 sweeps) did not run in full"
    /usr/bin/python3 - "$work" <<'PY' || fail "a job on the condensed cycle is off the fresh solve"
import csv, sys
w = sys.argv[1]
def rows(path):
    r = list(csv.reader(open(path)))
    return r[0], r[1:]
worst = {}
for j in ("none", "short", "long", "soft"):
    h, a = rows(f"{w}/auto/jobs/{j}/sweep.csv")
    h2, b = rows(f"{w}/solo_{j}/sweep.csv")
    assert h == h2 and len(a) == len(b) == 10, (j, len(a), len(b))
    for name, tol in (("STE [um]", 1e-3), ("root stress pinion [MPa]", 5e-3), ("root stress gear [MPa]", 5e-3)):
        i = h.index(name)
        for x, y in zip(a, b):
            d = abs(float(x[i]) - float(y[i])) / abs(float(y[i]))
            worst[name] = max(worst.get(name, 0), d)
            assert d <= tol, (j, name, x[i], y[i])
print("condensed cycle: worst relative differences from fresh solves", worst)
PY
    ;;
  isolation)
    study designs.csv
    "$gearfem" batch "$work/study.prm" --output-dir "$work/clean" > "$work/clean.log" 2>&1 ||
      { cat "$work/clean.log"; fail "batch without a fault failed"; }
    cp "$work/study.prm" "$work/inproc.prm"
    printf 'subsection Batch\n  set Job isolation = none\nend\n' >> "$work/inproc.prm"
    "$gearfem" batch "$work/inproc.prm" --output-dir "$work/inproc" > "$work/inproc.log" 2>&1 ||
      { cat "$work/inproc.log"; fail "batch with Job isolation = none failed"; }
    # faulty RUN FAULT [mpirun -np 2]: the batch with one faulty design in $work/RUN
    faulty() {
      local run=$1 fault=$2; shift 2
      GEARFEM_TEST_FAULT=$fault timeout 240 "$@" "$gearfem" batch "$work/${prm:-study.prm}" --output-dir "$work/$run" \
        > "$work/$run.log" 2>&1
      local rc=$?
      cat "$work/$run.log"
      [ $rc -eq 4 ] || fail "$run: exit status $rc (expected 4: some jobs failed)"
      [ -s "$work/$run/batch.csv" ] || fail "$run: no merged batch.csv"
      # (only this run's workers: other batch tests may run beside this one)
      pgrep -f -- "--output-dir $work/$run --batch-worker" > /dev/null && fail "$run: a worker process outlived the batch"
      return 0
    }
    faulty segv shift:segv
    faulty abort base:abort mpirun -np 2
    # 10 s: ten times a normal job of this study with its worker's start, on a loaded machine.
    printf 'subsection Batch\n  set Job time limit = 10\nend\n' >> "$work/study.prm"
    faulty hang soft:hang
    /usr/bin/python3 - "$work" <<'PY' || fail "the faulty batches do not record the faults as said"
import csv, sys
w = sys.argv[1]
def table(run):
    r = list(csv.reader(open(f"{w}/{run}/batch.csv")))
    h, rows = r[0], r[1:]
    out = {}
    for row in rows:
        out.setdefault(row[h.index("id [text]")], []).append(dict(zip(h, row)))
    return out
clean, inproc = table("clean"), table("inproc")
# Under AddressSanitizer (scripts/sanitize) its SEGV handler reports the fault and then aborts:
# the worker ends with SIGABRT instead of SIGSEGV.
for run, bad, words in (("segv", "shift", ("crashed", ("SIGSEGV", "SIGABRT"))), ("abort", "base", ("crashed", "SIGABRT")),
                        ("hang", "soft", ("Job time limit = 10 s", "killed"))):
    t = table(run)
    st = t[bad][0]["status [text]"]
    assert st.startswith("failed: ") and all(any(y in st for y in (x if isinstance(x, tuple) else (x,)))
                                             for x in words), (run, st)
    assert [r["torque [N m]"] for r in t[bad]] == ["100", "200"] and t[bad][0]["STE mean [um]"] == "", run
    for d, rows in t.items():
        if d == bad:
            continue
        for r, c, i in zip(rows, clean[d], inproc[d]):
            assert r["status [text]"] == "ok", (run, d, r["status [text]"])
            for k, v in r.items():
                if k != "wall time [s]" and not k.endswith("[text]"):
                    assert float(v) == float(c[k]) == float(i[k]), (run, d, k, v, c[k], i[k])
print("segv, abort (np 2) and hang: one failed job each naming the fault; the others equal the clean run")
PY
    grep -q "1 failed" "$work/segv.log" || fail "segv: the summary does not count one failure"
    ;;
  routes)
    study routes.csv
    "$gearfem" batch "$work/study.prm" --output-dir "$work/b" > "$work/b.log" 2>&1 ||
      { cat "$work/b.log"; fail "batch with Target and Deviations designs failed"; }
    # Each design written by hand: the study with the design's values appended (a later `set`
    # overrides an earlier one; design.prm lists every entry, defaults included, so a Target
    # run on it would take the listed Mesh and FE entries as set by the user).
    printf '' > "$work/plain.add"
    printf 'subsection Solve\n  set Target = mean STE 5\nend\n' > "$work/target.add"
    printf 'subsection Deviations\n  set Accuracy grade = 6\nend\n' > "$work/graded.add"
    for d in plain:full target:target graded:hunting; do
      id=${d%%:*} route=${d##*:}
      grep -q '^status ok$' "$work/b/jobs/$id/job.txt" || { cat "$work/b/jobs/$id/job.txt"; fail "design $id failed"; }
      grep -q "^route $route\$" "$work/b/jobs/$id/job.txt" || { cat "$work/b/jobs/$id/job.txt"; fail "design $id: route not $route"; }
      cat "$work/study.prm" "$work/$id.add" > "$work/$id.prm"
      "$gearfem" solve "$work/$id.prm" --output-dir "$work/s_$id" > "$work/s_$id.log" 2>&1 ||
        { cat "$work/s_$id.log"; fail "gearfem solve of design $id failed"; }
      TOL=1e-9 /usr/bin/python3 "$src/tests/regression/compare_outputs.py" "$work/s_$id" "$work/b/jobs/$id" sweep.csv pairs.csv ||
        fail "design $id: batch and solve differ"
    done
    grep -q '"route": {"name": "Solve/Target"' "$work/b/jobs/target/record.json" || fail "record.json of the Target design"
    grep -q '"model_choice"' "$work/b/jobs/target/record.json" || fail "no model_choice member for the Target design"
    grep -q '"name": "hunting cycle' "$work/b/jobs/graded/record.json" || fail "record.json of the Deviations design"
    [ -f "$work/b/jobs/graded/spectrum.csv" ] || fail "the Deviations design wrote no spectrum.csv"
    echo "routes: OK"
    ;;
  bad)
    check() { # TABLE EXPECT...: exit 2, each EXPECT in stderr, no job started
      study "$1"; shift
      "$gearfem" batch "$work/study.prm" --output-dir "$work/out" > "$work/stdout" 2> "$work/stderr"
      rc=$?
      cat "$work/stderr"
      [ $rc -eq 2 ] || fail "exit status $rc (expected 2)"
      for e in "$@"; do grep -qF "$e" "$work/stderr" || fail "message does not name '$e'"; done
      [ ! -e "$work/out" ] || fail "output left behind: $(ls -R "$work/out")"
    }
    check unknown_path.csv "column 'Gear 1/Tip relief amout'" "row 2 of" "unknown parameter path"
    check malformed.csv "row 3" "2 cells" "3 cells"
    check not_a_number.csv "column 'Material/Gear 2/Young's modulus'" "row 3 of" "2O7"
    # Under mpirun: the same exit status, and only rank 0 prints the message.
    study unknown_path.csv
    mpirun -np 2 "$gearfem" batch "$work/study.prm" --output-dir "$work/out" > "$work/stdout" 2> "$work/stderr"
    rc=$?
    cat "$work/stderr"
    [ $rc -eq 2 ] || fail "mpirun: exit status $rc (expected 2)"
    [ "$(grep -c 'gearfem: error' "$work/stderr")" -eq 1 ] || fail "mpirun: the error is not printed once"
    [ ! -e "$work/out" ] || fail "mpirun: output left behind"
    # --slice outside 1..N and --merge on another command are bad input too.
    "$gearfem" batch "$work/study.prm" --slice 3/2 > /dev/null 2>&1; [ $? -eq 2 ] || fail "--slice 3/2 not exit 2"
    "$gearfem" solve "$work/study.prm" --merge > /dev/null 2>&1; [ $? -eq 2 ] || fail "solve --merge not exit 2"
    ;;
  *) fail "unknown mode $mode" ;;
esac
