#!/usr/bin/env bash
# Speed against error (issue 14 section 1; README.md): every rung of the model ladder on the
# Parker pair, FZG type C and seed 001's 23/69 at three torques each, against the converged
# FE (full gears, Q2, Lagrange, h_contact 0.05 mm). About 60-90 min on the 2-core machine
# (the three references are most of it).
#   run.sh            run every rung (results/<pair>/<rung>), then analyse and check
#   run.sh --reuse    keep the rungs that finished in an earlier run (results/.../done)
# Copies table.md, which_model.md and pareto_*.png here; check.py ends with PASS or FAIL.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/../lib/common.sh"
need "$gearfem"
/usr/bin/python3 "$here/study.py" "$@"
/usr/bin/python3 "$here/analyse.py" --out "$out"
cp "$out/table.md" "$out/which_model.md" "$out"/pareto_*.png "$here/"
check
