#!/usr/bin/python3
"""Checks of the Harris-map study (README.md) on a `gearfem batch` output folder of
inputs/harris_map.prm, against references that do not come from the run itself:

1. Harris (1958), Tavakoli & Houser (1986): each *long* relief (tip to the start of single
   contact, both gears) has an interior minimum of the peak-to-peak STE over torque, and the
   torque of that minimum grows with the relief amount.
2. The batch-study requirement's figure for the unrelieved pair with 25 mm bores:
   peak-to-peak STE about 4.85 um at 340 N m (within 5 %).
3. The load-sharing argument for the *short* relief (tip to the middle of the double-contact
   zone on both gears): with equal pair stiffnesses k, at any position of the double zone one
   pair carries a relief r in [0, C_a] and the other none, so the STE there is
   (F/k + r)/2 where both touch and F/k where only one does; its minimum F/(2k) sits at the
   middle of the zone, where r = 0, whatever C_a. The peak-to-peak STE is therefore F/(2k),
   that of the unrelieved pair, at every load: a short linear relief has no torque of
   minimum peak-to-peak STE. Checked up to 241 N m (before the unrelieved pair's loaded
   contact extends beyond the theoretical path): each short relief's peak-to-peak STE grows
   with torque (no minimum there, unlike the long reliefs) and stays within 15 % of the
   unrelieved one. The 15 % is the idealisation's error, not a fit: the pair stiffness is not
   constant along the path (the unrelieved double-zone STE alone varies by 0.24-0.92 um at
   20-83 N m, up to 60 % of its peak-to-peak). What the short relief changes is the shape:
   the double-zone dip becomes a V, and the first mesh harmonic of the STE drops below the
   unrelieved one at light load (checked at 20 N m).
4. With --exact DIR (the same study on Contact/Micro-geometry = geometry, i.e. the relieved
   profiles meshed): at and above the design load (torques >= 240 N m; the micro-geometry
   tolerances are stated at the design load) the gap route agrees per design and torque,
   mean STE within 0.5 %, peak-to-peak STE within 0.5 % of the mean STE, root stresses
   within 1 %. Below it
   the worst differences over the map are printed (information: the mean STE there is only
   1-4 um, and the exact route's relieved profiles are other meshes).

Writes harris_map_h1.png (first mesh harmonic against torque) into the folder and ends with
`harris_map: PASS` or `harris_map: FAIL`.

    MPLBACKEND=Agg /usr/bin/python3 validation/harris_map/check.py OUT [--exact DIR]
"""
import argparse
import csv
import os
import sys

import numpy as np


def sweeps(folder):
    """{design id: {torque: (STE array over one pitch, root pinion max, root gear max)}}"""
    out = {}
    jobs = os.path.join(folder, "jobs")
    for d in sorted(os.listdir(jobs)):
        f = os.path.join(jobs, d, "sweep.csv")
        if not os.path.exists(f):
            continue
        r = list(csv.reader(open(f)))
        h, rows = r[0], r[1:]
        it, ist = h.index("torque [N m]"), h.index("STE [um]")
        rp, rg = h.index("root stress pinion [MPa]"), h.index("root stress gear [MPa]")
        per = {}
        for T in sorted({float(x[it]) for x in rows}):
            sel = [x for x in rows if float(x[it]) == T]
            per[T] = (np.array([float(x[ist]) for x in sel]), max(float(x[rp]) for x in sel),
                      max(float(x[rg]) for x in sel))
        out[d] = per
    return out


