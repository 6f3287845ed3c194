#!/usr/bin/env bash
# Analytical models (see README.md): the seed 001 AGMA tables with `gearfem rate` (the
# standard's K_H and the thesis' K_H), and the closed-form unit tests of lib/analytical
# (analytical_tests, also in the quick suite). About 30 s. check.py ends with PASS or FAIL.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/../lib/common.sh"
tests="$build/tests/unit/analytical/analytical_tests"
need "$gearfem" "$tests"
for input in seed001_23_69_rate seed001_23_69_rate_thesis_kh; do
  "$gearfem" rate "$root/inputs/$input.prm" --output-dir "$out/$input" 2>&1 | tee "$out/$input.log"
done
rc=0
"$tests" --gtest_brief=1 > "$out/analytical_tests.log" 2>&1 || rc=$?
tail -3 "$out/analytical_tests.log"
check --out "$out" --tests-status "$rc"
