#!/usr/bin/env bash
# Parker pair up/down RMS-DTE sweeps at 100/200/340 N m (interim analytical table), then
# analyse.py: resonance, jump frequencies, contact loss, linear natural frequency; plot.
# Usage: validation/parker_dynamics/run.sh   (GEARFEM=path/to/gearfem to override)
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(cd "$here/../.." && pwd)"
gearfem="${GEARFEM:-$root/build/app/gearfem}"
out="${OUT:-$here/results}"
for T in 100 200 340; do
  /usr/bin/time -f "${T} N m: wall %e s" "$gearfem" dynamics "$here/sweep_${T}Nm.prm" \
    --output-dir "$out/${T}Nm" | grep -E "natural frequency|warning" | sed "s/^/${T} N m: /"
done
/usr/bin/python3 "$here/analyse.py" "$here/parker_sweeps.png" "$out/100Nm" "$out/200Nm" "$out/340Nm"
