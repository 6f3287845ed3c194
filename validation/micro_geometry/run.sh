#!/usr/bin/env bash
# Micro-geometry as a gap modification (README.md): the Parker pair with linear tip relief
# on both gears, long and short, at the design load, meshed with the relief (exact) and
# applied as an initial separation on the unmodified mesh. check.py compares STE and root
# stress position by position and ends with PASS or FAIL.
set -euo pipefail
args_allowed='--amount|--long|--positions|[0-9][0-9.]*'
source "$(dirname "${BASH_SOURCE[0]}")/../lib/args.sh"
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(cd "$here/../.." && pwd)"
build="${GEARFEM_BUILD_DIR:-$root/build}"
gearfem="$build/app/gearfem"
[ -x "$gearfem" ] || "$root/scripts/setup"
out="$here/results"
mkdir -p "$out"
/usr/bin/python3 "$here/check.py" --gearfem "$gearfem" --base "$here/parker_relief.prm" --out "$out" "$@"
