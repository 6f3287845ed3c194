# Sourced by validation/<case>/run.sh (bash, after `set -euo pipefail`): defines
#   here   the case folder;  root  the repository;  build  the build folder
#   (GEARFEM_BUILD_DIR, default <root>/build);  gearfem  the executable;
#   out    the case's generated output (<here>/results, git-ignored, created here);
#   need   `need <file>...`: builds (scripts/setup) when a listed build product is missing;
#   check  `check [args]`: runs <here>/check.py with /usr/bin/python3 in place of the
#          script (exec: the last command of run.sh), so its PASS/FAIL line and status end it.
# A failing step ends the script (set -e, pipefail) with a `<case>: FAIL (step failed ...)` line.
_script="${BASH_SOURCE[1]}"
source "$(dirname "${BASH_SOURCE[0]}")/args.sh" # --help, and no argument the script does not take
here="$(cd "$(dirname "${BASH_SOURCE[1]}")" && pwd)"
root="$(cd "$here/../.." && pwd)"
build="${GEARFEM_BUILD_DIR:-$root/build}"
gearfem="$build/app/gearfem"
out="$here/results"
mkdir -p "$out"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 MPLBACKEND=Agg

need() {
  local f
  for f in "$@"; do
    if [ ! -x "$f" ]; then
      echo "== $f is missing: building with scripts/setup"
      GEARFEM_BUILD_DIR="$build" "$root/scripts/setup"
      return
    fi
  done
}

check() {
  PYTHONPATH="$root/validation/lib${PYTHONPATH:+:$PYTHONPATH}" exec /usr/bin/python3 "$here/check.py" "$@"
}

trap '_rc=$?; echo "$(basename "$here"): FAIL (step failed with exit $_rc: $BASH_COMMAND)"' ERR
