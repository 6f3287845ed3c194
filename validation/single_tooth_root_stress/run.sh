#!/bin/sh
# Single-tooth root stress against ISO 6336-3 (see README.md). Builds and runs the long
# validation test, writes results.csv and root_stress.png into this folder.
set -e
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
build=${GEARFEM_BUILD_DIR:-$root/build}
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release > /dev/null
cmake --build "$build" --target validate_single_tooth -j2
GEARFEM_VALIDATION_OUT="$here" "$build/tests/unit/fem/validate_single_tooth"
/usr/bin/python3 "$here/plot.py" "$here/results.csv"
