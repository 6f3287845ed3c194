#!/usr/bin/env bash
# Single-tooth root stress against ISO 6336-3 (see README.md). Runs the validation
# executable validate_single_tooth (about 1 min), writes results/results.csv, the tracked
# results.csv (no timings in it) and root_stress.png; check.py ends with PASS or FAIL.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/../lib/common.sh"
exe="$build/tests/unit/fem/validate_single_tooth"
need "$exe"
rm -f "$out/results.csv"
rc=0
GEARFEM_VALIDATION_OUT="$out" "$exe" 2>&1 | tee "$out/validate_single_tooth.log" || rc=$?
[ -f "$out/results.csv" ] && cp "$out/results.csv" "$here/results.csv"
/usr/bin/python3 "$here/plot.py" "$here/results.csv"
check "$out/results.csv" --status "$rc" --out "$out"
