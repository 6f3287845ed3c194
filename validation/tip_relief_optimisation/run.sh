#!/usr/bin/env bash
# Robust tip-relief optimisation (issue 15, section 4; README.md): `gearfem optimise` on
# inputs/tip_relief_opt.prm (Parker pair, the same linear relief on both gears, worst
# peak-to-peak STE of 240 and 340 N m, BOBYQA, then the 5 x 5 Harris-map grid over the same
# box on the same cached model), then `gearfem solve` on the written optimum.prm (the same
# gap route: it must reproduce the optimiser's STE) and on the optimum re-meshed with the
# relief (Micro-geometry = geometry: an independent discretisation). check.py compares the
# optimum with the grid's best, the unrelieved pair and the load-sharing bound, and ends with
# PASS or FAIL. A few minutes on 2 cores.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/../lib/common.sh"
need "$gearfem"
rm -rf "$out/study" "$out/solve_gap" "$out/solve_exact"
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
for f in relief.png relief_history.png; do
  [ -f "$out/study/$f" ] && cp "$out/study/$f" "$here/$f.tmp.png" && mv "$here/$f.tmp.png" "$here/$f"
done
check --out "$out"
