#!/usr/bin/env bash
# Accuracy-driven model choice (README.md): `gearfem solve` with `Solve/Target = mean STE 1,
# p-p STE 1, root stress 3` and no Mesh settings (`auto`), on the Parker pair, FZG type C,
# Siasos 2010's 23/69 and two pairs drawn at random (seed 36), against a converged reference
# and the fixed-mesh ladder h_contact m/10, m/15, m/30, m/45 (h_fillet 0.25 mm or m/12); each
# pair at three torques in one run per model (speed_vs_error's three; random pairs F/b = 25 m,
# 50 m, 100 m N/mm), errors the largest over the torques; and the demo (inputs/demo.prm with a
# target, 200 N m) against the Parker reference at 200 N m; four mesh draws of each pair's
# auto input (Mesh/Growth ratio 1.18-1.22). 5-12 min on the 2-core
# machine (278 s measured for the 67 runs when idle).
#   run.sh              draw the designs, run every model (results/<pair>/<run>/), check
#   run.sh --reuse      keep the runs finished by an earlier run with the same input
#   run.sh --draw-only  only draw and validate the random designs (results/designs.json)
#   MODEL_CHOICE_PAIRS=parker,demo run.sh   only the named pairs (comma-separated, of
#                       parker, demo, fzg_c, seed001, rand1, rand2; demo needs parker)
# check.py ends with PASS or FAIL; it writes results/table.md and, after a run of all pairs,
# the tracked copy table.md here.
set -euo pipefail
args_allowed='--reuse|--draw-only|--repeat=[0-9]+'
source "$(dirname "${BASH_SOURCE[0]}")/../lib/common.sh"
need "$gearfem"
export MODEL_CHOICE_PAIRS="${MODEL_CHOICE_PAIRS:-parker,demo,fzg_c,seed001,rand1,rand2}"
export PYTHONDONTWRITEBYTECODE=1
# study.py exits 1 when some runs failed: check.py then reports them (missing runs fail there).
rc=0
/usr/bin/python3 "$here/study.py" --pairs "$MODEL_CHOICE_PAIRS" "$@" || rc=$?
if [ $rc -gt 1 ]; then echo "model_choice: FAIL (study.py exit $rc)"; exit $rc; fi
for a in "$@"; do
  if [ "$a" = --draw-only ]; then echo "model_choice: designs drawn (--draw-only: nothing checked)"; exit 0; fi
done
check
