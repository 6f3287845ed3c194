#!/usr/bin/python3
"""Plots of a `gearfem solve` run: ste.png, stiffness.png, load_sharing.png, pressure.png and
root_stress.png.

Usage: MPLBACKEND=Agg /usr/bin/python3 scripts/plot_solve.py <output folder> [title]
Reads sweep.csv (required), pairs.csv, pressure.csv and line_of_action.csv (optional) from
the output folder; the columns are documented in docs/output-format.md and are found by
their header name (the " [unit]" suffix stripped), not by position. Every PNG is written to a
temporary name in the same folder and renamed into place. Exits with status 1 and a one-line
message on stderr when sweep.csv is missing or unreadable.
"""
import csv
import math
import os
import re
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.lines import Line2D  # noqa: E402

POINTS = {1: "A", 2: "B", 3: "C", 4: "D", 5: "E"}
UNIT = re.compile(r"\s*\[[^\]]*\]\s*$")


class Table:
    """A CSV with a "name [unit]" header: columns by name (unit stripped) as float arrays."""

    def __init__(self, path):
        with open(path, newline="") as f:
            rows = [r for r in csv.reader(f) if r and any(v.strip() for v in r)]
        if not rows:
            raise ValueError("empty file (no header)")
        self.header = [h.strip() for h in rows[0]]
        self.names = [UNIT.sub("", h) for h in self.header]
        data = [[_number(v) for v in r] for r in rows[1:]]
        width = len(self.header)
        data = [(r + [math.nan] * width)[:width] for r in data]
        self.values = np.array(data, dtype=float).reshape(len(data), width)
        self.n = len(data)

    def index(self, name):
        """Column index of `name`: exact match first, then a header starting with it."""
        if name in self.names:
            return self.names.index(name)
        for i, n in enumerate(self.names):
            if n.startswith(name):
                return i
        return None

    def has(self, *names):
        return all(self.index(n) is not None for n in names)

    def __getitem__(self, name):
        i = self.index(name)
        if i is None:
            raise KeyError(name)
        return self.values[:, i]

    def label(self, name):
        i = self.index(name)
        return self.header[i] if i is not None else name

    def subset(self, mask):
        t = Table.__new__(Table)
        t.header, t.names = self.header, self.names
        t.values = self.values[mask]
        t.n = len(t.values)
        return t


def _number(v):
    try:
        return float(v)
    except ValueError:
        return math.nan


def read_optional(path):
    if not os.path.exists(path):
        return None
    try:
        return Table(path)
    except (OSError, ValueError) as e:
        print(f"plot_solve.py: {path}: skipped ({e})", file=sys.stderr)
        return None


def save(fig, path):
    tmp = os.path.join(os.path.dirname(path), "." + os.path.basename(path) + ".tmp.png")
    fig.savefig(tmp, dpi=120, bbox_inches="tight")
    plt.close(fig)
    os.replace(tmp, path)


def torques(table):
    if table is None or table.n == 0 or not table.has("torque"):
        return []
    return sorted(set(float(t) for t in table["torque"] if np.isfinite(t)))


def same(a, b):
    return np.isclose(a, b, rtol=1e-9, atol=1e-12)


def torque_label(t):
    return f"T = {t:g} N m"


def colours(n):
    cycle = plt.rcParams["axes.prop_cycle"].by_key().get("color", ["C0"])
    return [cycle[i % len(cycle)] for i in range(max(n, 1))]


def by_torque(sweep, t, *names):
    """Rows of torque t sorted by roll angle: one array per name."""
    rows = sweep.subset(same(sweep["torque"], t))
    order = np.argsort(rows["roll angle"], kind="stable")
    return [rows[n][order] for n in names]


def style(n):
    # A single point would not show as a line.
    return "o-" if n == 1 else "-"


def point_lines(ax, loa, labels=True):
    """Dashed vertical lines at the points A..E, labelled at the top of the axes."""
    if loa is None or loa.n == 0 or not loa.has("point", "roll angle"):
        return
    for p, x in zip(loa["point"], loa["roll angle"]):
        if not np.isfinite(x) or int(round(p)) not in POINTS:
            continue
        ax.axvline(x, color="gray", ls="--", lw=0.7, zorder=0)
        if labels:
            ax.text(x, 1.01, POINTS[int(round(p))], transform=ax.get_xaxis_transform(),
                    ha="center", va="bottom", fontsize=9, color="dimgray")


