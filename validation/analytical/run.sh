#!/usr/bin/env bash
# Analytical models (see README.md): the Siasos 2010 AGMA tables with `gearfem rate` (the
# standard's K_H and the thesis' K_H), and the quick unit tests of the closed forms and
# ratings: analytical_tests (lib/analytical), rating_tests and rating_input_tests
# (lib/rating) and gearbox_tests (lib/gearbox), all also in the quick suite. About 30 s.
# check.py ends with PASS or FAIL.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/../lib/common.sh"
tests=(analytical/analytical_tests rating/rating_tests rating/rating_input_tests gearbox/gearbox_tests)
need "$gearfem" "${tests[@]/#/$build/tests/unit/}"
for input in seed001_23_69_rate seed001_23_69_rate_thesis_kh; do
  "$gearfem" rate "$root/inputs/$input.prm" --output-dir "$out/$input" 2>&1 | tee "$out/$input.log"
done
status=()
for t in "${tests[@]}"; do
  name=$(basename "$t")
  rc=0
  "$build/tests/unit/$t" --gtest_brief=1 > "$out/$name.log" 2>&1 || rc=$?
  echo "== $name (exit $rc)"
  tail -3 "$out/$name.log"
  status+=(--tests-status "$name=$rc")
done
check --out "$out" "${status[@]}"
