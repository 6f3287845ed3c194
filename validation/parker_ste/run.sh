#!/bin/sh
# Parker pair full-cycle STE (see README.md): builds gearfem and the long validation test,
# runs the 100/200/340 N m sweeps in plane stress and plane strain, copies the plots here,
# writes table.md (cycle summary) and validation.md (convergence, penalty/Lagrange, Hertz,
# seed 001, ISO 6336-3 tables).
set -e
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
build=${GEARFEM_BUILD_DIR:-$root/build}
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release > /dev/null
cmake --build "$build" --target gearfem validate_gear_contact -j2
for model in plane_stress plane_strain; do
  prm="$here/parker_ste.prm"
  [ "$model" = plane_strain ] && prm="$here/parker_ste_plane_strain.prm"
  "$build/app/gearfem" solve "$prm" --output-dir "$here/results/$model" | tee "$here/results/$model.log"
done
for f in ste stiffness load_sharing pressure root_stress; do
  cp "$here/results/plane_stress/$f.png" "$here/$f.png"
done
/usr/bin/python3 "$here/summarise.py" "$here/results" > "$here/table.md"
"$build/tests/unit/contact/validate_gear_contact" | grep -v '^\[' > "$here/validation.md"
cat "$here/table.md"
