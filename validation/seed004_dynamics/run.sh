#!/usr/bin/env bash
# The NTUA tooth-mass thesis' dynamic case (z 20/40, m 2.5, b 30, 160 rad/s, M_in 100 N m,
# M_out 200 N m, no damping, from rest): the thesis' model_solve replayed in numpy and its K
# vector (after the loop's overwrite, and as intended) written as mesh tables
# (thesis_model.py); gearfem dynamics with those tables, at 600 rpm, and with gearfem's
# Weber/Cornell table; the tooth inertia of the thesis' definition (--validate runs, both
# weightings); J(theta) in the equations of motion (energy balance); gearfem rate for the
# Weber/Cornell and ISO 6336-1 stiffness; the thesis' compliance code replayed in numpy
# (compliance_replica.py) and gearfem's FE mesh stiffness of the pair (fe_20_40.prm);
# check.py (PASS or FAIL). About 1 min.
# Usage: validation/seed004_dynamics/run.sh   (GEARFEM=path/to/gearfem to override)
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/../lib/common.sh"
gearfem="${GEARFEM:-$gearfem}"
need "$gearfem"
echo "== the thesis' model_solve (numpy) and its stiffness as mesh tables"
/usr/bin/python3 "$here/thesis_model.py" "$out" > "$out/thesis_model.log"
runs=(thesis_k_overwrite thesis_k_intended thesis_k_overwrite_600rpm weber_k energy_balance)
i=0
for r in "${runs[@]}"; do
  i=$((i + 1))
  echo "== run $i/${#runs[@]}: gearfem dynamics $r.prm"
  "$gearfem" dynamics "$here/$r.prm" --output-dir "$out/$r" > "$out/$r.log" 2>&1
  grep -E "angle amplitude|energy balance" "$out/$r.log" || true
done
echo "== tooth inertia of the generated pair (thesis and kinetic-energy weightings)"
sed 's/set Tooth inertia              = position dependent/set Tooth inertia              = constant/' \
  "$here/energy_balance.prm" > "$out/tooth_mass_linear.prm"
sed 's/set Tooth mass weighting       = linear/set Tooth mass weighting       = quadratic/' \
  "$out/tooth_mass_linear.prm" > "$out/tooth_mass_quadratic.prm"
grep -q "Tooth inertia              = constant" "$out/tooth_mass_linear.prm"  # the swaps must have happened
grep -q "weighting       = quadratic" "$out/tooth_mass_quadratic.prm"
for w in linear quadratic; do
  "$gearfem" dynamics "$out/tooth_mass_$w.prm" --validate --output-dir "$out/tooth_mass_$w" > "$out/tooth_mass_$w.log" 2>&1
  grep "tooth inertia J_tooth1" "$out/tooth_mass_$w.log"
done
echo "== gearfem rate: Weber/Cornell mesh cycle and ISO 6336-1 stiffness of the 20/40 pair"
"$gearfem" rate "$here/rate_20_40.prm" --output-dir "$out/rate" > "$out/rate.log" 2>&1
# The same in plane stress with the corner contact: the model of the dynamics' analytical table.
sed -e 's/set Plane model = plane strain/set Plane model = plane stress/' \
    -e 's/set Corner contact  = false/set Corner contact  = true/' "$here/rate_20_40.prm" > "$out/rate_plane_stress.prm"
grep -q "plane stress" "$out/rate_plane_stress.prm"
"$gearfem" rate "$out/rate_plane_stress.prm" --output-dir "$out/rate_plane_stress" > "$out/rate_plane_stress.log" 2>&1
echo "== the thesis' compliance code (numpy): its stiffness fits, each lead switched alone"
/usr/bin/python3 "$here/compliance_replica.py" "$out" | tee "$out/compliance_replica.log"
echo "== gearfem solve: FE mesh stiffness of the 20/40 pair at 100 N m"
"$gearfem" solve "$here/fe_20_40.prm" --output-dir "$out/fe" > "$out/fe.log" 2>&1
/usr/bin/python3 "$here/plot.py" "$here/response.png" "$out"
check --out "$out"