def point_angle(loa, sweep, point):
    """Roll angle of a point from line_of_action.csv, else from sweep.csv's point column."""
    for table in (loa, sweep):
        if table is not None and table.n and table.has("point", "roll angle"):
            rows = table["roll angle"][np.rint(table["point"]) == point]
            if len(rows):
                return float(rows[0])
    return 0.0 if point == 3 else None  # roll angle 0 is C by definition


def mesh_pitch(loa, sweep):
    """Angular pitch of the pinion [deg]: D - A (one base pitch along the line of action)."""
    a, dd = point_angle(loa, sweep, 1), point_angle(loa, sweep, 4)
    return dd - a if a is not None and dd is not None and dd > a else None


def plot_ste(d, title, sweep, loa, ts):
    """STE over the computed roll angles (solid), and, when they span one mesh pitch, its
    periodic continuation over A-E (dashed: STE repeats with the pinion's angular pitch)."""
    fig, ax = plt.subplots(figsize=(8, 4.5))
    pitch = mesh_pitch(loa, sweep)
    a, e = point_angle(loa, sweep, 1), point_angle(loa, sweep, 5)
    lo_all, hi_all = [], []
    for t, c in zip(ts, colours(len(ts))):
        x, y = by_torque(sweep, t, "roll angle", "STE")
        ax.plot(x, y, style(len(x)), color=c, ms=4, label=torque_label(t))
        lo_all.append(x.min())
        hi_all.append(x.max())
        span = x.max() - x.min() if len(x) > 1 else 0
        if pitch and a is not None and e is not None and len(x) > 2 and span >= 0.9 * pitch:
            # One pitch computed: repeat it over A-E, beside the computed range.
            step = span / (len(x) - 1)
            if span + step >= 0.999 * pitch:
                for k in range(-3, 4):
                    if k == 0:
                        continue
                    xs = x + k * pitch
                    m = (xs >= a - 1e-9) & (xs <= e + 1e-9)
                    if np.any(m):
                        ax.plot(xs[m], y[m], "--", color=c, lw=0.9, alpha=0.6)
                lo_all[-1], hi_all[-1] = min(a, x.min()), max(e, x.max())
    point_lines(ax, loa)
    if lo_all:
        pad = 0.02 * (max(hi_all) - min(lo_all) or 1)
        ax.set_xlim(min(lo_all) - pad, max(hi_all) + pad)
    if pitch:
        ax.plot([], [], "k--", lw=0.9, alpha=0.6, label="periodic continuation (one pitch computed)")
    ax.set_xlabel(sweep.label("roll angle"))
    ax.set_ylabel(sweep.label("STE"))
    ax.set_title(title + ": static transmission error", pad=16)
    if ts:
        ax.legend(fontsize=8)
    ax.grid(True, alpha=0.3)
    save(fig, os.path.join(d, "ste.png"))


def plot_stiffness(d, title, sweep, loa, ts):
    fig, ax = plt.subplots(figsize=(8, 4.5))
    handles = []
    for t, c in zip(ts, colours(len(ts))):
        x, ks, kt = by_torque(sweep, t, "roll angle", "k_secant per width",
                              "k_tangent per width")
        st = style(len(x))
        ax.plot(x, ks, st, color=c, ms=4)
        ax.plot(x, kt, st.replace("-", "--"), color=c, ms=4)
        handles.append(Line2D([], [], color=c, label=torque_label(t)))
    handles += [Line2D([], [], color="k", ls="-", label="secant"),
                Line2D([], [], color="k", ls="--", label="tangent")]
    point_lines(ax, loa)
    ax.set_xlabel(sweep.label("roll angle"))
    ax.set_ylabel("mesh stiffness per face width [N/(mm um)]")
    ax.set_title(title + ": mesh stiffness", pad=16)
    ax.legend(handles=handles, fontsize=8)
    ax.grid(True, alpha=0.3)
    save(fig, os.path.join(d, "stiffness.png"))


