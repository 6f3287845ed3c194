#!/usr/bin/env bash
# Seed 003 profile optimisation (Koronaios, NTUA 2021; see README.md): runs
# `gearfem optimise` on case 1 (pinion rack) and case 2 (pinion flank) with four methods each
# (steepest descent + golden section, SLSQP, COBYLA, ISRES; about 1 min in all on 2 cores),
# then `gearfem profile` on the case-2 optimum.prm (the same geometry chain as an involute),
# and check.py compares the involute and sinusoid rows with the thesis' tables (0.2 % /
# 1.5 %), case 1's optimum with its row, case 2's with its objective, and the contact ratio
# of the optimiser with gearfem's own path of contact. Ends with PASS or FAIL.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/../lib/common.sh"
need "$gearfem"
for c in 1 2; do
  echo "== gearfem optimise inputs/seed003_opt_case$c.prm"
  rm -rf "$out/case$c"
  nice -n 15 "$gearfem" optimise "$root/inputs/seed003_opt_case$c.prm" --output-dir "$out/case$c" | grep -v "ETA"
done
echo "== gearfem profile results/case2/optimum.prm (the optimum through the geometry chain)"
rm -rf "$out/case2_profile"
nice -n 15 "$gearfem" profile "$out/case2/optimum.prm" --output-dir "$out/case2_profile" > "$out/case2_profile.log"
cp "$out/case1/summary.md" "$here/case1_summary.md"
cp "$out/case2/summary.md" "$here/case2_summary.md"
for f in curvature profiles convergence; do
  for c in 1 2; do
    [ -f "$out/case$c/$f.png" ] && cp "$out/case$c/$f.png" "$here/case${c}_$f.png"
  done
done
check --out "$out"
