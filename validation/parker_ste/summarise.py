"""Summarise the Parker-pair sweeps (results/<model>/sweep.csv and the console table of
<model>.log) as markdown: per torque the mean and peak-to-peak STE, the mean secant mesh
stiffness against ISO 6336-1 c_gamma_alpha, the width of the single-pair zone and the
extent of extended contact beyond the geometric single-pair zone B..D."""
import csv
import os
import sys

root = sys.argv[1]


def read(path):
    with open(path) as f:
        rows = list(csv.reader(f))
    head = [h.split(" [")[0] for h in rows[0]]
    return [dict(zip(head, map(float, r))) for r in rows[1:]]


print("| model | T1 [N m] | mean STE [um] | STE p-p [um] | mean k_secant [N/(mm um)] | ISO c_gamma_alpha "
      "[N/(mm um)] | FE/ISO | single-pair zone [deg] | geometric B..D [deg] | max p [MPa] | time per position [s] |")
print("|---|---|---|---|---|---|---|---|---|---|---|")
for model in ("plane_stress", "plane_strain"):
    d = os.path.join(root, model)
    if not os.path.exists(os.path.join(d, "sweep.csv")):
        continue
    sweep = read(os.path.join(d, "sweep.csv"))
    loa = {int(r["point (1 A; 2 B; 3 C; 4 D; 5 E)"]): r["roll angle"] for r in read(os.path.join(d, "line_of_action.csv"))}
    iso = {}
    with open(os.path.join(root, model + ".log")) as f:
        for line in f:
            cells = [c.strip() for c in line.strip().strip("|").split("|")]
            if len(cells) >= 6 and cells[0].replace(".", "").isdigit():
                iso[float(cells[0])] = float(cells[4])
    for T in sorted({r["torque"] for r in sweep}):
        rows = [r for r in sweep if r["torque"] == T]
        ste = [r["STE"] for r in rows]
        k = [r["k_secant per width"] for r in rows]
        step = rows[1]["roll angle"] - rows[0]["roll angle"] if len(rows) > 1 else 0
        single = sum(1 for r in rows if r["pairs in contact"] == 1) * step
        kbar = sum(k) / len(k)
        print("| %s | %g | %.3f | %.3f | %.2f | %.2f | %.3f | %.2f | %.2f | %.0f | %.2f |" % (
            model.replace("_", " "), T, sum(ste) / len(ste), max(ste) - min(ste), kbar, iso.get(T, 0),
            kbar / iso[T] if iso.get(T) else 0, single, loa[4] - loa[2], max(r["p_max"] for r in rows),
            sum(r["time"] for r in rows) / len(rows)))
