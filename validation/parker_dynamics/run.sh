#!/usr/bin/env bash
# Parker pair up/down RMS-DTE sweeps at 100/200/340 N m with (1) the FE-calibrated torque
# table (gearfem calibrate on the validation/parker_ste FE sweeps, calibrate_tables.prm),
# (2) STE excitation with the raw FE STE curve (the FE sweep.csv, kbar from F_n/STE),
# (3) the analytical Weber/Cornell torque table and (4) the FE-exact torque table (contact
# solves on the condensed cycle of the parker_ste plane-stress model, gearfem condense);
# analyse.py reports the resonance, jump
# frequencies and contact loss and plots parker_sweeps{,_ste,_analytical}.png; check.py
# compares with the references of README.md (including f_n against ISO 6336 c_gamma_alpha and
# Gkimisis 2019's f_eigen, eigen_thesis.py) and ends with PASS or FAIL.
# Uses validation/parker_ste/results/plane_stress (runs parker_ste/sweeps.sh when missing).
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/../lib/common.sh"
need "$gearfem"
"$root/validation/parker_ste/sweeps.sh" --if-missing
# The sweep inputs name results/tables/mesh_torque.h5 (relative to this folder).
(cd "$here" && "$gearfem" calibrate "$here/calibrate_tables.prm" --output-dir "$out/tables") > "$out/calibrate.log" 2>&1
grep -E "^tables|held out" "$out/calibrate.log" || true  # a summary only; the status is the command's
# The FE-exact table: the parker_ste plane-stress case (same mesh and positions) condensed at
# 340 N m for 5-2040 N m (6 x 340 N m, as the calibrated table's load factor), one-sided.
{ cat "$root/validation/parker_ste/parker_ste.prm"
  printf 'subsection Solve\n  set Torques = 340\n  set VTU = none\n  set Plots = false\nend\n'
  printf 'subsection Condense\n  set Build torque = 340\n  set Torque range = 5, 2040\n'
  printf '  set Table file = mesh_torque.h5\n  set Table compressions = 120\nend\n'; } > "$out/condense_table.prm"
start=$(date +%s)
"$gearfem" condense "$out/condense_table.prm" --output-dir "$out/tables_fe_exact" > "$out/condense.log" 2>&1
echo "FE-exact table: $(grep -m1 '^wrote.*mesh_torque' "$out/condense.log"), $(( $(date +%s) - start )) s"
i=0
for T in 100 200 340; do
  for kind in fe ste analytical fex; do
    i=$((i + 1))
    prm="$here/sweep_${T}Nm.prm"; [ $kind = analytical ] || prm="$here/sweep_${kind}_${T}Nm.prm"
    start=$(date +%s)
    (cd "$here" && "$gearfem" dynamics "$prm" --output-dir "$out/${kind}_${T}Nm") > "$out/${kind}_${T}Nm.log" 2>&1
    echo "sweep $i/12: $kind $T N m, $(( $(date +%s) - start )) s; $(grep -m1 'natural frequency' "$out/${kind}_${T}Nm.log" || true)"
  done
done
/usr/bin/python3 "$here/analyse.py" "$here/parker_sweeps.png" \
  "Parker pair 50/50 m3 b20, zeta 0.02, FE-calibrated table" "$out"/fe_{100,200,340}Nm
/usr/bin/python3 "$here/analyse.py" "$here/parker_sweeps_ste.png" \
  "Parker pair 50/50 m3 b20, zeta 0.02, STE excitation from the FE STE" "$out"/ste_{100,200,340}Nm
/usr/bin/python3 "$here/analyse.py" "$here/parker_sweeps_analytical.png" \
  "Parker pair 50/50 m3 b20, zeta 0.02, analytical Weber/Cornell table" "$out"/analytical_{100,200,340}Nm
/usr/bin/python3 "$here/analyse.py" "$here/parker_sweeps_fe_exact.png" \
  "Parker pair 50/50 m3 b20, zeta 0.02, FE-exact table (condensed cycle)" "$out"/fex_{100,200,340}Nm
check --out "$out" --fe-sweep "$root/validation/parker_ste/results/plane_stress/sweep.csv"
