#!/bin/sh
# `gearfem mesh`: the sample run writes the meshes, and each bad input below
# exits with status 2 and writes no files. Usage: mesh_cli.sh <gearfem> <source dir>
gearfem=$1; src=$2; tmp=$(mktemp -d); fail=0
"$gearfem" mesh "$src/inputs/mesh_demo.prm" --output-dir "$tmp/ok" > /dev/null || fail=1
for f in gear1.msh gear2.msh mesh_quality.csv; do [ -s "$tmp/ok/$f" ] || { echo "missing $f"; fail=1; }; done
n=0
for entry in "set h_contact = 5" "set h_fillet = -1" "set h_body = 0" "set Model = sector|set Sector teeth = 0" \
             "subsection Gear 1|set Bore radius = 80|end" "subsection Gear 1|set Rim thickness = 80|end"; do
  n=$((n + 1))
  { sed -n '/^subsection Mesh/q;p' "$src/inputs/mesh_demo.prm"; echo "subsection Mesh"; echo "$entry" | tr '|' '\n'; echo "end"; } > "$tmp/bad$n.prm"
  "$gearfem" mesh "$tmp/bad$n.prm" --output-dir "$tmp/out$n" 2> "$tmp/err$n"; rc=$?
  if [ $rc -ne 2 ] || [ -e "$tmp/out$n" ]; then echo "bad input '$entry': status $rc"; fail=1; fi
done
printf 'subsection Finite elements\n  set Degree = 3\nend\n' > "$tmp/p3.prm"
"$gearfem" mesh "$tmp/p3.prm" --output-dir "$tmp/p3" 2> /dev/null; [ $? -eq 2 ] && [ ! -e "$tmp/p3" ] || { echo "p = 3 accepted"; fail=1; }
rm -rf "$tmp"
exit $fail
