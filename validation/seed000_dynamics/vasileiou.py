#!/usr/bin/python3
"""Gkimisis 2019 Figs 27-28 (Vasileiou's pair, speed source): the two cases, a quasi-static
run of each (100 rpm, f_mesh 53 Hz, 4096 steps per period, same file otherwise) to tell the single-pair zone from the double-pair
zone, the phase portraits (DTE against its rate) and the figures check.py compares with what
the thesis shows: contact kept, period 1, and two distinct regions (single and double
contact) in the portrait.

Two regions: with the zones of the quasi-static run (mesh position modulo the pitch; single
pair where the static DTE is above the mid-point of its range), `region ratio` = median DTE
in the single-pair zone / median DTE in the double-pair zone (the thesis, on Fig. 23 that it
likens Figs 27-28 to: single-contact deflections "almost double" the double-contact ones).

Usage: vasileiou.py <gearfem> <out dir> <figure.png> <case file>...   (writes <out>/vasileiou.csv)
"""
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from thesis_runs import entry, read_prm, run, variant  # noqa: E402


def response(folder):
    with open(os.path.join(folder, "response.csv")) as f:
        rows = [[float(v) for v in r] for r in list(csv.reader(f))[1:] if r]
    return np.array(rows)


def main():
    gearfem, out, png = sys.argv[1:4]
    cases = sys.argv[4:]
    rows, data = [], []
    for path in cases:
        name = os.path.basename(path)[:-4]
        base = read_prm(path)
        z1 = int(entry(base, "Pinion teeth"))
        pitch = 360.0 / z1
        fig, _ = run(gearfem, base, os.path.join(out, "vasileiou", name))
        qs, _ = run(gearfem, variant(base, speed=100, steps=4096, periods=60), os.path.join(out, "vasileiou", name + "_quasistatic"))
        r = response(os.path.join(out, "vasileiou", name))
        s = response(os.path.join(out, "vasileiou", name + "_quasistatic"))
        # static DTE against mesh position within the pitch (same position origin in both runs)
        ps, ds = np.mod(s[:, 1], pitch), s[:, 2]
        order = np.argsort(ps)
        ps, ds = ps[order], ds[order]
        mid = 0.5 * (ds.min() + ds.max())
        static_at = np.interp(np.mod(r[:, 1], pitch), ps, ds, period=pitch)
        single = static_at > mid
        d_single, d_double = r[single, 2], r[~single, 2]
        ratio = float(np.median(d_single) / np.median(d_double))
        rows.append({"case": name, "loss": fig["loss"], "back": fig["back"], "period": fig["period"],
                     "settled": fig["settled"], "rms [um]": fig["rms"], "fmesh [Hz]": fig["fmesh"],
                     "fn [Hz]": fig["fn"], "single-pair time fraction": float(single.mean()),
                     "median DTE single [um]": float(np.median(d_single)),
                     "median DTE double [um]": float(np.median(d_double)),
                     "region ratio": ratio, "static DTE ratio": float(ds.max() / ds.min())})
        data.append((name, r, single, fig))
        print(f"{name}: loss {fig['loss']:g}, period {fig['period']:g}, RMS {fig['rms']:.4g} um, "
              f"median DTE single/double {np.median(d_single):.3f}/{np.median(d_double):.3f} um, "
              f"ratio {ratio:.3f}")
    with open(os.path.join(out, "vasileiou.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0]))
        w.writeheader()
        w.writerows(rows)
    fig, axes = plt.subplots(1, len(data), figsize=(5.2 * len(data), 4.2))
    for ax, (name, r, single, f) in zip(np.atleast_1d(axes), data):
        ax.plot(r[:, 2], r[:, 3], "-", color="0.6", lw=0.6)
        ax.plot(r[single, 2], r[single, 3], ".", ms=2.5, color="tab:red", label="single-pair zone")
        ax.plot(r[~single, 2], r[~single, 3], ".", ms=2.5, color="tab:blue", label="double-pair zone")
        ax.set_xlabel("DTE x [um]")
        ax.set_ylabel("dx/dt [mm/s]")
        ax.set_title(f"{name}\ncontact loss {f['loss']:g}, period {f['period']:g}", fontsize=9)
        ax.grid(True, alpha=0.3)
        ax.legend(fontsize=8)
    fig.suptitle("Gkimisis 2019 Figs 27-28 pair (32/32 m2 b20, speed source): phase portraits, "
                 "analytical table", fontsize=10)
    fig.tight_layout()
    tmp = os.path.join(os.path.dirname(os.path.abspath(png)), ".tmp_" + os.path.basename(png))
    fig.savefig(tmp, dpi=110)
    os.replace(tmp, png)


if __name__ == "__main__":
    main()
