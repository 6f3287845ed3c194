#!/usr/bin/env bash
# The 3-D FE model of the face (`Helical/Model = 3-D FE`, docs/three_d.md) against its plane
# limits, its nu = 0 identity, the beam of the slicing on a misaligned spur face and on the
# helical demo, and its cost (see README.md). About 10 min on 2 cores. check.py ends with
# `three_d: PASS` or `three_d: FAIL`.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/../lib/common.sh"
need "$gearfem"
prm() { # prm NAME B_MM TORQUE SLICES MODEL PLANE NU MISALIGNMENT_UM POSITIONS: the demo teeth, spur
  { sed -e "s/Face width      = 20/Face width      = $2/" -e "s/plane stress/$6/" \
        -e "s/Poisson ratio   = 0.3/Poisson ratio   = $7/" "$root/inputs/demo_fixed_mesh.prm"
    printf 'subsection Solve\n  set Number of positions = %s\n  set Torques = %s\n  set VTU = none\n  set Plots = false\nend\n' "$9" "$3"
    printf 'subsection Helical\n  set Rack section = transverse\n  set Slices = %s\n  set Model = %s\n' "$4" "$5"
    printf '  set Coupling length = %s\n  set Misalignment = %s\nend\n' "$([ "$5" = slices ] && echo 0 || echo -1)" "$8"; } > "$out/$1.prm"
}
run() { # run NAME: gearfem helical on $out/NAME.prm into $out/NAME, its peak memory in NAME.time
  echo "== $1"
  /usr/bin/time -v -o "$out/$1.time" "$gearfem" helical "$out/$1.prm" --output-dir "$out/$1" > "$out/$1.log" 2>&1 ||
    { cat "$out/$1.log"; return 1; }
  grep -E "^3-D body|^T |^build" "$out/$1.log"
}
# Plane limits: b = m/2 and b = 10 m, 3-D against uncoupled plane-stress and plane-strain sections.
for b in 1.5 30; do
  T=$(/usr/bin/python3 -c "print(200 * $b / 20)")
  n=$([ "$b" = 1.5 ] && echo 5 || echo 21)
  prm "b${b}_3d" "$b" "$T" "$n" "3-D FE" "plane stress" 0.3 0 8; run "b${b}_3d"
  prm "b${b}_ps" "$b" "$T" "$n" slices "plane stress" 0.3 0 8; run "b${b}_ps"
  prm "b${b}_pe" "$b" "$T" "$n" slices "plane strain" 0.3 0 8; run "b${b}_pe"
done
# nu = 0: the aligned spur pair in 3-D is its uncoupled sections.
prm nu0_3d 20 200 11 "3-D FE" "plane stress" 0.0 0 8; run nu0_3d
prm nu0_2d 20 200 11 slices "plane stress" 0.0 0 8; run nu0_2d
# A misaligned spur face (f_Sigma_beta 10 and 25 um): 3-D against the beam (l = m) and uncoupled.
for f in 10 25; do
  prm "mis${f}_3d" 20 200 11 "3-D FE" "plane stress" 0.3 "$f" 8; run "mis${f}_3d"
  prm "mis${f}_beam" 20 200 11 "slices" "plane stress" 0.3 "$f" 8
  sed -i 's/set Coupling length = 0/set Coupling length = -1/' "$out/mis${f}_beam.prm"; run "mis${f}_beam"
done
# The helical demo (beta 20 deg, crowned and misaligned), 21 slices, 40 positions: 3-D and beam.
sed 's/set Helix angle  = 20/set Helix angle  = 20\n  set Model = 3-D FE/' "$root/inputs/helical_demo.prm" > "$out/demo_3d.prm"
run demo_3d
cp "$root/inputs/helical_demo.prm" "$out/demo_beam.prm"; run demo_beam
check --out "$out" --table "$here/table.md" --plot "$here/three_d.png"
