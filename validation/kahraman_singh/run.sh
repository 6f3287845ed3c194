#!/usr/bin/env bash
# Kahraman & Singh (1990) validation: up/down sweeps with RK4 and with the tight-tolerance
# DOPRI5 reference, then the comparison plot and figures (compare.py).
# Usage: validation/kahraman_singh/run.sh   (GEARFEM=path/to/gearfem to override)
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(cd "$here/../.." && pwd)"
gearfem="${GEARFEM:-${GEARFEM_BUILD_DIR:-$root/build}/app/gearfem}"
if [ -z "${GEARFEM:-}" ]; then # build it (Release, incremental)
  build="${GEARFEM_BUILD_DIR:-$root/build}"
  cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release > /dev/null
  cmake --build "$build" --target gearfem -j2 > /dev/null
fi
out="${OUT:-$here/results}"
for c in sweep_rk4 sweep_reference; do
  /usr/bin/time -f "$c wall %e s" "$gearfem" dynamics "$here/$c.prm" --output-dir "$out/$c"
done
/usr/bin/python3 "$here/compare.py" "$out/sweep_rk4/sweep.csv" "$out/sweep_reference/sweep.csv" "$here/ks_sweep.png"