def plot_load_sharing(d, title, sweep, pairs, loa, ts):
    fig, (a1, a2) = plt.subplots(2, 1, figsize=(8, 6.5), sharex=True,
                                 gridspec_kw={"height_ratios": [3, 1]})
    markers = "os^vD<>px*h"
    cols = colours(len(ts))
    have_pairs = (pairs is not None and pairs.n > 0
                  and pairs.has("torque", "roll angle", "pinion tooth", "load share"))
    if have_pairs:
        extra = [t for t in torques(pairs) if not np.any(same(np.array(ts), t))]
        for t, c in zip(ts + extra, colours(len(ts) + len(extra))):
            rows = pairs.subset(same(pairs["torque"], t))
            teeth = sorted(set(int(round(v)) for v in rows["pinion tooth"]))
            for j, tooth in enumerate(teeth):
                r = rows.subset(np.rint(rows["pinion tooth"]) == tooth)
                order = np.argsort(r["roll angle"], kind="stable")
                a1.plot(r["roll angle"][order], r["load share"][order],
                        "-" + markers[j % len(markers)], color=c, ms=4, lw=1,
                        label=f"{torque_label(t)}, pinion tooth {tooth}")
        a1.legend(fontsize=7, ncol=2)
    else:
        a1.text(0.5, 0.5, "no pairs.csv rows", transform=a1.transAxes, ha="center")
    a1.set_ylabel(pairs.label("load share") if have_pairs else "load share [-]")
    a1.set_ylim(-0.05, 1.05)
    a1.set_title(title + ": load sharing", pad=16)
    a1.grid(True, alpha=0.3)
    point_lines(a1, loa)
    if sweep.has("pairs in contact"):
        for t, c in zip(ts, cols):
            x, n = by_torque(sweep, t, "roll angle", "pairs in contact")
            a2.step(x, n, where="mid", color=c, label=torque_label(t))
            if len(x) == 1:
                a2.plot(x, n, "o", color=c)
        a2.set_ylabel("pairs in contact")
        a2.yaxis.get_major_locator().set_params(integer=True)
    a2.set_xlabel(sweep.label("roll angle"))
    a2.grid(True, alpha=0.3)
    point_lines(a2, loa, labels=False)
    save(fig, os.path.join(d, "load_sharing.png"))


