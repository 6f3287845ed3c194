#!/usr/bin/env bash
# A 1-DOF dynamic run driven by the exported ROSS stiffness arrays (gearfem export), integrated by
# an independent script (scipy solve_ivp, check.py), against `gearfem dynamics` on the same
# FE-exact torque table: RMS DTE within 2 % at three mesh frequencies. The demo pair (Parker
# 50/50) is condensed at 200 N m with its FE-exact table (gearfem condense, ~30 s), exported
# (ross_mesh.json, spline, TE and force tables) and run; check.py ends with PASS or FAIL.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/../lib/common.sh"
need "$gearfem"
geometry() { sed -n '/^subsection Rack/,/^subsection Mesh/p' "$root/inputs/demo_fixed_mesh.prm" | sed '$d'; sed -n '/^subsection Mesh/,/^end/p' "$root/inputs/demo_fixed_mesh.prm"; }
{ geometry; cat "$here/condense.prm"; } > "$out/condense.prm"
start=$(date +%s)
"$gearfem" condense "$out/condense.prm" --output-dir "$out/condensed" > "$out/condense.log" 2>&1
echo "condensed cycle and FE-exact table: $(( $(date +%s) - start )) s"
{ sed -n '/^subsection Rack/,/^subsection Material/p' "$root/inputs/demo_fixed_mesh.prm" | sed '$d'; cat "$here/export.prm"; } \
  | sed "s|results/condensed|$out/condensed|" > "$out/export.prm"
"$gearfem" export "$out/export.prm" --output-dir "$out/export" > "$out/export.log" 2>&1
sed "s|results/condensed|$out/condensed|" "$here/dynamics.prm" > "$out/dynamics.prm"
"$gearfem" dynamics "$out/dynamics.prm" --output-dir "$out/dynamics" > "$out/dynamics.log" 2>&1
grep -E "natural frequency|equivalent mass" "$out/dynamics.log" || true
check --out "$out" --figure "$here/multibody_exports.png"
