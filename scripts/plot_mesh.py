#!/usr/bin/python3
"""Plot gmsh MSH 4.1 (ASCII) meshes: element edges of the whole body and a zoom on the
tooth region, boundary edges coloured by physical group (see meshes/README.md).

Usage: plot_mesh.py OUT.png MESH.msh XMIN,XMAX,YMIN,YMAX [MESH2.msh BOX2 ...]
Coordinates in the .msh are metres; the plot and the zoom box are in millimetres.
The PNG is written atomically (temporary name, then os.replace).
"""
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.collections import LineCollection  # noqa: E402


def read_msh(path):
    """Return nodes {tag: (x, y)}, quads [[n0..n3]], lines [(n0, n1, physical)]."""
    with open(path) as f:
        lines = [l.strip() for l in f]
    i = 0
    nodes, quads, blines = {}, [], []
    curve_phys = {}
    while i < len(lines):
        s = lines[i]
        if s == "$Entities":
            npt, ncu, nsu, nvo = map(int, lines[i + 1].split())
            i += 2 + npt
            for k in range(ncu):
                t = lines[i + k].split()
                tag, nphys = int(t[0]), int(t[7])
                curve_phys[tag] = int(t[8]) if nphys > 0 else 0
            i += ncu + nsu + nvo
            continue
        if s == "$Nodes":
            nblocks = int(lines[i + 1].split()[0])
            i += 2
            for _ in range(nblocks):
                dim, tag, param, n = map(int, lines[i].split())
                tags = [int(lines[i + 1 + k]) for k in range(n)]
                for k in range(n):
                    c = lines[i + 1 + n + k].split()
                    nodes[tags[k]] = (float(c[0]) * 1e3, float(c[1]) * 1e3)
                i += 1 + 2 * n
            continue
        if s == "$Elements":
            nblocks = int(lines[i + 1].split()[0])
            i += 2
            for _ in range(nblocks):
                dim, tag, etype, n = map(int, lines[i].split())
                for k in range(n):
                    v = list(map(int, lines[i + 1 + k].split()))[1:]
                    if etype == 3:
                        quads.append(v[:4])
                    elif etype == 1:
                        blines.append((v[0], v[1], curve_phys.get(tag, 0)))
                i += 1 + n
            continue
        i += 1
    return nodes, quads, blines


COLOURS = {1: "tab:red", 2: "tab:orange", 3: "tab:blue", 4: "tab:cyan", 5: "tab:green",
           6: "tab:olive", 7: "tab:olive", 8: "tab:purple", 9: "tab:purple"}


def boundary_colour(pid):
    if pid >= 1000:
        return COLOURS.get(pid % 1000, "k")
    return {1: "k", 2: "tab:brown", 3: "tab:brown"}.get(pid, "k")


def draw(ax, nodes, quads, blines, box=None):
    segs = []
    for q in quads:
        for a, b in zip(q, q[1:] + q[:1]):
            segs.append((nodes[a], nodes[b]))
    ax.add_collection(LineCollection(segs, colors="0.55", linewidths=0.25))
    bsegs = [(nodes[a], nodes[b]) for a, b, _ in blines]
    cols = [boundary_colour(p) for _, _, p in blines]
    ax.add_collection(LineCollection(bsegs, colors=cols, linewidths=1.0))
    ax.set_aspect("equal")
    if box:
        ax.set_xlim(box[0], box[1])
        ax.set_ylim(box[2], box[3])
    else:
        xs = [p[0] for p in nodes.values()]
        ys = [p[1] for p in nodes.values()]
        ax.set_xlim(min(xs), max(xs))
        ax.set_ylim(min(ys), max(ys))
    ax.set_xlabel("x [mm]")
    ax.set_ylabel("y [mm]")


def main(argv):
    out = argv[1]
    pairs = [(argv[k], [float(v) for v in argv[k + 1].split(",")]) for k in range(2, len(argv), 2)]
    fig, axes = plt.subplots(len(pairs), 2, figsize=(12, 5.5 * len(pairs)), squeeze=False)
    for row, (path, box) in enumerate(pairs):
        nodes, quads, blines = read_msh(path)
        name = os.path.basename(path)
        draw(axes[row][0], nodes, quads, blines)
        axes[row][0].set_title(f"{name}: {len(quads)} quadrilaterals")
        draw(axes[row][1], nodes, quads, blines, box)
        axes[row][1].set_title(f"{name}: teeth (flank red/orange, fillet blue/cyan, tip green)", fontsize=9)
    fig.tight_layout()
    tmp = out + ".tmp.png"
    fig.savefig(tmp, dpi=130)
    os.replace(tmp, out)


if __name__ == "__main__":
    main(sys.argv)
