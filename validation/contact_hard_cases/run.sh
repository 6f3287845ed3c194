#!/usr/bin/env bash
# Hard cases of the contact solver (see README.md): runs the validation executable
# validate_hard_cases (about 5 min on 2 cores; rows appear as the cases finish), keeps the
# full output in results/, writes the tracked table.md without timings; check.py ends with
# PASS or FAIL.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/../lib/common.sh"
exe="$build/tests/unit/contact/validate_hard_cases"
need "$exe"
echo "== validate_hard_cases: 10 sweeps (1 N m, 340, 1020 N m, soft gear, eps 2.29, z 14, 3 x tip relief, A/E)"
rc=0
"$exe" 2>&1 | tee "$out/validate_hard_cases.log" || rc=$?  # pipefail: the test's status
check "$out/validate_hard_cases.log" --status "$rc" --table "$here/table.md" --out "$out"
