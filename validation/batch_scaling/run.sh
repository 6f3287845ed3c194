#!/usr/bin/env bash
# Wall time of `gearfem batch` at np = 1 and np = 2 on the same study (8 designs), parallel
# efficiency E = T1 / (2 T2), peak resident memory per rank (GNU time).
# Usage: run.sh [GEARFEM] [OUT]
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
gearfem=${1:-$here/../../build/app/gearfem}
out=${2:-$here/out}
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1
rm -rf "$out" && mkdir -p "$out"
now() { date +%s.%N; }
s=$(now)
/usr/bin/time -f "%M" -o "$out/mem1" "$gearfem" batch "$here/study.prm" --output-dir "$out/np1" > "$out/np1.log" 2>&1
T1=$(echo "$(now) - $s" | bc)
s=$(now)
mpirun -np 2 /usr/bin/time -f "%M" -a -o "$out/mem2" "$gearfem" batch "$here/study.prm" --output-dir "$out/np2" > "$out/np2.log" 2>&1
T2=$(echo "$(now) - $s" | bc)
echo "np=1: $T1 s; np=2: $T2 s; parallel efficiency T1/(2 T2) = $(echo "scale=3; $T1 / (2 * $T2)" | bc)"
echo "peak RSS np=1: $(cat "$out/mem1") kB; per rank at np=2: $(tr '\n' ' ' < "$out/mem2")kB"
grep -h "^batch: job" "$out/np1.log" "$out/np2.log"
