#!/bin/sh
# Hard cases of the contact solver (see README.md): builds and runs the long validation test,
# writes table.md.
set -e
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
build=${GEARFEM_BUILD_DIR:-$root/build}
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release > /dev/null
cmake --build "$build" --target validate_hard_cases -j2
"$build/tests/unit/contact/validate_hard_cases" | grep '^|' > "$here/table.md"
cat "$here/table.md"
