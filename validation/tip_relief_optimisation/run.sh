#!/usr/bin/env bash
# Robust tip-relief optimisation (README.md):
#  1. `gearfem optimise` on inputs/tip_relief_opt.prm (Parker pair, the same linear relief on
#     both gears, worst peak-to-peak STE of 240 and 340 N m, BOBYQA, the 5 x 5 Harris-map grid
#     over the same box, the single-load optima at 240 and at 340 N m alone, and these designs
#     checked from 100 to 500 N m; all on the one cached model), then `gearfem solve` on the
#     written optimum.prm (the same gap route: it must reproduce the optimiser's STE) and on the
#     optimum re-meshed with the relief (Micro-geometry = geometry: an independent
#     discretisation);
#  2. `gearfem optimise` on inputs/tip_relief_opt_parabolic4.prm (FZG type C 16/24, parabolic
#     relief per gear: 4 variables, BOBYQA, then the 3^4 grid), then `gearfem solve` on its
#     optimum.prm.
# check.py compares each optimum with its grid's best, the unrelieved pair, the load-sharing
# bound and the single-load optima, and ends with PASS or FAIL. About 35 s on 2 cores (the
# designs on a condensed cycle of the model; Condensed cycle = off: about 10 min).
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/../lib/common.sh"
need "$gearfem"
rm -rf "$out/study" "$out/solve_gap" "$out/solve_exact" "$out/parabolic4" "$out/parabolic4_solve"
echo "== gearfem optimise inputs/tip_relief_opt.prm"
# CPU time beside the wall time: the machine is shared, so the wall time says little.
/usr/bin/time -f "optimise: %U s user CPU, %e s wall, %M kB peak" -o "$out/study.time" \
  "$gearfem" optimise "$root/inputs/tip_relief_opt.prm" --output-dir "$out/study" | tee "$out/study.log" | grep -v "ETA"
cat "$out/study.time"
echo "== gearfem solve results/study/optimum.prm (gap route, as optimised)"
"$gearfem" solve "$out/study/optimum.prm" --output-dir "$out/solve_gap" > "$out/solve_gap.log"
tail -n 4 "$out/solve_gap.log"
echo "== gearfem solve of the optimum re-meshed with its relief (Micro-geometry = geometry)"
mkdir -p "$out/solve_exact"
{ cat "$out/study/optimum.prm"; printf 'subsection Contact\n  set Micro-geometry = geometry\nend\n'; } > "$out/solve_exact/case.prm"
"$gearfem" solve "$out/solve_exact/case.prm" --output-dir "$out/solve_exact" > "$out/solve_exact.log"
tail -n 4 "$out/solve_exact.log"
echo "== gearfem optimise inputs/tip_relief_opt_parabolic4.prm (FZG C, parabolic, 4 variables)"
/usr/bin/time -f "optimise parabolic4: %U s user CPU, %e s wall, %M kB peak" -o "$out/parabolic4.time" \
  "$gearfem" optimise "$root/inputs/tip_relief_opt_parabolic4.prm" --output-dir "$out/parabolic4" \
  | tee "$out/parabolic4.log" | grep -v "ETA"
cat "$out/parabolic4.time"
echo "== gearfem solve results/parabolic4/optimum.prm (gap route, as optimised)"
"$gearfem" solve "$out/parabolic4/optimum.prm" --output-dir "$out/parabolic4_solve" > "$out/parabolic4_solve.log"
tail -n 4 "$out/parabolic4_solve.log"
copy() { [ -f "$1" ] && cp "$1" "$here/$2.tmp.png" && mv "$here/$2.tmp.png" "$here/$2"; }
for f in relief.png relief_history.png relief_robust.png; do copy "$out/study/$f" "$f"; done
copy "$out/parabolic4/relief.png" relief_parabolic4.png
copy "$out/parabolic4/relief_history.png" relief_history_parabolic4.png
check --out "$out"
