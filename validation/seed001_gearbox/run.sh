#!/usr/bin/env bash
# Seed 001 (Siasos, NTUA 2010, ch. 9) 150 kW two-stage planetary gearbox (issue 16 sec. 3):
# runs `gearfem gearbox` on the thesis' tabulated stresses (damage chain) and on gearfem's
# own AGMA stresses, prints the figures recorded in validation/RESULTS.md, and checks them
# against the thesis (check.py: PASS/FAIL).
#   validation/seed001_gearbox/run.sh [gearfem] [output folder]
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(cd "$here/../.." && pwd)"
gearfem="${1:-${GEARFEM_BUILD_DIR:-$root/build}/app/gearfem}"
out="${2:-$here/out}"
export MPLBACKEND=Agg
for case in seed001_gearbox_thesis_stresses seed001_gearbox; do
  echo "== $case"
  rm -rf "${out:?}/$case"
  "$gearfem" gearbox "$root/inputs/$case.prm" --output-dir "$out/$case"
  echo "-- lives (stage, member, mode, load, cycles/rev, D, spectra, years; empty = no damage)"
  awk -F, 'NR > 1 && $6 > 0' "$out/$case/gearbox_life.csv"
  echo "-- first bin (45 000 N m): stage, mesh, sigma_H, sigma_F1, sigma_F2, ISO sigma_H1, theta_B,max, P"
  awk -F, 'NR > 1 && $3 == 45000 { print $1 "," $2 "," $5 "," $6 "," $7 "," $8 "," $11 "," $14 }' "$out/$case/gearbox.csv"
  echo "-- max scuffing probability over all bins and meshes"
  awk -F, 'NR > 1 && $14 > m { m = $14 } END { print m }' "$out/$case/gearbox.csv"
done
echo "== checks against the thesis (check.py)"
/usr/bin/python3 "$here/check.py" "$out"
