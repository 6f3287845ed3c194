#!/usr/bin/env bash
# Internal gear, pinion z 24 inside a ring z 60 (see README.md): runs the validation
# executable validate_internal_gear (Hertz at C on 3 meshes; the ring root stress over a
# mesh cycle for 7 backup ratios x 4 rim supports; ISO 6336-3; equilibrium; about 4 min on
# 2 cores), keeps its full output in results/, writes the tracked table.md (no timings) and
# rim_thickness.png; check.py ends with `internal_gear: PASS` or `internal_gear: FAIL`.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/../lib/common.sh"
exe="$build/tests/unit/contact/validate_internal_gear"
need "$exe"
echo "== validate_internal_gear: 3 Hertz models, 29 ring models (rows appear as they finish)"
rc=0
"$exe" --gtest_brief=1 2>&1 | tee "$out/validate_internal_gear.log" || rc=$?  # pipefail: the test's status
check "$out/validate_internal_gear.log" --status "$rc" --table "$here/table.md" --plot "$here/rim_thickness.png" \
      --out "$out"