def plot_pressure(d, title, sweep, pairs, pressure, loa, ts):
    fig, axes = plt.subplots(1, 2, figsize=(12, 4.5))
    have_p = (pressure is not None and pressure.n > 0
              and pressure.has("torque", "position", "pinion tooth", "s", "p"))
    have_hertz = (pairs is not None and pairs.n > 0
                  and pairs.has("torque", "position", "pinion tooth", "p_Hertz", "a_Hertz"))
    cols = colours(len(ts))
    for ax, point in zip(axes, (3, 4)):
        name = POINTS[point]
        target = point_angle(loa, sweep, point)
        # A point beyond the computed roll angles is the same mesh state one pitch earlier
        # (D = A + pitch): use that position.
        pitch = mesh_pitch(loa, sweep)
        original = target
        if target is not None and pitch and sweep.n:
            lo, hi = np.nanmin(sweep["roll angle"]), np.nanmax(sweep["roll angle"])
            while target > hi + 1e-9 and target - pitch >= lo - 1e-9:
                target -= pitch
            while target < lo - 1e-9 and target + pitch <= hi + 1e-9:
                target += pitch
        ax.set_xlabel(pressure.label("s") if have_p else "s [mm]")
        ax.set_ylabel(pressure.label("p") if have_p else "p [MPa]")
        ax.grid(True, alpha=0.3)
        if target is None:
            ax.set_title(f"nearest {name}: roll angle of {name} unknown")
            continue
        angles, plotted = [], False
        for t, c in zip(ts, cols):
            # Nearest position of this torque that has pressure samples.
            if not have_p:
                break
            rows = pressure.subset(same(pressure["torque"], t))
            if rows.n == 0:
                continue
            positions = sorted(set(int(round(v)) for v in rows["position"]))
            sw = sweep.subset(same(sweep["torque"], t))
            roll = {}
            for pos in positions:
                m = np.rint(sw["position"]) == pos
                if np.any(m):
                    roll[pos] = float(sw["roll angle"][m][0])
                elif rows.has("roll angle"):
                    roll[pos] = float(rows["roll angle"][np.rint(rows["position"]) == pos][0])
            if not roll:
                continue
            pos = min(roll, key=lambda q: abs(roll[q] - target))
            angles.append(roll[pos])
            at = rows.subset(np.rint(rows["position"]) == pos)
            teeth = sorted(set(int(round(v)) for v in at["pinion tooth"]))
            for j, tooth in enumerate(teeth):
                r = at.subset(np.rint(at["pinion tooth"]) == tooth)
                if not np.any(r["p"] > 0):
                    continue
                order = np.argsort(r["s"], kind="stable")
                ls = ["-", "-.", (0, (5, 1)), (0, (3, 1, 1, 1))][j % 4]
                edge = False
                if pairs is not None and pairs.has("edge contact"):
                    e_rows = pairs.subset(same(pairs["torque"], t) & (np.rint(pairs["position"]) == pos)
                                          & (np.rint(pairs["pinion tooth"]) == tooth))
                    edge = bool(e_rows.n and e_rows["edge contact"][0] > 0.5)
                ax.plot(r["s"][order], r["p"][order], ls=ls, color=c, lw=1.2, marker=".", ms=4,
                        label=f"{torque_label(t)}, tooth {tooth} ({roll[pos]:.2f} deg)"
                        + (", tip-edge contact (not Hertzian)" if edge else ""))
                plotted = True
                if have_hertz:
                    h = pairs.subset(same(pairs["torque"], t)
                                     & (np.rint(pairs["position"]) == pos)
                                     & (np.rint(pairs["pinion tooth"]) == tooth))
                    if h.n and np.isfinite(h["a_Hertz"][0]) and h["a_Hertz"][0] > 0:
                        a, p0 = float(h["a_Hertz"][0]), float(h["p_Hertz"][0])
                        s = np.linspace(-a, a, 201)
                        ax.plot(s, p0 * np.sqrt(np.clip(1 - (s / a) ** 2, 0, None)), ":",
                                color=c, lw=1.2)
        where = ", ".join(dict.fromkeys(f"{a:.2f}" for a in angles))
        shifted = "" if abs(target - original) < 1e-9 else f", periodic image of {original:.2f} deg"
        ax.set_title(f"nearest {name} ({target:.2f} deg{shifted}): roll angle {where} deg"
                     if angles else f"nearest {name} ({target:.2f} deg{shifted})", fontsize=10)
        if plotted:
            handles, labels = ax.get_legend_handles_labels()
            if have_hertz:
                handles.append(Line2D([], [], color="k", ls=":", label="Hertz ellipse"))
            ax.legend(handles=handles, fontsize=7)
        else:
            ax.text(0.5, 0.5, "no pressure samples", transform=ax.transAxes, ha="center")
    fig.suptitle(title + ": contact pressure along the flank")
    save(fig, os.path.join(d, "pressure.png"))


def plot_root_stress(d, title, sweep, loa, ts):
    fig, ax = plt.subplots(figsize=(8, 4.5))
    handles = []
    for t, c in zip(ts, colours(len(ts))):
        x, s1, s2 = by_torque(sweep, t, "roll angle", "root stress pinion", "root stress gear")
        st = style(len(x))
        ax.plot(x, s1, st, color=c, ms=4)
        ax.plot(x, s2, st.replace("-", "--"), color=c, ms=4)
        handles.append(Line2D([], [], color=c, label=torque_label(t)))
    handles += [Line2D([], [], color="k", ls="-", label="pinion"),
                Line2D([], [], color="k", ls="--", label="gear")]
    point_lines(ax, loa)
    ax.set_xlabel(sweep.label("roll angle"))
    ax.set_ylabel("max root stress [MPa]")
    ax.set_title(title + ": tooth root stress", pad=16)
    ax.legend(handles=handles, fontsize=8)
    ax.grid(True, alpha=0.3)
    save(fig, os.path.join(d, "root_stress.png"))


