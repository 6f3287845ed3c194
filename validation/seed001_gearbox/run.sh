#!/usr/bin/env bash
# Siasos 2010 (NTUA, ch. 9) 150 kW two-stage planetary gearbox (see README.md):
#  - the damage chain: `gearfem gearbox` on the thesis' tabulated stresses and on
#    gearfem's own AGMA stresses;
#  - the stress sources: the same gearbox with ISO 6336 stresses (Stress source = ISO) and
#    with FE stresses on the sun-planet meshes of both stages (inputs/seed001_gearbox_fe.prm:
#    3-tooth sectors, 12 positions, 3 torques), plus the stage-2 FE mesh with halved element
#    sizes at the top torque (convergence);
# prints the figures recorded in validation/RESULTS.md and checks them (check.py: PASS/FAIL).
#   validation/seed001_gearbox/run.sh [gearfem] [output folder]
set -euo pipefail
args_allowed='[^-].*'
source "$(dirname "${BASH_SOURCE[0]}")/../lib/args.sh"
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(cd "$here/../.." && pwd)"
gearfem="${1:-${GEARFEM_BUILD_DIR:-$root/build}/app/gearfem}"
out="${2:-$here/results}"
export MPLBACKEND=Agg
mkdir -p "$out/inputs"
# Variants written from the committed inputs (the only changes are the sed expressions).
sed -e 's/^\(  set Stress source *=\).*/\1 ISO/' "$root/inputs/seed001_gearbox.prm" > "$out/inputs/seed001_gearbox_iso.prm"
sed -e 's/^\(  set h_contact *=\).*/\1 0.058333/' -e 's/^\(  set h_fillet *=\).*/\1 0.125/' \
    -e 's/^\(  set h_body *=\).*/\1 1.75/' -e 's/^\(  set Torque points *=\).*/\1 1/' \
    -e 's/^\(  set Stages *=\).*/\1 2/' \
    "$root/inputs/seed001_gearbox_fe.prm" > "$out/inputs/seed001_gearbox_fe_fine.prm"
for case in seed001_gearbox_thesis_stresses seed001_gearbox seed001_gearbox_iso seed001_gearbox_fe seed001_gearbox_fe_fine; do
  echo "== $case"
  input="$root/inputs/$case.prm"
  [ -f "$input" ] || input="$out/inputs/$case.prm"
  rm -rf "${out:?}/$case"
  start=$(date +%s)
  "$gearfem" gearbox "$input" --output-dir "$out/$case"
  echo "-- wall time $(( $(date +%s) - start )) s"
  echo "-- lives (stage, member, mode, load, cycles/rev, D, spectra, years; empty = no damage)"
  awk -F, 'NR > 1 && $6 > 0' "$out/$case/gearbox_life.csv"
  echo "-- first bin (45 000 N m): stage, mesh, sigma_H, sigma_F1, sigma_F2, ISO sigma_H1, ISO sigma_F1, ISO sigma_F2, theta_B,max, P"
  awk -F, 'NR > 1 && $3 == 45000 { print $1 "," $2 "," $5 "," $6 "," $7 "," $8 "," $15 "," $16 "," $11 "," $14 }' "$out/$case/gearbox.csv"
  echo "-- max scuffing probability over all bins and meshes"
  awk -F, 'NR > 1 && $14 > m { m = $14 } END { print m }' "$out/$case/gearbox.csv"
  if [ -f "$out/$case/fe_stresses.csv" ]; then
    echo "-- FE stresses (stage, mesh, input torque, pinion torque, sigma_H Hertz, p_max nodal, sigma_F1, sigma_F2, DoFs)"
    cat "$out/$case/fe_stresses.csv"
  fi
done
echo "== checks against the thesis and between the stress sources (check.py)"
/usr/bin/python3 "$here/check.py" "$out"
