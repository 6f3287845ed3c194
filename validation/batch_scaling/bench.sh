#!/usr/bin/env bash
# Wall time of `gearfem batch` at np = 1 and np = 2 on the same study (8 designs), parallel
# efficiency E = T1 / (2 T2), peak resident memory and CPU time per process (GNU time), and
# the busy fraction of the two ranks at np = 2.
# Usage: bench.sh [GEARFEM] [OUT]
set -euo pipefail
args_allowed='[^-].*'
source "$(dirname "${BASH_SOURCE[0]}")/../lib/args.sh"
here=$(cd "$(dirname "$0")" && pwd)
gearfem=${1:-$here/../../build/app/gearfem}
out=${2:-$here/out}
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1
rm -rf "$out" && mkdir -p "$out"
now() { date +%s.%N; }
s=$(now)
/usr/bin/time -f "%M kB, %U s user + %S s sys" -o "$out/mem1" "$gearfem" batch "$here/study.prm" --output-dir "$out/np1" > "$out/np1.log" 2>&1
T1=$(echo "$(now) - $s" | bc)
s=$(now)
mpirun -np 2 /usr/bin/time -f "%M kB, %U s user + %S s sys" -a -o "$out/mem2" "$gearfem" batch "$here/study.prm" --output-dir "$out/np2" > "$out/np2.log" 2>&1
T2=$(echo "$(now) - $s" | bc)
echo "np=1: $T1 s; np=2: $T2 s; parallel efficiency T1/(2 T2) = $(echo "scale=3; $T1 / (2 * $T2)" | bc)"
echo "peak RSS and CPU time np=1: $(cat "$out/mem1"); per rank at np=2: $(tr '\n' ';' < "$out/mem2")"
# Busy fraction at np=2: the sum of the jobs' wall times over 2 T2. It separates the
# scheduler's idle time (1 - busy) from slow-down by other load on the machine.
busy=$(grep -h "^batch: job" "$out/np2.log" | sed 's/.*rank [0-9]*, \([0-9.]*\) s.*/\1/' | paste -sd+ | bc)
echo "np=2: sum of job wall times $busy s, busy fraction $(echo "scale=3; $busy / (2 * $T2)" | bc)"
grep -h "^batch: job" "$out/np1.log" "$out/np2.log"
