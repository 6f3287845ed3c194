#!/bin/sh
# 2-D Hertz line contact (see README.md): builds and runs the long validation test, writes
# convergence.md (both methods, plane stress/strain, equal and dissimilar discs, h = a/4..a/16).
set -e
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
build=${GEARFEM_BUILD_DIR:-$root/build}
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release > /dev/null
cmake --build "$build" --target validate_hertz -j2
"$build/tests/unit/contact/validate_hertz" | grep '^|' > "$here/convergence.md"
cat "$here/convergence.md"