def plot_friction(d, title, sweep, pairs, loa, ts):
    """Friction force per tooth pair (on the pinion, + towards its tip) and the mesh power loss."""
    fig, (ax1, ax2) = plt.subplots(2, 1, figsize=(8, 7), sharex=True)
    for t, c in zip(ts, colours(len(ts))):
        x, p = by_torque(sweep, t, "roll angle", "power loss")
        st = style(len(x))
        ax2.plot(x, p, st, color=c, ms=4, label=torque_label(t))
        if pairs is not None and pairs.has("friction force"):
            sub = pairs.subset([same(v, t) for v in pairs["torque"]])
            for k in sorted(set(sub["pinion tooth"])):
                m = [same(v, k) for v in sub["pinion tooth"]]
                xs = [a for a, keep in zip(sub["roll angle"], m) if keep]
                fs = [a for a, keep in zip(sub["friction force"], m) if keep]
                ax1.plot(xs, fs, st, color=c, ms=3)
    for ax in (ax1, ax2):
        point_lines(ax, loa, labels=ax is ax1)
        ax.grid(True, alpha=0.3)
    ax1.axhline(0, color="k", lw=0.6)
    ax1.set_ylabel("friction force on the pinion,\n+ towards its tip [N]")
    ax2.set_ylabel("mesh power loss [W]")
    ax2.set_xlabel(sweep.label("roll angle"))
    ax2.legend(fontsize=8)
    ax1.set_title(title + ": friction force per tooth pair and mesh power loss", pad=16)
    save(fig, os.path.join(d, "friction.png"))


def main():
    if len(sys.argv) < 2:
        print("usage: plot_solve.py <output folder> [title]", file=sys.stderr)
        return 2
    d = sys.argv[1]
    title = sys.argv[2] if len(sys.argv) > 2 else os.path.basename(os.path.abspath(d))
    path = os.path.join(d, "sweep.csv")
    if not os.path.exists(path):
        print(f"plot_solve.py: {path}: not found (run `gearfem solve` first)", file=sys.stderr)
        return 1
    try:
        sweep = Table(path)
    except (OSError, ValueError) as e:
        print(f"plot_solve.py: {path}: {e}", file=sys.stderr)
        return 1
    missing = [n for n in ("torque", "position", "roll angle") if not sweep.has(n)]
    if missing:
        print(f"plot_solve.py: {path}: no column {', '.join(missing)}", file=sys.stderr)
        return 1
    pairs = read_optional(os.path.join(d, "pairs.csv"))
    pressure = read_optional(os.path.join(d, "pressure.csv"))
    loa = read_optional(os.path.join(d, "line_of_action.csv"))
    ts = torques(sweep)

    plots = [
        ("ste.png", ("STE",), lambda: plot_ste(d, title, sweep, loa, ts)),
        ("stiffness.png", ("k_secant per width", "k_tangent per width"),
         lambda: plot_stiffness(d, title, sweep, loa, ts)),
        ("load_sharing.png", (), lambda: plot_load_sharing(d, title, sweep, pairs, loa, ts)),
        ("pressure.png", (), lambda: plot_pressure(d, title, sweep, pairs, pressure, loa, ts)),
        ("root_stress.png", ("root stress pinion", "root stress gear"),
         lambda: plot_root_stress(d, title, sweep, loa, ts)),
    ]
    if sweep.has("power loss") and max(abs(v) for v in sweep["power loss"]) > 0:
        plots.append(("friction.png", ("power loss",),
                      lambda: plot_friction(d, title, sweep, pairs, loa, ts)))
    for name, needs, plot in plots:
        absent = [n for n in needs if not sweep.has(n)]
        if absent:
            print(f"plot_solve.py: {name} skipped: sweep.csv has no column "
                  f"{', '.join(absent)}", file=sys.stderr)
            continue
        plot()
    return 0


if __name__ == "__main__":
    sys.exit(main())
