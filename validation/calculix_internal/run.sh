#!/usr/bin/env bash
# CalculiX peer comparison on a planet-ring pair (README.md): gearfem mesh and gearfem solve
# on inputs/internal_ccx.prm (seed 001's stage-1 planet z 28 in the ring z 74, 5-tooth
# sectors; 10 positions along the path that include B and D and come within 0.3 deg of A and
# E; planet torques 2500 and 4500 N m), then ccx (calculix-ccx, single-threaded, two runs side
# by side) on the same gmsh meshes (CPS8, plane stress) at the same positions with gearfem's
# pinion rotations prescribed, at the penalty factor 30 everywhere and 3 at two positions;
# check.py compares STE (1 %) and the ring's root stress (3 %), times both programs
# (measured in this run) and ends with PASS or FAIL. Without ccx it prints
# `calculix_internal: SKIP` and exits 77 (a skip, never a PASS: nothing was compared).
# About 15-25 min of ccx on the shared 2-core machine.
set -euo pipefail
args_allowed='--jobs|--reuse|--kappas|--kappa-positions|[0-9][0-9.,:]*'
source "$(dirname "${BASH_SOURCE[0]}")/../lib/args.sh"
if ! command -v "${CCX:-ccx}" > /dev/null 2>&1; then
  echo "calculix_internal: SKIP (CalculiX 'ccx' not found; install it with apt-get install -y calculix-ccx; nothing was compared)"
  exit 77
fi
source "$(dirname "${BASH_SOURCE[0]}")/../lib/common.sh"
need "$gearfem"
export PYTHONPATH="$root/validation/lib${PYTHONPATH:+:$PYTHONPATH}"
/usr/bin/python3 "$here/run_peer.py" --gearfem "$gearfem" --prm "$root/inputs/internal_ccx.prm" --out "$out" \
  --ccx "${CCX:-ccx}" --kappas 30,3 --kappa-positions 3:2,5 "$@"
check --out "$out" --table "$here/table.md" --plot "$here/comparison.png"
