#!/usr/bin/env bash
# Harris map (README.md) of inputs/harris_map.prm with `gearfem batch`, then
# scripts/plot_batch.py: harris_map.png, design_space.png and the table of minima.
#   study.sh full    [NP]  the study as written: full gears, 25 mm bores, 12 torques x 40
#                          positions, reliefs as gap modifications (one factorisation per rank)
#   study.sh exact   [NP]  the same with Contact/Micro-geometry = geometry (each relieved
#                          profile meshed: 11 factorisations), the reference of the gap route
#   study.sh preview [NP]  3-tooth sector models (rim-clamped), h_contact 0.2 mm, 16 positions:
#                          the shape of the map in minutes, not its numbers
# Then check.py checks the full study against Harris (1958) / Tavakoli & Houser (1986), the
# batch-study requirement's unrelieved figure, the load-sharing argument for short reliefs
# and, when out_exact/ exists, the gap route against the exact one; it ends with
# harris_map: PASS|FAIL.
# Not in the quick or long tier: ~25-60 min at np = 2.
set -euo pipefail
args_allowed='full|exact|preview|[0-9]+'
source "$(dirname "${BASH_SOURCE[0]}")/../lib/args.sh"
here=$(cd "$(dirname "$0")" && pwd)
src=$here/../..
gearfem=${GEARFEM:-$src/build/app/gearfem}
mode=${1:-preview} np=${2:-2}
out=$here/out_$mode
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1
study=$src/inputs/harris_map.prm
case "$mode" in
  full|exact|preview) ;;
  *) echo "study.sh: unknown mode '$mode' (allowed: full, exact, preview)" >&2; exit 2 ;;
esac
mkdir -p "$out"  # every mode tees its log there, also from a clean clone
if [ "$mode" = preview ]; then
  { sed -e "s|Design table = harris_map_designs.csv|Design table = $src/inputs/harris_map_designs.csv|" "$study"
    printf 'subsection Mesh\n  set Model = sector\n  set Sector teeth = 3\n  set h_contact = 0.2\nend\n'
    printf 'subsection Solve\n  set Number of positions = 16\n  set VTU = none\nend\n'; } > "$out/preview.prm"
  study=$out/preview.prm
elif [ "$mode" = exact ]; then
  { sed -e "s|Design table = harris_map_designs.csv|Design table = $src/inputs/harris_map_designs.csv|" "$study"
    printf 'subsection Contact\n  set Micro-geometry = geometry\nend\n'; } > "$out/exact.prm"
  study=$out/exact.prm
fi
s=$(date +%s)
# grep exits 1 when every line is a job line: not a failure of the study (pipefail).
mpirun -np "$np" "$gearfem" batch "$study" --output-dir "$out" | tee "$out/batch.log" | { grep -v '^batch: job' || true; }
echo "wall $(( $(date +%s) - s )) s at np = $np"
MPLBACKEND=Agg /usr/bin/python3 "$src/scripts/plot_batch.py" "$out"
if [ "$mode" = full ]; then
  exact=()
  [ -f "$here/out_exact/batch.csv" ] && exact=(--exact "$here/out_exact")
  MPLBACKEND=Agg /usr/bin/python3 "$here/check.py" "$out" "${exact[@]}"
fi
