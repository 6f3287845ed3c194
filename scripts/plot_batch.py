#!/usr/bin/python3
"""Plots of a `gearfem batch` aggregate (docs/batch.md): design_space.png always, and
harris_map.png when the designs vary `Gear 1/Tip relief amount` (peak-to-peak STE against
torque, one curve per relief, the minimum of each curve marked and printed).

    MPLBACKEND=Agg /usr/bin/python3 scripts/plot_batch.py <batch output folder>
"""
import csv
import os
import sys

import matplotlib.pyplot as plt

folder = sys.argv[1]
rows = list(csv.reader(open(os.path.join(folder, "batch.csv"))))
head, rows = rows[0], [r for r in rows[1:] if r[-1] == "ok"]
col = {h: i for i, h in enumerate(head)}
params = head[col["id [text]"] + 1: col["torque [N m]"]]
by_id = {}
for r in rows:
    by_id.setdefault(r[col["id [text]"]], []).append(r)

amount = next((p for p in params if p.startswith("Gear 1/Tip relief amount")), None)
length = next((p for p in params if p.startswith("Gear 1/Tip relief length")), None)
if amount:
    fig, ax = plt.subplots(figsize=(8, 5))
    print("| design | C_a [um] | length [mm] | torque at min p-p STE [N m] | min p-p STE [um] |")
    print("|---|---|---|---|---|")
    for i, (d, rs) in enumerate(sorted(by_id.items(), key=lambda kv: (kv[1][0][col[length]] if length else "", float(kv[1][0][col[amount]])))):
        rs.sort(key=lambda r: float(r[col["torque [N m]"]]))
        T = [float(r[col["torque [N m]"]]) for r in rs]
        pp = [float(r[col["STE peak-to-peak [um]"]]) for r in rs]
        ca = float(rs[0][col[amount]])
        ln = float(rs[0][col[length]]) if length else 0
        style = "-" if not length or ln >= max(float(r[col[length]]) for r in rows) else "--"
        line, = ax.semilogx(T, pp, style, marker="o", ms=3, label=f"{d}: {ca:g} um" + (f" over {ln:g} mm" if length else ""))
        k = min(range(len(pp)), key=lambda j: pp[j])
        ax.plot(T[k], pp[k], "v", color=line.get_color(), ms=8)
        print(f"| {d} | {ca:g} | {ln:g} | {T[k]:g} | {pp[k]:.3f} |")
    ax.set_xlabel("pinion torque [N m]")
    ax.set_ylabel("peak-to-peak STE [um]")
    ax.set_title("Harris map: peak-to-peak STE against torque (triangles: minimum of each relief)")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=7, ncol=2)
    fig.tight_layout()
    fig.savefig(os.path.join(folder, "harris_map.png"), dpi=120)

# Design space: every result column against the first design parameter, one marker per torque.
x = params[0]
fig, axes = plt.subplots(2, 2, figsize=(10, 7))
for ax, y in zip(axes.flat, ["STE peak-to-peak [um]", "k_secant per width mean [N/(mm um)]", "p_max [MPa]",
                             "root stress pinion [MPa]"]):
    for T in sorted({float(r[col["torque [N m]"]]) for r in rows}):
        sel = [r for r in rows if float(r[col["torque [N m]"]]) == T]
        try:
            xs = [float(r[col[x]]) for r in sel]
        except ValueError:
            xs = [r[col[x]] for r in sel]
        ax.plot(xs, [float(r[col[y]]) for r in sel], "o", ms=4, label=f"{T:g} N m")
    ax.set_xlabel(x)
    ax.set_ylabel(y)
    ax.grid(True, alpha=0.3)
axes.flat[0].legend(fontsize=7)
fig.suptitle("gearfem batch: design space")
fig.tight_layout()
fig.savefig(os.path.join(folder, "design_space.png"), dpi=120)
