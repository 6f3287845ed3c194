#!/usr/bin/env bash
# Extreme but legal designs (README.md; input-robustness requirement): each case changes one
# entry of base.prm and runs one command; the outcome must be a result (exit 0) or a named
# reason (exit 2, or 3 for a solver failure), never NaN, a hang or a crash. Prints the
# markdown table recorded in validation/RESULTS.md (also results/table.md, with the times)
# and ends with PASS or FAIL.
# Reference: the expected outcome of each design (README.md; section "extreme_designs" of
# RESULTS.md): a legal design gives a result, an out-of-range one a named stop; no tolerance
# (exit status).
#   validation/extreme_designs/run.sh [gearfem] [--quick]
# --quick skips the solve runs.
set -euo pipefail
args_allowed='.*/gearfem'
source "$(dirname "${BASH_SOURCE[0]}")/../lib/common.sh"
gearfem="${1:-$gearfem}"
quick="${2:-}"
need "$gearfem"
work=$(mktemp -d "${TMPDIR:-/tmp}/gearfem_extreme.XXXXXX")
trap 'rm -rf "$work"' EXIT
limit=${GEARFEM_EXTREME_TIMEOUT:-300}
failures=0
n_cases=0

# case NAME COMMAND EXPECT KEY=VALUE...: EXPECT is the allowed exit statuses ("0", "2", "0|2").
run_case() {
  local name=$1 cmd=$2 expect=$3; shift 3
  declare -A v=([MODULE]=3 [ADDENDUM]=1.0 [Z1]=50 [Z2]=50 [FACE]=20 [PLANE]="plane stress" [NU]=0.3
                [H]=0.5 [HBODY]=3 [MODEL]=sector [TORQUE]=200 [POSITIONS]=list [NPOS]=40 [ROLL]=0.37)
  for kv in "$@"; do v[${kv%%=*}]="${kv#*=}"; done
  local f="$work/$name.prm" k
  local args=()
  for k in "${!v[@]}"; do args+=(-e "s|@$k@|${v[$k]}|"); done
  sed "${args[@]}" "$here/base.prm" > "$f"
  local t0 t1 rc=0 what
  t0=$(date +%s.%N)
  timeout "$limit" "$gearfem" $cmd "$f" --output-dir "$work/out_$name" > "$work/$name.out" 2> "$work/$name.err" || rc=$?
  t1=$(date +%s.%N)
  if [ $rc -eq 0 ]; then
    what=$(grep -hE "contact ratio|eps_alpha|STE|sigma_H|quadrilaterals|mean" "$work/$name.out" | head -2 | tr '\n' ' ' | cut -c1-150 || true)
    if [ -f "$work/out_$name/sweep.csv" ]; then
      # STE and F_n of every row of the solve sweep.
      what=$(awk -F, 'NR == 1 { for (i = 1; i <= NF; i++) { if ($i == "STE [um]") s = i; if ($i == "F_n [N]") f = i; if ($i == "torque [N m]") t = i }; next }
                      { printf "T %s N m: STE %.5g um, F_n %.5g N; ", $t, $s, $f }' "$work/out_$name/sweep.csv")
    fi
    if grep -rqiE "(^|,)\s*[-+]?(nan|inf)" "$work/out_$name"/*.csv 2> /dev/null; then
      what="NaN/inf in a CSV file"; rc=99
    fi
  else
    what=$(grep -v "^$" "$work/$name.err" | tail -1 | sed 's/^gearfem: //' | cut -c1-300 || true)
  fi
  if [ $rc -eq 124 ]; then what="hang: killed after $limit s"; fi
  local ok=yes
  [[ "|$expect|" == *"|$rc|"* ]] || { ok=NO; failures=$((failures + 1)); }
  if grep -qi "internal error\|terminate\|Sanitizer" "$work/$name.err"; then ok=NO; failures=$((failures + 1)); fi
  n_cases=$((n_cases + 1))
  printf '| %s | `%s` | %d | %.1f | %s | %s |\n' "$name" "$cmd" "$rc" "$(echo "$t1 - $t0" | bc)" "${what//|/\\|}" "$ok"
  rm -rf "$work/out_$name"
}

exec > >(tee "$out/table.md")  # the table with times goes to results/ (git-ignored)
echo "| case | command | exit | time [s] | outcome | as expected |"
echo "|---|---|---|---|---|---|"
run_case z1_5             profile 2   Z1=5
run_case z1_5_rate        rate    2   Z1=5
run_case z2_10000         profile 0   Z2=10000
run_case z2_10000_rate    rate    0   Z2=10000
run_case z2_10000_mesh    mesh    0   Z2=10000
run_case z2_10000_full_mesh mesh  2   Z2=10000 "MODEL=full gear"
run_case m_0.1            profile 0   MODULE=0.1
run_case m_0.1_mesh       mesh    2   MODULE=0.1
run_case m_0.1_mesh_fine  mesh    0   MODULE=0.1 H=0.02 HBODY=0.1
run_case m_50             profile 0   MODULE=50
run_case m_50_rate        rate    0   MODULE=50
run_case m_50_mesh        mesh    "0|2" MODULE=50 H=5 HBODY=50
run_case b_0.1_rate       rate    "0|2" FACE=0.1
run_case b_1000_rate      rate    "0|2" FACE=1000
run_case torque_1e-3_rate rate    0   TORQUE=1e-3
run_case eps_just_above_1 profile 0   ADDENDUM=0.55
run_case eps_below_1      profile 2   ADDENDUM=0.5
if [ "$quick" != "--quick" ]; then
  run_case torque_1e-3      solve 0   TORQUE=1e-3
  # The same on a 8x finer contact mesh: q ~ 6e-9 rad, whose iterates differ by round-off
  # (exit 3, "did not settle", before the 100-ulp floor on the rotation test).
  run_case torque_1e-3_fine solve 0   TORQUE=1e-3 H=0.0625
  run_case torque_huge      solve 2   TORQUE=1e6
  run_case torque_limit_ok  solve 0   TORQUE=2000
  run_case nu_0.499_strain  solve 0   NU=0.499 "PLANE=plane strain"
  run_case nu_0.499_stress  solve 0   NU=0.499
  run_case eps_just_above_1_solve solve "0|3" ADDENDUM=0.55
  run_case duplicate_roll   solve "0|2" ROLL="0.37, 0.37"
  run_case one_position     solve 0   POSITIONS=cycle NPOS=1
fi
echo
if [ $failures -eq 0 ]; then
  echo "extreme_designs: PASS ($n_cases cases as expected)"
else
  echo "extreme_designs: FAIL ($failures unexpected outcomes of $n_cases cases)"
  exit 1
fi
