#!/usr/bin/env bash
# Gkimisis 2019 dynamic cases. (1) The four Table 1 cases as the thesis describes them, with
# the analytical (Weber/Cornell) torque table and with the thesis' semi-analytical law
# (Law = Ricker, the same files with the law swapped), and the contact-state plot (plot.py);
# (2) the same cases with the set-up of the thesis' listing (thesis_runs.py) and the settled
# speed of its initial conditions checked by an independent integration (momentum.py); the
# thesis' own dynamic listing replicated in numpy (listing_replica.py, listing_geometry.py) over
# its open ingredients (initial gear speed, step, ramp, damping, case-4 torque);
# (3) the period-doubling search around case 2 (grid.py, period_grid.png); (4) the Vasileiou
# pair of Figs 27-28 with phase portraits (vasileiou.py, vasileiou_portraits.png); (5) the
# speed-versus-error table of the laws with an FE-exact table of the pair (gearfem condense
# fe_table_32_60.prm, timing.py); (6) the Table 1 pair geometry (gearfem profile);
# check.py against the thesis (PASS or FAIL). About 15-20 min on two cores.
# Usage: validation/seed000_dynamics/run.sh   (GEARFEM=path/to/gearfem to override)
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/../lib/common.sh"
gearfem="${GEARFEM:-$gearfem}"
need "$gearfem"
export PYTHONPATH="$here:$root/validation/lib${PYTHONPATH:+:$PYTHONPATH}"
cases=(case1_5Nm_600rpm case2_20Nm_1200rpm case3_40Nm_1200rpm case4_40Nm_1200rpm_a+1mm)
mkdir -p "$out/ricker"
i=0
for c in "${cases[@]}"; do
  i=$((i + 1))
  echo "== run $i/8: $c (analytical table)"
  "$gearfem" dynamics "$here/$c.prm" --output-dir "$out/$c" > "$out/$c.log" 2>&1
  grep -E "RMS|loss fraction|period \[|K_v" "$out/$c.log" || true
done
for c in "${cases[@]}"; do
  i=$((i + 1))
  sed 's/set Law = analytical table/set Law = Ricker/' "$here/$c.prm" > "$out/ricker/$c.prm"
  grep -q "set Law = Ricker" "$out/ricker/$c.prm"  # the swap must have happened
  echo "== run $i/8: $c (Ricker law)"
  "$gearfem" dynamics "$out/ricker/$c.prm" --output-dir "$out/ricker/$c" > "$out/ricker/$c.log" 2>&1
  grep -E "RMS|loss fraction|period \[|K_v" "$out/ricker/$c.log" || true
done
/usr/bin/python3 "$here/plot.py" "$here/contact_states.png" $(for c in "${cases[@]}"; do echo "$out/$c"; done)
"$gearfem" profile "$root/inputs/seed000_32_60.prm" --output-dir "$out/profile" > "$out/profile.log" 2>&1
echo "== the thesis' listing set-up (8 runs)"
/usr/bin/python3 "$here/thesis_runs.py" "$gearfem" "$out" $(for c in "${cases[@]}"; do echo "$here/$c.prm"; done)
echo "== the thesis' dynamic listing, replicated (numpy, geometric model; 80 runs over its open ingredients)"
/usr/bin/python3 "$here/listing_replica.py" "$out" | tee "$out/listing_replica.log"
echo "== settled speed from the thesis' initial conditions (independent 2-DOF RK4)"
for k in constant zones; do
  /usr/bin/python3 "$here/momentum.py" 1200 20 $k | tee "$out/momentum_$k.log"
done
echo "== period-doubling grid (360 runs)"
/usr/bin/python3 "$here/grid.py" "$gearfem" "$out" "$here/case2_20Nm_1200rpm.prm" "$here/period_grid.png"
echo "== Vasileiou pair (Figs 27-28)"
/usr/bin/python3 "$here/vasileiou.py" "$gearfem" "$out" "$here/vasileiou_portraits.png" \
  "$here/vasileiou_5.31Nm_2727rpm.prm" "$here/vasileiou_8.11Nm_3272rpm.prm"
echo "== FE-exact table of the pair (condensed cycle) and the speed-versus-error table"
"$gearfem" condense "$here/fe_table_32_60.prm" --output-dir "$out/fe_table" > "$out/condense.log" 2>&1
grep -m1 "^wrote.*mesh_torque" "$out/condense.log"
/usr/bin/python3 "$here/timing.py" "$gearfem" "$out" "$here/case2_20Nm_1200rpm.prm" "$out/fe_table/mesh_torque.h5"
check --out "$out"
