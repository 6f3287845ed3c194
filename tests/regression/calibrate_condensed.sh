#!/usr/bin/env bash
# gearfem calibrate on a condensed cycle (Calibration/Condensed cycle): its FE samples at the
# torques of a full solve equal that solve's (same roll angles; STE within 1e-3 of the full
# FE, the condensed route's accuracy), and the calibrated STE follows within 1 %; with the
# default Cycle torques it samples 6 torques over the cycle's range; a torque outside the
# range and a cycle of another pair are refused with exit 2 naming the entry.
#   calibrate_condensed.sh GEARFEM SRC_DIR
set -uo pipefail
gearfem=$1 src=$2
fail() { echo "FAIL: $*" >&2; exit 1; }
work=$(mktemp -d "${TMPDIR:-/tmp}/gearfem_calcond.XXXXXX")
trap 'rm -rf "$work"' EXIT
seed=$src/tests/fuzz/seeds
"$gearfem" condense "$seed/solve_small.prm" --output-dir "$work/cycle" > "$work/condense.log" 2>&1 || { cat "$work/condense.log"; fail "condense"; }
"$gearfem" solve "$seed/solve_small.prm" --output-dir "$work/full" > "$work/solve.log" 2>&1 || { cat "$work/solve.log"; fail "solve"; }
# Beam and Hertz only: on 5 positions the body compliance is not identifiable, and an
# ill-posed fit would amplify the 1e-4 differences of the samples.
sed -e "s|@RESULTS@|$work/full/results.h5|" -e "s|set Fit factors .*|set Fit factors = beam, hertz|" \
  "$seed/calibrate_small.prm" > "$work/full.prm"
sed -e "s|set Results files = @RESULTS@|set Results files =\n  set Condensed cycle = $work/cycle/condensed.h5\n  set Cycle torques = 100, 200, 300|" \
  -e "s|set Fit factors .*|set Fit factors = beam, hertz|" "$seed/calibrate_small.prm" > "$work/cycle.prm"
for c in full cycle; do
  "$gearfem" calibrate "$work/$c.prm" --output-dir "$work/cal_$c" > "$work/cal_$c.log" 2>&1 || { cat "$work/cal_$c.log"; fail "calibrate $c"; }
done
grep -q "15 FE positions at 3 torques from 0 file(s) and the condensed cycle" "$work/cal_cycle.log" || { cat "$work/cal_cycle.log"; fail "the cycle was not sampled"; }
/usr/bin/python3 - "$work" <<'PY' || fail "the condensed samples differ from the full FE"
import csv, sys
w = sys.argv[1]
def rows(c):
    return list(csv.DictReader(open(f"{w}/cal_{c}/calibration.csv")))
a, b = rows("full"), rows("cycle")
assert len(a) == len(b) == 15, (len(a), len(b))
mean = sum(float(r["STE FE [um]"]) for r in a) / len(a)
worst = {"STE FE [um]": 0.0, "STE after [um]": 0.0}
for x, y in zip(a, b):
    assert x["torque [N m]"] == y["torque [N m]"] and abs(float(x["roll angle [deg]"]) - float(y["roll angle [deg]"])) < 1e-9
    for k in worst:
        worst[k] = max(worst[k], abs(float(x[k]) - float(y[k])) / mean)
assert worst["STE FE [um]"] <= 1e-3, worst
assert worst["STE after [um]"] <= 1e-2, worst
print("calibrate on the condensed cycle against the full FE samples (relative to the mean STE):", worst)
PY
# The default torques: 6 over the cycle's range (25 to 600 N m for the build at 300 N m).
sed "s|set Results files = @RESULTS@|set Results files =\n  set Condensed cycle = $work/cycle/condensed.h5|" "$seed/calibrate_small.prm" > "$work/default.prm"
"$gearfem" calibrate "$work/default.prm" --output-dir "$work/cal_default" > "$work/cal_default.log" 2>&1 || { cat "$work/cal_default.log"; fail "calibrate with the default cycle torques"; }
grep -q "30 FE positions at 6 torques" "$work/cal_default.log" || { cat "$work/cal_default.log"; fail "not 6 default torques"; }
# Refusals: a torque outside the cycle's range; the cycle of another pair.
sed "s|set Cycle torques = 100, 200, 300|set Cycle torques = 100, 1000|" "$work/cycle.prm" > "$work/range.prm"
"$gearfem" calibrate "$work/range.prm" --output-dir "$work/x" > /dev/null 2> "$work/range.err"
[ $? -eq 2 ] && grep -q "Calibration/Cycle torques" "$work/range.err" || { cat "$work/range.err"; fail "a torque beyond the cycle's range was not refused"; }
sed "s|set Number of teeth = 40|set Number of teeth = 41|" "$work/cycle.prm" > "$work/other.prm"
"$gearfem" calibrate "$work/other.prm" --output-dir "$work/y" > /dev/null 2> "$work/other.err"
[ $? -eq 2 ] && grep -q "Calibration/Condensed cycle" "$work/other.err" || { cat "$work/other.err"; fail "the cycle of another pair was not refused"; }
echo "calibrate on a condensed cycle: PASS"
