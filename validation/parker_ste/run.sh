#!/usr/bin/env bash
# Parker pair full-cycle STE (see README.md): the FE sweeps (sweeps.sh), the plane-stress
# plots copied here, the cycle summary (summarise.py) and the long validation executable
# validate_gear_contact (mesh convergence, penalty/Lagrange, Hertz, Siasos 2010 pair,
# ISO 6336-3; about 10 min). Full outputs with timings go to results/; the tracked table.md and
# validation.md are written without timings; check.py ends with PASS or FAIL.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/../lib/common.sh"
exe="$build/tests/unit/contact/validate_gear_contact"
need "$gearfem" "$exe"
"$here/sweeps.sh"
for f in ste stiffness load_sharing pressure root_stress; do
  cp "$out/plane_stress/$f.png" "$here/$f.png"
done
/usr/bin/python3 "$here/summarise.py" "$out" > "$out/table.md"
echo "== validate_gear_contact: 5 studies (mesh convergence, penalty/Lagrange, Hertz, Siasos 2010 pair, ISO 6336-3)"
rc=0
"$exe" 2>&1 | tee "$out/validate_gear_contact.log" || rc=$?  # pipefail: the test's status
check --status "$rc" --out "$out" --table "$here/table.md" --validation "$here/validation.md"
