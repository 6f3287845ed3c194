#!/usr/bin/env bash
# Seed 000 (Gkimisis 2019) Table 1 dynamic cases: 2-DOF torque-driven model with the
# analytical (Weber/Cornell) torque table, then with the seed 000 semi-analytical law
# (Law = Ricker, the same files with the law swapped); then the contact-state plot (plot.py).
# Usage: validation/seed000_dynamics/run.sh   (GEARFEM=path/to/gearfem to override)
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
cases=(case1_5Nm_600rpm case2_20Nm_1200rpm case3_40Nm_1200rpm case4_20Nm_1200rpm_a+1mm)
for c in "${cases[@]}"; do
  "$gearfem" dynamics "$here/$c.prm" --output-dir "$out/$c" | grep -E "RMS|loss fraction|period \[|K_v"
done
for c in "${cases[@]}"; do
  mkdir -p "$out/ricker"
  sed 's/set Law = analytical table/set Law = Ricker/' "$here/$c.prm" > "$out/ricker/$c.prm"
  echo "Ricker law, $c:"
  "$gearfem" dynamics "$out/ricker/$c.prm" --output-dir "$out/ricker/$c" | grep -E "RMS|loss fraction|period \[|K_v"
done
/usr/bin/python3 "$here/plot.py" "$here/contact_states.png" $(for c in "${cases[@]}"; do echo "$out/$c"; done)
