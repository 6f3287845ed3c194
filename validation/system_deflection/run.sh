#!/usr/bin/env bash
# The gear pair on its shafts (see README.md): the straddled spur pair of
# inputs/system_straddle.prm with its lead correction (which builds the transverse section's
# cycle), then on that cycle uncorrected, uncoupled and as a 15 deg helical pair; and the
# overhung pinion of inputs/system_overhung.prm; and the two-stage train of
# inputs/system_two_stage.prm. About 1 min on 2 cores. check.py ends with
# `system_deflection: PASS` or `system_deflection: FAIL`.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/../lib/common.sh"
need "$gearfem"
variant() { # variant NAME [SYSTEM/HELICAL LINES]: inputs/system_straddle.prm with the lines appended
  local n="$1"; shift
  { cat "$root/inputs/system_straddle.prm"; printf 'subsection Solve\n  set Plots = false\nend\n'; printf '%s\n' "$@"; } \
    > "$out/$n.prm"
}
run() { # run NAME [args]: gearfem helical on $out/NAME.prm into $out/NAME
  local n="$1"; shift
  echo "== $n"
  "$gearfem" helical "$out/$n.prm" --output-dir "$out/$n" "$@" > "$out/$n.log" 2>&1 || { cat "$out/$n.log"; return 1; }
  grep -E "^T |^build|^lead" "$out/$n.log" || true
}
variant straddle
run straddle # builds and writes the transverse section's cycle
cycle="$out/straddle/condensed.h5"
variant straddle_uncorrected 'subsection System' '  set Correction torque = 0' 'end'
run straddle_uncorrected --condensed "$cycle"
variant straddle_none 'subsection System' '  set Coupling = none' 'end'
run straddle_none --condensed "$cycle"
variant straddle_helical 'subsection System' '  set Correction torque = 0' 'end' \
  'subsection Helical' '  set Helix angle = 15' '  set Hand = right' 'end'
run straddle_helical --condensed "$cycle"
# The cost: the coupled and uncoupled sweeps twice more, alternating; check.py takes the fastest
# of each (the sweeps take a fraction of a second on a shared machine).
for k in 2 3; do
  for n in straddle_uncorrected straddle_none; do
    "$gearfem" helical "$out/$n.prm" --condensed "$cycle" --output-dir "$out/cost_${n}_$k" > "$out/cost_${n}_$k.log" 2>&1 ||
      { cat "$out/cost_${n}_$k.log"; exit 1; }
  done
done
{ cat "$root/inputs/system_overhung.prm"; printf 'subsection Solve\n  set Plots = false\nend\n'
  printf 'subsection System\n  set Correction torque = 0\nend\n'; } > "$out/overhung.prm"
run overhung
echo "== two_stage"
"$gearfem" system "$root/inputs/system_two_stage.prm" --output-dir "$out/two_stage" > "$out/two_stage.log" 2>&1 ||
  { cat "$out/two_stage.log"; exit 1; }
grep -E "^stage|^on the shafts" "$out/two_stage.log"
check --out "$out" --table "$here/table.md" --plot "$here/system_deflection.png"
