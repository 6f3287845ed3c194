#!/bin/sh
# Calibration of the Weber/Cornell model against the Parker-pair FE sweeps (see README.md).
# Needs validation/parker_ste/results/plane_stress/results.h5 (runs parker_ste first if it
# is missing), then writes calibration.md, calibration.png and the tables into results/.
set -e
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
build=${GEARFEM_BUILD_DIR:-$root/build}
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release > /dev/null
cmake --build "$build" --target gearfem -j"${GEARFEM_JOBS:-2}"
[ -f "$here/../parker_ste/results/plane_stress/results.h5" ] || "$here/../parker_ste/run.sh"
"$build/app/gearfem" calibrate "$here/calibrate.prm" --output-dir "$here/results"
cp "$here/results/calibration.md" "$here/results/calibration.png" "$here/"
