#!/usr/bin/env bash
# CalculiX peer comparison on the FZG type C pair (README.md): gearfem
# solve on inputs/fzg_c_ccx.prm (9 positions over one pitch that bracket both transitions,
# LS7 and LS9), then ccx (calculix-ccx, single-threaded) on the same gmsh meshes (CPS8, plane
# stress) at the same positions with gearfem's pinion rotations prescribed, at the penalty
# factor 30 everywhere and 3 at two (a transition and C); check.py compares STE, mesh stiffness,
# load sharing and root stress, times both programs (measured in this run) and ends with
# PASS or FAIL. Without ccx it prints `calculix_peer: SKIP` and exits 77 (a skip, never a
# PASS: nothing was compared). About 25-40 min of ccx on the shared 2-core machine.
set -euo pipefail
args_allowed='--jobs|--reuse|--kappas|--kappa-positions|[0-9][0-9.,:]*'
source "$(dirname "${BASH_SOURCE[0]}")/../lib/args.sh"
if ! command -v "${CCX:-ccx}" > /dev/null 2>&1; then
  echo "calculix_peer: SKIP (CalculiX 'ccx' not found; install it with apt-get install -y calculix-ccx; nothing was compared)"
  exit 77
fi
source "$(dirname "${BASH_SOURCE[0]}")/../lib/common.sh"
need "$gearfem"
export PYTHONPATH="$root/validation/lib${PYTHONPATH:+:$PYTHONPATH}"
echo "== ccx plane stress: CPS8 cantilever at three section thicknesses (slab_check.py)"
/usr/bin/python3 "$here/slab_check.py" --ccx "${CCX:-ccx}" --out "$out"
/usr/bin/python3 "$here/run_peer.py" --gearfem "$gearfem" --prm "$root/inputs/fzg_c_ccx.prm" --out "$out" \
  --fine-prm "$root/inputs/fzg_c_ccx_fine.prm" \
  --ccx "${CCX:-ccx}" --kappas 30,3 --kappa-positions 3:2,4 "$@"
check --out "$out" --table "$here/table.md" --plot "$here/comparison.png"
