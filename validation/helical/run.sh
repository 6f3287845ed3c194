#!/usr/bin/env bash
# Helical pairs by face-width slicing (see README.md): the Parker pair's transverse section
# condensed once, then helical runs on it (21 and 51 slices, an overlap-ratio sweep, a misaligned
# spur face), a full-FE spur cycle for the cost ratio, and ISO/TR 6336-30 example 1 for c_gamma.
# About 5 min on 2 cores. check.py ends with `helical: PASS` or `helical: FAIL`.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/../lib/common.sh"
need "$gearfem"
prm() { # prm NAME BETA SLICES COUPLING_LENGTH MISALIGNMENT [COUPLING]: the demo pair with a Helical section
  { cat "$root/inputs/demo_fixed_mesh.prm"
    printf 'subsection Solve\n  set VTU = none\n  set Plots = false\nend\n'
    printf 'subsection Helical\n  set Rack section = transverse\n  set Helix angle = %s\n  set Slices = %s\n' "$2" "$3"
    printf '  set Coupling = %s\n' "${6:-bending}"
    printf '  set Coupling length = %s\n  set Misalignment = %s\nend\n' "$4" "$5"; } > "$out/$1.prm"
}
run() { # run NAME [args]: gearfem helical on $out/NAME.prm into $out/NAME
  local n="$1"; shift
  echo "== $n"
  "$gearfem" helical "$out/$n.prm" --output-dir "$out/$n" "$@" > "$out/$n.log" 2>&1 || { cat "$out/$n.log"; return 1; }
  grep -E "^T |^build" "$out/$n.log"
}
echo "== spur_fe: the demo's full-FE cycle (40 positions), for the cost ratio"
{ cat "$root/inputs/demo_fixed_mesh.prm"; printf 'subsection Solve\n  set VTU = none\n  set Plots = false\nend\n'; } > "$out/spur_fe.prm"
"$gearfem" solve "$out/spur_fe.prm" --output-dir "$out/spur_fe" > "$out/spur_fe.log" 2>&1
grep -E "^time" "$out/spur_fe.log"
prm b15_n21 15 21 -1 0
run b15_n21 # builds and writes the condensed cycle of the transverse section
cycle="$out/b15_n21/condensed.h5"
prm b15_n51 15 51 -1 0
run b15_n51 --condensed "$cycle"
# Overlap ratio eps_beta = b tan(beta) / (pi m_t) with the transverse section fixed (m_t 3 mm, b 20 mm).
for e in 0 0.25 0.5 0.75 1 1.25 1.5 1.75 2; do
  beta=$(/usr/bin/python3 -c "import math; print(math.degrees(math.atan($e * math.pi * 3 / 20)))")
  prm "eps_$e" "$beta" 21 -1 0
  run "eps_$e" --condensed "$cycle"
done
# A misaligned spur face (beta 0): f_Sigma_beta 10 and 25 um; bending coupling (default),
# uncoupled, and the shear layer.
for f in 10 25; do
  prm "mis_$f" 0 21 -1 "$f"; run "mis_$f" --condensed "$cycle"
  prm "mis_${f}_winkler" 0 21 0 "$f"; run "mis_${f}_winkler" --condensed "$cycle"
  prm "mis_${f}_shear" 0 21 -1 "$f" shear; run "mis_${f}_shear" --condensed "$cycle"
done
echo "== iso_tr: ISO/TR 6336-30 example 1 (m_n 8, z 17/103, beta 15.8 deg), its own cycle"
"$gearfem" helical "$root/inputs/helical_iso_tr.prm" --output-dir "$out/iso_tr" > "$out/iso_tr.log" 2>&1 ||
  { cat "$out/iso_tr.log"; exit 1; }
grep -E "^T |^build" "$out/iso_tr.log"
check --out "$out" --table "$here/table.md" --plot "$here/helical.png"
