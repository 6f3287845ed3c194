#!/usr/bin/env bash
# CLI checks of `gearfem optimise` (registered in CMakeLists.txt beside this file).
#   optimise_checks.sh bad   GEARFEM FILE.prm  exit 2, the parameter of its "# expect:" line named,
#                                              no output left, --validate also exits 2
#   optimise_checks.sh short GEARFEM SRC_DIR   a 200-evaluation case-1 COBYLA run: exit 0, every
#                                              file written, objective lowered, optimum feasible,
#                                              no NaN, and the sinusoid row equals Table 5.2 (0.2 %)
#   optimise_checks.sh relief GEARFEM SRC_DIR  a short tip-relief run (coarse sector, COBYLA): exit 0,
#                                              every file written, no NaN, objective not above the
#                                              start's, optimum.prm accepted by `gearfem solve`, and
#                                              robust.csv (Check torques 200, 300) giving the optimum
#                                              the optimiser's p-p at its torque (300 N m, 1e-3); the
#                                              designs ran on a condensed cycle, and a full FE solve of
#                                              optimum.prm gives the optimiser's p-p within 0.5 % of
#                                              the mean STE
set -uo pipefail
mode=$1 gearfem=$2 arg=$3
fail() { echo "FAIL: $*" >&2; exit 1; }
work=$(mktemp -d "${TMPDIR:-/tmp}/gearfem_opt.XXXXXX")
trap 'rm -rf "$work"' EXIT
near_rel() { awk -v a="$1" -v b="$2" -v t="$3" 'BEGIN { d = (a - b) / b; if (d < 0) d = -d; exit !(d <= t) }'; }

case $mode in
  bad)
    expect=$(sed -n 's/^# expect: //p' "$arg")
    "$gearfem" optimise "$arg" --output-dir "$work/out" > "$work/stdout" 2> "$work/stderr"
    rc=$?
    cat "$work/stderr"
    [ $rc -eq 2 ] || fail "exit status $rc (expected 2) for $arg"
    grep -qF "$expect" "$work/stderr" || fail "message does not name '$expect'"
    grep -qi "internal error\|terminate\|Traceback" "$work/stderr" && fail "crash text in stderr"
    [ ! -e "$work/out" ] || [ -z "$(ls -A "$work/out")" ] || fail "output left behind: $(ls "$work/out")"
    "$gearfem" optimise --validate "$arg" > /dev/null 2>&1
    [ $? -eq 2 ] || fail "--validate did not exit 2 for $arg"
    ;;
  short)
    "$gearfem" optimise "$arg/tests/regression/data/optimise/short_case1.prm" --output-dir "$work/out" > "$work/log" 2>&1 \
      || { cat "$work/log"; fail "run failed"; }
    for f in optimise.csv summary.md curvature.csv profiles.csv optimum.prm; do
      [ -s "$work/out/$f" ] || fail "$f missing"
    done
    grep -qi "nan" "$work/out/optimise.csv" "$work/out/curvature.csv" "$work/out/summary.md" && fail "NaN written"
    grep -q "evaluations .*ETA" "$work/log" || fail "no progress line with i/N and ETA"
    # The cobyla row: objective below the start's; the start row is the sinusoid fit.
    start=$(awk -F'|' '$2 ~ /^ start/ { gsub(/ /, "", $5); print $5 }' "$work/out/summary.md")
    best=$(awk -F'|' '$2 ~ /^ cobyla/ { gsub(/ /, "", $5); print $5 }' "$work/out/summary.md")
    awk -v s="$start" -v b="$best" 'BEGIN { exit !(b < 0.5 * s) }' || fail "objective not lowered: $start -> $best"
    last=$(awk -F, '$1 == "cobyla" { v = $5 } END { print v }' "$work/out/optimise.csv")
    near_rel "$last" "$best" 1e-3 || fail "history ends at $last, summary says $best"
    # Sinusoid row against the thesis' Table 5.2: 0.1333, 0.6719, 0.1542 1/mm within 0.2 %.
    read -r mean max std < <(awk -F'|' '$2 ~ /^ sinusoid/ { print $6, $7, $8 }' "$work/out/summary.md")
    near_rel "$mean" 0.1333 2e-3 && near_rel "$max" 0.6719 2e-3 && near_rel "$std" 0.1542 2e-3 \
      || fail "sinusoid row $mean $max $std differs from Table 5.2"
    ;;
  relief)
    "$gearfem" optimise "$arg/tests/regression/data/optimise/short_relief.prm" --output-dir "$work/out" > "$work/log" 2>&1 \
      || { cat "$work/log"; fail "run failed"; }
    for f in optimise.csv ste.csv summary.md optimum.prm robust.csv; do
      [ -s "$work/out/$f" ] || fail "$f missing"
    done
    grep -qi "nan" "$work/out/optimise.csv" "$work/out/ste.csv" "$work/out/summary.md" "$work/out/robust.csv" \
      && fail "NaN written"
    [ "$(wc -l < "$work/out/robust.csv")" -eq 5 ] || fail "robust.csv: not 2 designs x 2 torques"
    # The optimum at 300 N m in the check (another sweep plan) against the optimiser's best.
    best300=$(awk -F, 'NR > 1 { v = $7 } END { print v }' "$work/out/optimise.csv")
    check300=$(awk -F, '$1 == "optimum" && $4 == 300 { print $6 }' "$work/out/robust.csv")
    near_rel "$check300" "$best300" 1e-3 || fail "robust.csv optimum at 300 N m: $check300, optimiser $best300"
    grep -q "evaluations .*ETA" "$work/log" || fail "no progress line with i/N and ETA"
    start=$(awk -F, 'NR == 2 { print $6 }' "$work/out/optimise.csv")
    best=$(awk -F, 'NR > 1 { v = $7 } END { print v }' "$work/out/optimise.csv")
    awk -v s="$start" -v b="$best" 'BEGIN { exit !(b <= s) }' || fail "objective raised: $start -> $best"
    head -1 "$work/out/optimum.prm" | grep -q "^# gearfem solve" || fail "optimum.prm is not a solve case"
    "$gearfem" solve --validate "$work/out/optimum.prm" > "$work/solve.log" 2>&1 || { cat "$work/solve.log"; fail "gearfem solve refuses optimum.prm"; }
    grep -q "designs evaluated on a condensed cycle" "$work/out/summary.md" || fail "the designs did not run on a condensed cycle"
    # The independent check of the condensed route: the optimum solved by the full FE.
    "$gearfem" solve "$work/out/optimum.prm" --output-dir "$work/full" > "$work/full.log" 2>&1 || { cat "$work/full.log"; fail "full solve of optimum.prm failed"; }
    /usr/bin/python3 - "$work/full/sweep.csv" "$best300" <<'PY' || fail "the full FE p-p STE of the optimum differs from the optimiser's"
import csv, sys
rows = [r for r in csv.DictReader(open(sys.argv[1])) if abs(float(r["torque [N m]"]) - 300) < 1e-9]
ste = [float(r["STE [um]"]) for r in rows]
pp, mean, best = max(ste) - min(ste), sum(ste) / len(ste), float(sys.argv[2])
print(f"optimum at 300 N m: full FE p-p {pp:.5f} um, optimiser (condensed cycle) {best:.5f} um, mean STE {mean:.4f} um")
assert abs(pp - best) <= 5e-3 * mean, (pp, best, mean)
PY
    ;;
  *) fail "unknown mode $mode" ;;
esac
echo "PASS: optimise $mode"
