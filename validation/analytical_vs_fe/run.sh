#!/usr/bin/env bash
# Calibration of the Weber/Cornell model against the Parker-pair FE sweeps (see README.md).
# Needs validation/parker_ste/results/plane_stress (runs parker_ste/sweeps.sh when missing,
# about 2 min), then gearfem calibrate into results/ (about 4 s); copies calibration.md and
# calibration.png here; check.py ends with PASS or FAIL.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/../lib/common.sh"
need "$gearfem"
"$root/validation/parker_ste/sweeps.sh" --if-missing
(cd "$here" && "$gearfem" calibrate "$here/calibrate.prm" --output-dir "$out") 2>&1 | tee "$out/calibrate.log"
cp "$out/calibration.md" "$out/calibration.png" "$here/"
check "$out/calibration.md" --out "$out"
