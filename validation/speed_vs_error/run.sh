#!/usr/bin/env bash
# Speed against error (README.md): every rung of the model ladder on the
# Parker pair, FZG type C and Siasos 2010's 23/69 at three torques each, against the converged
# FE (full gears, Q2, Lagrange, h_contact 0.05 mm). About 10 min on the 2-core machine
# (the three references are most of it).
#   run.sh            run every rung (results/<pair>/<rung>), then analyse and check
#   run.sh --reuse    keep the rungs that finished in an earlier run (results/.../done)
#   SPEED_VS_ERROR_PAIRS=parker run.sh   only the named pairs (comma-separated; the Parker pair
#                     alone takes about 10 min of CPU)
# Copies table.md, which_model.md and pareto_*.png here; check.py ends with PASS or FAIL.
set -euo pipefail
args_allowed='--reuse|--only|--pairs|[a-z0-9_.,]+'
source "$(dirname "${BASH_SOURCE[0]}")/../lib/common.sh"
need "$gearfem"
export SPEED_VS_ERROR_PAIRS="${SPEED_VS_ERROR_PAIRS:-parker,fzg_c,seed001}"
/usr/bin/python3 "$here/study.py" --pairs "$SPEED_VS_ERROR_PAIRS" "$@"
/usr/bin/python3 "$here/analyse.py" --out "$out"
# The tracked copies only come from a run of all three pairs.
[ "$SPEED_VS_ERROR_PAIRS" = parker,fzg_c,seed001 ] && cp "$out/table.md" "$out/which_model.md" "$out/summary.md" "$out"/pareto_*.png "$here/"
check
