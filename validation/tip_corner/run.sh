#!/usr/bin/env bash
# Tip-corner contact acceptance on the Parker pair (README.md).
# Runs gearfem solve with Slave body = 1 and 2, over a full cycle of 40 positions, their
# mirror images and +-0.6/0.75/0.9 deg, at 100/200/340 N m; the single-pass formulation at
# the corner positions for comparison; h_contact 0.05 mm at the transitions. check.py
# compares against the tolerances in README.md and ends with PASS or FAIL.
set -euo pipefail
args_allowed='--h|--gap|[0-9][0-9.]*|node|integrated'
source "$(dirname "${BASH_SOURCE[0]}")/../lib/args.sh"
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(cd "$here/../.." && pwd)"
build="${GEARFEM_BUILD_DIR:-$root/build}"
gearfem="$build/app/gearfem"
[ -x "$gearfem" ] || "$root/scripts/setup"
out="$here/results"
mkdir -p "$out"
/usr/bin/python3 "$here/check.py" --gearfem "$gearfem" --base "$here/parker_corner.prm" --out "$out" "$@"
