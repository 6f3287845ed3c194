#!/usr/bin/env bash
# Siasos 2010 (NTUA, ch. 6, tables 6.2-2/3): FE root stress of the 23/69 pair at the highest
# points of single tooth contact, against AGMA 908/2101 (gearfem rate) and the thesis' FEM.
#  1. gearfem profile: the line-of-action points B (gear HPSTC) and D (pinion HPSTC);
#  2. gearfem rate: AGMA and ISO root stresses with the standard's K_H and with the thesis' K_H;
#  3. gearfem solve on 3-tooth sectors (inputs/seed001_root_stress.prm), the mesh ladder at
#     500 and 200 N m: h_fillet 0.5/0.25/0.125/0.0625 mm at h_contact 0.05 mm and h_contact
#     0.2/0.1/0.05 mm at h_fillet 0.125 mm; the finest mesh at all four torques;
#  4. the cause of the h_contact sensitivity of validation/speed_vs_error: the first positions
#     after A at h_contact 0.4 and 0.05 mm (h_fillet 0.25 mm);
#  5. check.py (PASS/FAIL). About 9 min on 2 shared cores (16 min beside heavy jobs).
# Usage: validation/seed001_root_stress/run.sh   (GEARFEM=path/to/gearfem to override)
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/../lib/common.sh"
gearfem="${GEARFEM:-$gearfem}"
need "$gearfem"
input="$root/inputs/seed001_root_stress.prm"
mkdir -p "$out/inputs"
start_all=$(date +%s)

# name h_contact h_fillet torques
runs=(
  "hc0.2_hf0.125 0.2 0.125 500,200"
  "hc0.1_hf0.125 0.1 0.125 500,200"
  "hc0.05_hf0.5 0.05 0.5 500,200"
  "hc0.05_hf0.25 0.05 0.25 500,200"
  "hc0.05_hf0.125 0.05 0.125 500,200"
  "hc0.05_hf0.0625 0.05 0.0625 500,400,300,200"
  "nearA_hc0.4 0.4 0.25 500"
  "nearA_hc0.05 0.05 0.25 500"
)
n=$(( ${#runs[@]} + 2 ))
i=1
echo "== $i/$n: gearfem profile (line of action: B, D)"
"$gearfem" profile "$root/inputs/seed001_23_69.prm" --output-dir "$out/profile" > "$out/profile.log" 2>&1
grep "line of action" "$out/profile.log"
i=$((i + 1))
echo "== $i/$n: gearfem rate (AGMA, ISO; standard and thesis K_H)"
"$gearfem" rate "$root/inputs/seed001_23_69_rate.prm" --output-dir "$out/rate" > "$out/rate.log" 2>&1
"$gearfem" rate "$root/inputs/seed001_23_69_rate_thesis_kh.prm" --output-dir "$out/rate_thesis_kh" > "$out/rate_thesis_kh.log" 2>&1
grep "AGMA sigma_H" "$out/rate.log"
for r in "${runs[@]}"; do
  read -r name hc hf torques <<< "$r"
  i=$((i + 1))
  echo "== $i/$n: gearfem solve, 3-tooth sectors, h_contact $hc mm, h_fillet $hf mm, T1 $torques N m"
  positions=""  # nearA_*: 4 positions from A, a 40th of a pitch apart (the cycle of speed_vs_error)
  [[ $name == nearA_* ]] && positions='s/^\(  set Positions *=\).*/\1 cycle\n  set Number of positions = 4\n  set Pitches = 0.1/'
  sed -e "s/^\(  set h_contact *=\).*/\1 $hc/" -e "s/^\(  set h_fillet *=\).*/\1 $hf/" \
      -e "s/^\(  set Torques *=\).*/\1 ${torques//,/, }/" ${positions:+-e "$positions"} "$input" > "$out/inputs/$name.prm"
  grep -q "h_contact *= $hc$" "$out/inputs/$name.prm"  # the substitutions must have happened
  grep -q "h_fillet *= $hf$" "$out/inputs/$name.prm"
  t0=$(date +%s)
  rm -rf "${out:?}/$name"
  nice -n 10 "$gearfem" solve "$out/inputs/$name.prm" --output-dir "$out/$name" > "$out/$name.log" 2>&1
  echo "   $(grep -m1 '^model:' "$out/$name.log")"
  echo "   wall $(( $(date +%s) - t0 )) s"
done
echo "== total wall time $(( $(date +%s) - start_all )) s" | tee "$out/wall_time.txt"
check --out "$out"
