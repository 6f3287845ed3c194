#!/usr/bin/env bash
# The Parker-pair FE sweeps (gearfem solve, plane stress and plane strain, 3 torques x 40
# positions; about 1-2 min each on 2 cores) into results/<model>/, logs in results/<model>.log.
#   sweeps.sh              run both sweeps
#   sweeps.sh --if-missing run only the sweeps without a completed result (results/<model>.done);
#                          validation/analytical_vs_fe and parker_dynamics use this.
set -euo pipefail
args_allowed='--if-missing'
source "$(dirname "${BASH_SOURCE[0]}")/../lib/common.sh"
need "$gearfem"
i=0
for model in plane_stress plane_strain; do
  i=$((i + 1))
  [ "${1:-}" = --if-missing ] && [ -f "$out/$model.done" ] && continue
  prm="$here/parker_ste.prm"
  [ "$model" = plane_strain ] && prm="$here/parker_ste_plane_strain.prm"
  rm -f "$out/$model.done"
  echo "== parker_ste sweep $i/2 ($model, 120 positions)"
  "$gearfem" solve "$prm" --output-dir "$out/$model" 2>&1 | tee "$out/$model.log"
  touch "$out/$model.done"
done
