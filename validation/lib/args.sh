# Sourced by every validation script (directly, or through common.sh) before any work:
#   --help or -h   prints the script's header comment, exit 0;
#   any argument the script does not take is refused with exit 2, before anything is created.
# A script that takes arguments sets `args_allowed` (a bash regex over one argument) first.
# tests/regression/script_args.py runs both on every script from a clean copy of the tree.
_script="${_script:-${BASH_SOURCE[1]}}"
for _a in "$@"; do
  case "$_a" in
    -h|--help) sed -n '2,/^[^#]/{/^#/s/^# \{0,1\}//p}' "$_script"; exit 0 ;;
  esac
  if [ -z "${args_allowed:-}" ] || [[ ! "$_a" =~ ^(${args_allowed})$ ]]; then
    echo "$(basename "$(dirname "$_script")")/$(basename "$_script"): unknown argument '$_a'" \
         "(allowed: ${args_allowed:-none}; --help)" >&2
    exit 2
  fi
done
unset _a
