#!/usr/bin/env bash
# The Python module at speed (README.md): a demo cycle re-solved from Python at 10 torques x 40
# positions against the C++ re-solve of the same work in the same process; a Python-scripted
# Harris map (20 reliefs x 12 torques x 40 positions on one cycle, build included) against the
# batch study of validation/harris_map; the fixed cost of `gearfem solve --condensed` (plots
# off) on the demo. About 1 min on the 2-core machine.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/../lib/common.sh"
[ -f "$build/python/gearfem.cpython-311-x86_64-linux-gnu.so" ] || GEARFEM_BUILD_DIR="$build" "$root/scripts/setup"
need "$gearfem"
export PYTHONPATH="$build/python" OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1
# One rank: its one condensed cycle is built from the first design (no relief), as the Python
# map's is; two ranks would each build theirs from another design (0.2 % apart near minima).
echo "== [1/3] the batch study of the Harris map (gearfem batch inputs/harris_map.prm, one rank)"
rm -rf "$out/batch"
"$gearfem" batch "$root/inputs/harris_map.prm" --output-dir "$out/batch" > "$out/batch.log" 2>&1
echo "== [2/3] the Harris map from Python"
/usr/bin/python3 "$here/harris_map.py" "$out/harris" --batch-dir "$out/batch" | tee "$out/harris.log"
echo "== [3/3] re-solve speed from Python and the CLI's fixed cost"
check --gearfem "$gearfem" --out "$out"
