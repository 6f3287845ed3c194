#!/usr/bin/env bash
# Gkimisis 2019 Table 1 dynamic cases: 2-DOF torque-driven model with the
# analytical (Weber/Cornell) torque table, then with the thesis' semi-analytical law
# (Law = Ricker, the same files with the law swapped); the contact-state plot (plot.py);
# the Table 1 pair geometry (gearfem profile); check.py against the thesis (PASS or FAIL).
# Usage: validation/seed000_dynamics/run.sh   (GEARFEM=path/to/gearfem to override)
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/../lib/common.sh"
gearfem="${GEARFEM:-$gearfem}"
need "$gearfem"
cases=(case1_5Nm_600rpm case2_20Nm_1200rpm case3_40Nm_1200rpm case4_20Nm_1200rpm_a+1mm)
mkdir -p "$out/ricker"
i=0
for c in "${cases[@]}"; do
  i=$((i + 1))
  echo "== run $i/8: $c (analytical table)"
  "$gearfem" dynamics "$here/$c.prm" --output-dir "$out/$c" > "$out/$c.log" 2>&1
  grep -E "RMS|loss fraction|period \[|K_v" "$out/$c.log" || true
done
for c in "${cases[@]}"; do
  i=$((i + 1))
  sed 's/set Law = analytical table/set Law = Ricker/' "$here/$c.prm" > "$out/ricker/$c.prm"
  grep -q "set Law = Ricker" "$out/ricker/$c.prm"  # the swap must have happened
  echo "== run $i/8: $c (Ricker law)"
  "$gearfem" dynamics "$out/ricker/$c.prm" --output-dir "$out/ricker/$c" > "$out/ricker/$c.log" 2>&1
  grep -E "RMS|loss fraction|period \[|K_v" "$out/ricker/$c.log" || true
done
/usr/bin/python3 "$here/plot.py" "$here/contact_states.png" $(for c in "${cases[@]}"; do echo "$out/$c"; done)
"$gearfem" profile "$root/inputs/seed000_32_60.prm" --output-dir "$out/profile" > "$out/profile.log" 2>&1
check --out "$out"
