#!/usr/bin/env bash
# Face-width sensitivity of the seed 003 FE check (README.md, "FE verification"): the thesis
# does not state its face width; run.sh assumes b = 20 mm. This script runs `gearfem solve` on
# the involute and on case 2's optimum.prm at b = 10 and 30 mm (T1 = 5 N m; b = 20 mm is
# run.sh's fe_involute/fe_optimum, run here if missing, as is case 2's optimisation) and
# check.py --face-width compares the mean contact pressure and root stress with the plane-
# stress scalings p ~ 1/sqrt(b), sigma ~ 1/b and their optimum/involute ratios across widths.
# About 3 min on 2 cores after run.sh (2 min more without it). Ends with PASS or FAIL.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/../lib/common.sh"
need "$gearfem"
if [ ! -f "$out/case2/optimum.prm" ]; then
  echo "== gearfem optimise inputs/seed003_opt_case2.prm (case 2's optimum.prm)"
  nice -n 15 "$gearfem" optimise "$root/inputs/seed003_opt_case2.prm" --output-dir "$out/case2" > "$out/case2.log"
fi
solve() { # solve <design> <width [mm]> <output name>
  local prm=$root/inputs/seed003_opt_fe_involute.prm
  [ "$1" = optimum ] && prm=$out/case2/optimum.prm
  sed "s|set Face width\( *\)= .*|set Face width\1= $2|" "$prm" > "$out/$3.prm"
  [ "$(grep -c "set Face width *= $2$" "$out/$3.prm")" = 2 ] || { echo "no face width in $prm"; return 1; }
  echo "== gearfem solve $1 at b = $2 mm (results/$3)"
  rm -rf "${out:?}/$3"
  nice -n 15 "$gearfem" solve "$out/$3.prm" --output-dir "$out/$3" > "$out/$3.log" 2>&1
  grep -v "ETA" "$out/$3.log" | tail -n 1
}
for d in involute optimum; do
  [ -f "$out/fe_$d/sweep.csv" ] || solve $d 20 "fe_$d"
  for b in 10 30; do
    solve $d $b "fe_b${b}_$d"
  done
done
check --out "$out" --face-width
