#!/usr/bin/python3
"""FE peak fillet stress over the mesh levels against ISO 6336-3 (results.csv -> root_stress.png)."""
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

here = os.path.dirname(os.path.abspath(__file__))
src = sys.argv[1] if len(sys.argv) > 1 else os.path.join(here, "results.csv")
rows = list(csv.reader(open(src)))[1:]
cases = {}
for r in rows:
    z, x, level, cells, dofs, fe, iso, rich, ratio = map(float, r)
    cases.setdefault((int(z), x), []).append((int(level), dofs, fe, iso, rich))
fig, ax = plt.subplots(figsize=(7, 4.5))
for k, ((z, x), v) in enumerate(sorted(cases.items())):
    c = f"C{k}"
    ax.plot([d for _, d, _, _, _ in v], [f / v[0][3] for _, _, f, _, _ in v], "o-", color=c,
            label=f"z {z}, x {x:+.1f}: FE/ISO (Richardson {v[-1][4] / v[0][3]:.3f})")
ax.axhline(1.0, color="k", lw=1, label="ISO 6336-3 F_t/(b m) Y_Fa Y_Sa")
ax.axhspan(0.9, 1.1, color="0.9", zorder=0, label="+-10 %")
ax.set_xscale("log")
ax.set_xlabel("DoFs (3-tooth sector, Q2, 3 uniform refinements)")
ax.set_ylabel("FE peak fillet sigma_1 / ISO")
ax.set_ylim(0.85, 1.15)
ax.legend(fontsize=8)
ax.set_title("Single tooth, tip load, plane stress (m 3 mm, b 20 mm)")
fig.tight_layout()
out = os.path.join(os.path.dirname(os.path.abspath(src)), "root_stress.png")
fig.savefig(out + ".tmp.png", dpi=130)
os.replace(out + ".tmp.png", out)
