#!/usr/bin/env bash
# Kahraman & Singh (1990) validation: up/down sweeps with RK4 and with the tight-tolerance
# DOPRI5 reference (results/), the comparison plot ks_sweep.png and figures (compare.py),
# then check.py against the references of README.md (ends with PASS or FAIL).
# Usage: validation/kahraman_singh/run.sh   (GEARFEM=path/to/gearfem to override)
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/../lib/common.sh"
gearfem="${GEARFEM:-$gearfem}"
need "$gearfem"
i=0
for c in sweep_rk4 sweep_reference; do
  i=$((i + 1))
  echo "== sweep $i/2: $c (2 x 121 speeds)"
  /usr/bin/time -f "$c wall %e s" "$gearfem" dynamics "$here/$c.prm" --output-dir "$out/$c" > "$out/$c.log" 2>&1
  tail -1 "$out/$c.log"
done
/usr/bin/python3 "$here/compare.py" "$out/sweep_rk4/sweep.csv" "$out/sweep_reference/sweep.csv" "$here/ks_sweep.png"
check "$out/sweep_rk4/sweep.csv" "$out/sweep_reference/sweep.csv" --out "$out"
