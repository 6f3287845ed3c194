#!/usr/bin/env bash
# CLI check of `Solve/Error estimate = true`, quick: 3-tooth sectors of the
# Parker pair at 200 N m, sweep over the named points B and D, coarse contact mesh.
#   error_estimate_checks.sh GEARFEM
# Checks: exit 0; run.json is valid JSON with an `error_estimate` member (3 samples, all
# numbers finite, error = 4/3 (h/2 - h)); the level-h value at the transition sample D equals
# the sweep's own row at D (an independent solve of the same model and position: sweep.csv,
# written by another code path), to 1e-6 relative; the summary prints the table.
set -uo pipefail
gearfem=$1
fail() { echo "FAIL: $*" >&2; exit 1; }
work=$(mktemp -d "${TMPDIR:-/tmp}/gearfem_est.XXXXXX")
trap 'rm -rf "$work"' EXIT
cat > "$work/case.prm" <<'PRM'
# gearfem solve
subsection Rack
  set Module = 3
  set Pressure angle = 20
end
subsection Gear 1
  set Number of teeth = 50
  set Face width = 20
end
subsection Gear 2
  set Number of teeth = 50
  set Face width = 20
end
subsection Pair
  set Centre distance = 150
end
subsection Mesh
  set Model = sector
  set Sector teeth = 3
  set h_contact = 0.2
  set h_fillet = 0.4
  set h_body = 3
end
subsection Solve
  set Positions = named
  set Named positions = B, D
  set Torques = 200
  set VTU = none
  set Plots = false
  set Error estimate = true
end
PRM
"$gearfem" solve "$work/case.prm" --output-dir "$work/out" > "$work/log" 2>&1 || { cat "$work/log"; fail "solve failed"; }
cat "$work/log"
grep -q "Estimated discretisation error" "$work/log" || fail "no error-estimate table in the summary"
grep -q "error-estimate solve 6/6" "$work/log" || fail "no progress line 6/6"
/usr/bin/python3 - "$work/out/run.json" "$work/out/sweep.csv" <<'PY' || fail "run.json check"
import csv, json, math, sys
e = json.load(open(sys.argv[1]))["error_estimate"]
assert len(e["samples"]) == 3, e["samples"]
assert [s["point"] for s in e["samples"]] == ["(B+D)/2", "(A+B)/2", "D"]
keys = {"STE_um": "STE [um]", "root_stress_pinion_MPa": "root stress pinion [MPa]",
        "root_stress_gear_MPa": "root stress gear [MPa]", "p_max_MPa": "p_max [MPa]"}
for s in e["samples"]:
    for k in keys:
        q = s[k]
        assert all(math.isfinite(q[x]) for x in ("h", "h_over_r", "error", "relative")), (s, k)
        assert abs(q["error"] - 4 / 3 * (q["h_over_r"] - q["h"])) <= 1e-9 * abs(q["h"]), (s, k)
rows = [r for r in csv.DictReader(open(sys.argv[2])) if r["point (0 none; 1 A; 2 B; 3 C; 4 D; 5 E) [-]"].startswith("4")]
assert len(rows) == 1, rows
d = e["samples"][2]
for k, col in keys.items():
    a, b = d[k]["h"], float(rows[0][col])
    print(f"D: {k} estimate level h {a:.9g}, sweep.csv {b:.9g}")
    assert abs(a - b) <= 1e-6 * abs(b), (k, a, b)
assert e["fine_dofs"] > 0 and e["seconds_setup"] > 0 and e["run_sweep_seconds"] > 0
print("error_estimate CLI: OK")
PY
