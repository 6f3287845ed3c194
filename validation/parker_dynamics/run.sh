#!/usr/bin/env bash
# Parker pair up/down RMS-DTE sweeps at 100/200/340 N m with (1) the FE-calibrated torque
# table (gearfem calibrate on the validation/parker_ste FE sweeps, calibrate_tables.prm) and
# (2) STE excitation with the raw FE STE curve (the FE sweep.csv, kbar from F_n/STE) and
# (3) the analytical Weber/Cornell torque table; analyse.py reports the resonance, jump
# frequencies and contact loss and plots parker_sweeps{,_ste,_analytical}.png.
# Uses validation/parker_ste/results/plane_stress/results.h5 (runs validation/parker_ste/run.sh
# first if it is missing).
# Usage: validation/parker_dynamics/run.sh   (GEARFEM=path/to/gearfem to override)
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(cd "$here/../.." && pwd)"
gearfem="${GEARFEM:-${GEARFEM_BUILD_DIR:-$root/build}/app/gearfem}"
if [ -z "${GEARFEM:-}" ]; then # build it (Release, incremental)
  build="${GEARFEM_BUILD_DIR:-$root/build}"
  cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release > /dev/null
  cmake --build "$build" --target gearfem -j2 > /dev/null
fi
out="$here/results" # the sweep inputs name results/tables/mesh_torque.h5
# The FE sweeps (about 10 min) are computed once and reused.
[ -f "$here/../parker_ste/results/plane_stress/results.h5" ] || "$here/../parker_ste/run.sh"
"$gearfem" calibrate "$here/calibrate_tables.prm" --output-dir "$out/tables" | grep -E "^tables|held out" || true
for T in 100 200 340; do
  for kind in fe ste analytical; do
    prm="$here/sweep_${T}Nm.prm"; [ $kind = analytical ] || prm="$here/sweep_${kind}_${T}Nm.prm"
    /usr/bin/time -f "${kind} ${T} N m: wall %e s" "$gearfem" dynamics "$prm" \
      --output-dir "$out/${kind}_${T}Nm" | grep -E "natural frequency|warning" | sed "s/^/${kind} ${T} N m: /"
  done
done
/usr/bin/python3 "$here/analyse.py" "$here/parker_sweeps.png" \
  "Parker pair 50/50 m3 b20, zeta 0.02, FE-calibrated table" "$out"/fe_{100,200,340}Nm
/usr/bin/python3 "$here/analyse.py" "$here/parker_sweeps_ste.png" \
  "Parker pair 50/50 m3 b20, zeta 0.02, STE excitation from the FE STE" "$out"/ste_{100,200,340}Nm
/usr/bin/python3 "$here/analyse.py" "$here/parker_sweeps_analytical.png" \
  "Parker pair 50/50 m3 b20, zeta 0.02, analytical Weber/Cornell table" "$out"/analytical_{100,200,340}Nm
