#!/usr/bin/env bash
# 2-D Hertz line contact (see README.md): runs the validation executable validate_hertz
# (both methods, plane stress/strain, equal and dissimilar discs, h = a/4..a/16; about 15 min
# on 2 cores), keeps its full output in results/, writes the tracked convergence.md without
# timings, and check.py compares p0 and a with Johnson's closed form (ends with PASS/FAIL).
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/../lib/common.sh"
exe="$build/tests/unit/contact/validate_hertz"
need "$exe"
echo "== validate_hertz: 24 solves (4 disc cases x 2 methods x 3 meshes); rows appear as they finish"
rc=0
"$exe" --gtest_brief=1 2>&1 | tee "$out/validate_hertz.log" || rc=$?  # pipefail: the test's status
check "$out/validate_hertz.log" --status "$rc" --table "$here/convergence.md" --out "$out"