def h1(ste):
    """Amplitude of the first mesh harmonic of STE sampled over one base pitch [um]."""
    return 2 * abs(np.fft.rfft(ste)[1]) / len(ste)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("folder")
    ap.add_argument("--exact", help="the same study on the exact (re-meshed) route")
    a = ap.parse_args()
    s = sweeps(a.folder)
    fails = []

    def check(ok, what):
        print(("ok   " if ok else "FAIL ") + what)
        if not ok:
            fails.append(what)

    need = ["none"] + [f"{k}_{c:02d}" for k in ("long", "short") for c in (3, 6, 9, 12, 15)]
    missing = [d for d in need if d not in s]
    check(not missing, f"all 11 designs have a sweep (missing: {missing})")
    if missing:
        print("harris_map: FAIL")
        return 1
    torques = sorted(s["none"])
    pp = {d: np.array([np.ptp(s[d][T][0]) for T in torques]) for d in need}
    a1 = {d: np.array([h1(s[d][T][0]) for T in torques]) for d in need}

    print("| relief | C_a [um] | torque at min p-p STE [N m] | min p-p [um] | interior |")
    print("|---|---|---|---|---|")
    t_min = []
    for c in (3, 6, 9, 12, 15):
        d = f"long_{c:02d}"
        k = int(np.argmin(pp[d]))
        interior = 0 < k < len(torques) - 1
        t_min.append(torques[k])
        print(f"| long | {c} | {torques[k]:g} | {pp[d][k]:.3f} | {'yes' if interior else 'no'} |")
        check(interior, f"{d}: the minimum of p-p STE lies inside the map (Harris 1958)")
    check(all(x < y for x, y in zip(t_min, t_min[1:])),
          f"long reliefs: torque of the minimum grows with C_a: {t_min} (Tavakoli & Houser 1986)")

    T340 = min(torques, key=lambda T: abs(T - 340))
    p340 = pp["none"][torques.index(T340)]
    check(abs(p340 / 4.85 - 1) < 0.05,
          f"no relief at {T340:g} N m: p-p STE {p340:.3f} um against ~4.85 um (batch-study requirement)")

    light = [j for j, T in enumerate(torques) if T <= 241]
    for c in (3, 6, 9, 12, 15):
        d = f"short_{c:02d}"
        dev = max(abs(pp[d][j] / pp["none"][j] - 1) for j in light)
        check(dev <= 0.15, f"{d}: p-p STE equals the unrelieved one up to 241 N m within 15 % "
                           f"(load sharing: F/(2k) whatever C_a); worst {100 * dev:.1f} %")
        check(all(pp[d][j] < pp[d][j + 1] for j in light[:-1]),
              f"{d}: p-p STE grows with torque up to 241 N m (no minimum: load sharing)")
        check(a1[d][0] < a1["none"][0],
              f"{d}: first mesh harmonic at {torques[0]:g} N m {a1[d][0]:.3f} um below the unrelieved {a1['none'][0]:.3f} um")

    if a.exact:
        e = sweeps(a.exact)
        worst = {True: [0.0] * 4, False: [0.0] * 4}  # design load and above / below
        for d in need:
            for T in torques:
                g, x = s[d][T], e[d][T]
                m, w = x[0].mean(), worst[T >= 240]
                w[0] = max(w[0], abs(g[0].mean() / m - 1))
                w[1] = max(w[1], abs(np.ptp(g[0]) - np.ptp(x[0])) / m)
                w[2] = max(w[2], abs(g[1] / x[1] - 1), abs(g[2] / x[2] - 1))
                w[3] = max(w[3], abs(np.ptp(g[0]) - np.ptp(x[0])))
        w = worst[True]
        n = sum(T >= 240 for T in torques)
        check(w[0] < 5e-3, f"gap against exact route, 11 designs x {n} torques >= 240 N m: mean STE {100 * w[0]:.3f} % (limit 0.5 %)")
        check(w[1] < 5e-3, f"gap against exact route, >= 240 N m: p-p STE {100 * w[1]:.3f} % of the mean STE (limit 0.5 %)")
        check(w[2] < 1e-2, f"gap against exact route, >= 240 N m: max root stress {100 * w[2]:.3f} % (limit 1 %)")
        w = worst[False]
        print(f"info gap against exact route below 240 N m: mean STE {100 * w[0]:.3f} %, p-p STE {100 * w[1]:.2f} % "
              f"of the mean ({w[3]:.3f} um), root stress {100 * w[2]:.2f} %")

    try:
        import matplotlib.pyplot as plt
        fig, ax = plt.subplots(figsize=(8, 5))
        for d in need:
            style = "-" if d.startswith("long") else "--" if d.startswith("short") else "k-"
            ax.semilogx(torques, a1[d], style, marker="o", ms=3, label=d)
        ax.set_xlabel("pinion torque [N m]")
        ax.set_ylabel("first mesh harmonic of STE [um]")
        ax.set_title("Harris map of the first mesh harmonic")
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=7, ncol=2)
        fig.tight_layout()
        tmp = os.path.join(a.folder, "harris_map_h1.tmp.png")
        fig.savefig(tmp, dpi=120)
        os.replace(tmp, os.path.join(a.folder, "harris_map_h1.png"))
    except ImportError:
        print("(matplotlib missing: no harris_map_h1.png)")

    print("harris_map: " + ("PASS" if not fails else f"FAIL ({len(fails)} checks)"))
    return 1 if fails else 0


if __name__ == "__main__":
    sys.exit(main())
