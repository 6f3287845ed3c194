"""CalculiX (ccx) model of a spur pair at one mesh position, built from gearfem's own meshes.

- reads gear1.msh / gear2.msh of `gearfem mesh` (MSH 4.1 ASCII, metres, body frames,
  physical groups = boundary ids of meshes/README.md);
- turns the bilinear quads into CPS8 (plane stress, face width as thickness): interior
  mid-side nodes at the chord midpoint, boundary mid-side nodes on a chord-length cubic
  through the neighbouring boundary vertices of the same curve (gearfem snaps the vertices
  onto the exact curves; its Q2 mapping puts the mid-nodes on them as well);
- places both gears as gearfem does (geometry::GearPair::placement, docs/contact.md):
  pinion at O1 = (0, 0) turned by phase1 + phi1, gear at O2 = (0, a) turned by
  phase2 - phi1/u, drive flanks touching without load;
- one surface-to-surface contact pair per tooth pair in mesh (penalty, linear
  pressure-overclosure with slope K [N/mm^3]), frictionless; the slave is the body whose tip
  is nearer the contact (the owner of a tip corner within reach, as in gearfem's per-zone
  rule), the master surface includes the mate's tip land and fillet;
- gear 2 bore clamped; the pinion bore turned rigidly by dtheta about O1 (prescribed
  displacements u = dtheta (-y, x) of every bore node: small rotation, no NLGEOM), one
  *STEP per rotation;
- reads back the .dat (bore reactions -> T1, per-pair contact force and moment) and the
  .frd (nodal stresses on the drive fillets -> peak sigma_1 per tooth).

Units in the ccx deck: mm, N, MPa.
"""
import csv
import math
import os
import re
import subprocess
import sys
import time

import numpy as np

DRIVE_FLANK, FILLET_DRIVE, TIP = 1, 3, 5


# --------------------------------------------------------------------------- geometry
def inv(a):
    return math.tan(a) - a


def pair_geometry(z1, z2, m, x1, x2, alpha_deg=20.0):
    """Zero-backlash involute pair as in lib/geometry/pair.cc: working pressure angle, centre
    distance, working pitch radii and the body phases at phi1 = 0 [mm, rad]."""
    al = math.radians(alpha_deg)
    r01, r02 = m * z1 / 2, m * z2 / 2
    rb1, rb2 = r01 * math.cos(al), r02 * math.cos(al)
    s1 = math.pi * m / 2 + 2 * x1 * m * math.tan(al)
    s2 = math.pi * m / 2 + 2 * x2 * m * math.tan(al)
    inv_w = inv(al) + (s1 + s2 - math.pi * m) / (m * (z1 + z2))
    lo, hi = 1e-6, 1.5  # inv^-1 by bisection
    for _ in range(200):
        mid = (lo + hi) / 2
        lo, hi = (mid, hi) if inv(mid) < inv_w else (lo, mid)
    aw = (lo + hi) / 2
    a = (rb1 + rb2) / math.cos(aw)
    rw1, rw2 = rb1 / math.cos(aw), rb2 / math.cos(aw)
    sw1 = 2 * rw1 * (s1 / (2 * r01) + inv(al) - inv(aw))
    sw2 = 2 * rw2 * (s2 / (2 * r02) + inv(al) - inv(aw))
    return dict(a=a, alpha_w=aw, rb1=rb1, rb2=rb2, phase1=-sw1 / (2 * rw1),
                phase2=math.pi - sw2 / (2 * rw2), u=z2 / z1, z1=z1, z2=z2)


def rot(xy, ang):
    c, s = math.cos(ang), math.sin(ang)
    return np.column_stack([c * xy[:, 0] - s * xy[:, 1], s * xy[:, 0] + c * xy[:, 1]])


# --------------------------------------------------------------------------- mesh
class Body:
    """One gear in its body frame [mm]: CPS8 elements and boundary edges by physical group."""

    def __init__(self, msh_path):
        nodes, quads, lines = read_msh41(msh_path)
        tags = np.array(sorted(nodes))
        index = {t: i for i, t in enumerate(tags)}
        xy = np.array([nodes[t] for t in tags]) * 1e3
        quads = np.array([[index[t] for t in q] for q in quads])
        # orient counter-clockwise (ccx needs positive Jacobians in the x-y plane)
        p = xy[quads]
        area2 = ((p[:, 1, 0] - p[:, 0, 0]) * (p[:, 3, 1] - p[:, 0, 1]) -
                 (p[:, 3, 0] - p[:, 0, 0]) * (p[:, 1, 1] - p[:, 0, 1]))
        quads[area2 < 0] = quads[area2 < 0][:, ::-1]
        self.group_edges = {}  # physical tag -> list of (a, b) vertex indices
        for tag, a, b in lines:
            self.group_edges.setdefault(tag, []).append((index[a], index[b]))
        edge_group = {}
        for tag, es in self.group_edges.items():
            for a, b in es:
                edge_group[frozenset((a, b))] = tag
        mids = {}
        coords = list(map(tuple, xy))
        curved = self._curved_midpoints(xy)
        elems = []
        for q in quads:
            mid_ids = []
            for k in range(4):
                a, b = int(q[k]), int(q[(k + 1) % 4])
                key = frozenset((a, b))
                if key not in mids:
                    mids[key] = len(coords)
                    coords.append(tuple(curved.get(key, (xy[a] + xy[b]) / 2)))
                mid_ids.append(mids[key])
            elems.append([int(v) for v in q] + mid_ids)
        self.xy = np.array(coords)
        self.elems = np.array(elems)
        self.mids = mids
        # element face (1..4: edges 1-2, 2-3, 3-4, 4-1) of every boundary edge
        face_of = {}
        for e, q in enumerate(self.elems):
            for k in range(4):
                face_of[frozenset((int(q[k]), int(q[(k + 1) % 4])))] = (e, k + 1)
        self.group_faces = {tag: [face_of[frozenset(e)] for e in es] for tag, es in self.group_edges.items()}
        self.edge_group = edge_group

    def _curved_midpoints(self, xy):
        """Mid-side points of boundary edges on a chord-length cubic through the neighbouring
        vertices of the same physical group (quadratic or straight where a group is short)."""
        out = {}
        for tag, es in self.group_edges.items():
            nb = {}
            for a, b in es:
                nb.setdefault(a, []).append(b)
                nb.setdefault(b, []).append(a)
            for a, b in es:
                chain = [a, b]
                pa = [v for v in nb[a] if v != b]
                qb = [v for v in nb[b] if v != a]
                if pa:
                    chain.insert(0, pa[0])
                if qb:
                    chain.append(qb[0])
                pts = xy[chain]
                if len(pts) < 3:
                    continue
                t = np.concatenate([[0], np.cumsum(np.linalg.norm(np.diff(pts, axis=0), axis=1))])
                ia = chain.index(a)
                tm = (t[ia] + t[ia + 1]) / 2
                deg = len(pts) - 1
                m = np.array([[(tm - t[j]) for j in range(len(t))]])
                # Lagrange interpolation through all chain points at tm
                w = np.ones(len(t))
                for i in range(len(t)):
                    for j in range(len(t)):
                        if i != j:
                            w[i] *= (tm - t[j]) / (t[i] - t[j])
                del m, deg
                out[frozenset((a, b))] = w @ pts
        return out

    def teeth_with(self, segment):
        return sorted({tag // 1000 - 1 for tag in self.group_edges if tag >= 1000 and tag % 1000 == segment})

    def group_nodes(self, tag):
        """Vertex and mid-side node indices of a physical group."""
        s = set()
        for a, b in self.group_edges.get(tag, []):
            s.update((a, b, self.mids[frozenset((a, b))]))
        return sorted(s)


def read_msh41(path):
    """Nodes {tag: (x, y)}, quads [[4 tags]], boundary lines [(physical tag, a, b)] of an
    ASCII MSH 4.1 file (first-order elements)."""
    with open(path) as f:
        lines = f.read().split("\n")
    i = 0
    curve_phys, nodes, quads, blines = {}, {}, [], []
    while i < len(lines):
        s = lines[i].strip()
        if s == "$Entities":
            n_pt, n_cu, n_su, n_vo = map(int, lines[i + 1].split())
            i += 2 + n_pt
            for k in range(n_cu):
                w = lines[i + k].split()
                nphys = int(w[7])
                curve_phys[int(w[0])] = int(w[8]) if nphys else 0
            i += n_cu
            continue
        if s == "$Nodes":
            nblocks = int(lines[i + 1].split()[0])
            i += 2
            for _ in range(nblocks):
                dim, ent, par, n = map(int, lines[i].split())
                tags = [int(lines[i + 1 + k]) for k in range(n)]
                for k in range(n):
                    w = lines[i + 1 + n + k].split()
                    nodes[tags[k]] = (float(w[0]), float(w[1]))
                i += 1 + 2 * n
            continue
        if s == "$Elements":
            nblocks = int(lines[i + 1].split()[0])
            i += 2
            for _ in range(nblocks):
                dim, ent, typ, n = map(int, lines[i].split())
                for k in range(n):
                    w = list(map(int, lines[i + 1 + k].split()))
                    if typ == 3:
                        quads.append(w[1:5])
                    elif typ == 1:
                        blines.append((curve_phys.get(ent, 0), w[1], w[2]))
                    else:
                        raise ValueError(f"{path}: element type {typ} (only 4-node quads and 2-node lines)")
                i += 1 + n
            continue
        i += 1
    return nodes, quads, blines


# --------------------------------------------------------------------------- deck
def tooth_tag(k, seg):
    return 1000 * (k + 1) + seg


def placed(body, centre, angle):
    return rot(body.xy, angle) + np.asarray(centre)


def _polyline(body, x, tags):
    """Sub-segments (vertex - mid-node - vertex) of the boundary edges of the groups."""
    segs = []
    for tag in tags:
        for a, b in body.group_edges.get(tag, []):
            m = body.mids[frozenset((a, b))]
            segs += [(x[a], x[m]), (x[m], x[b])]
    return np.array(segs)


def point_segment_distance(p, segs):
    """Smallest distance from each point p (n x 2) to a set of segments (k x 2 x 2)."""
    a, b = segs[:, 0, :], segs[:, 1, :]
    ab = b - a
    t = np.clip(np.einsum("nkd,kd->nk", p[:, None, :] - a[None], ab) / np.einsum("kd,kd->k", ab, ab), 0, 1)
    q = a[None] + t[..., None] * ab[None]
    return np.linalg.norm(p[:, None, :] - q, axis=2).min(axis=1)


def mesh_pairs(g, b1, b2, x1, x2, reach=0.2):
    """Tooth pairs (pinion tooth i, gear tooth j) whose drive flanks come within `reach` mm:
    the unloaded gap [mm] (pinion flank/tip nodes to the gear flank/tip polyline), the
    radius of the closest pinion point [mm] and the closest point (pair frame) [mm]."""
    out = []
    for i in b1.teeth_with(DRIVE_FLANK):
        n1 = b1.group_nodes(tooth_tag(i, DRIVE_FLANK)) + b1.group_nodes(tooth_tag(i, TIP))
        p1 = x1[n1]
        for j in b2.teeth_with(DRIVE_FLANK):
            tags2 = [tooth_tag(j, DRIVE_FLANK), tooth_tag(j, TIP)]
            n2 = b2.group_nodes(tags2[0])
            if np.linalg.norm(p1.mean(0) - x2[n2].mean(0)) > 20:
                continue
            d1 = point_segment_distance(p1, _polyline(b2, x2, tags2))
            p2 = x2[n2 + b2.group_nodes(tags2[1])]
            d2 = point_segment_distance(p2, _polyline(b1, x1, [tooth_tag(i, DRIVE_FLANK), tooth_tag(i, TIP)]))
            k1, k2 = int(np.argmin(d1)), int(np.argmin(d2))
            gap = min(d1[k1], d2[k2])
            close = p1[k1] if d1[k1] <= d2[k2] else p2[k2]
            r1 = float(np.linalg.norm(p1[np.argmin(np.linalg.norm(p1 - close, axis=1))]))
            if gap < reach:
                out.append((i, j, float(gap), r1, close))
    return out


def deck_bodies(w, b1, b2, x1, x2, E, nu, section_thickness):
    """The two bodies of a deck through the line writer w: nodes (gear 2's numbered after gear
    1's), CPS8 elements in sets G1 and G2, one steel and its plane-stress sections."""
    off2, eoff2 = len(x1), len(b1.elems)
    w("*NODE, NSET=NALL")
    for k, (x, y) in enumerate(x1):
        w(f"{k + 1}, {x:.12g}, {y:.12g}")
    for k, (x, y) in enumerate(x2):
        w(f"{off2 + k + 1}, {x:.12g}, {y:.12g}")
    for name, body, eo, no in (("G1", b1, 0, 0), ("G2", b2, eoff2, off2)):
        w(f"*ELEMENT, TYPE=CPS8, ELSET={name}")
        for e, q in enumerate(body.elems):
            w(f"{eo + e + 1}, " + ", ".join(str(no + v + 1) for v in q))
    w("*MATERIAL, NAME=STEEL\n*ELASTIC\n%.8g, %.8g" % (E, nu))
    for name in ("G1", "G2"):
        w(f"*SOLID SECTION, ELSET={name}, MATERIAL=STEEL\n{section_thickness:.8g}")


def deck_nset(w, name, ids):
    """A node set, 12 ids a line."""
    w(f"*NSET, NSET={name}")
    ids = list(ids)
    for k in range(0, len(ids), 12):
        w(", ".join(str(v) for v in ids[k:k + 12]))


def deck_surface(w, name, body, xb, eo, tags, centre, radius):
    """An element-face surface of the faces of boundary groups `tags` of `body` (nodes xb,
    element numbers offset by eo) whose mid-node lies within `radius` of `centre`."""
    w(f"*SURFACE, NAME={name}, TYPE=ELEMENT")
    n = 0
    for tag in tags:
        for (e, f), (a, b) in zip(body.group_faces.get(tag, []), body.group_edges.get(tag, [])):
            if np.linalg.norm(xb[body.mids[frozenset((a, b))]] - centre) <= radius:
                w(f"{eo + e + 1}, S{f}")
                n += 1
    if n == 0:
        raise ValueError(f"contact surface {name}: no face within {radius} mm of the contact")


def timed(cmd, log, env=None, cwd=None, case="ccx_model"):
    """Runs cmd with nice -n 15, output to log; returns (wall, cpu) [s], the CPU time (user +
    system) of this child alone (os.wait4), so that two runs side by side are timed apart.
    Exits with `<case>: FAIL` when the command fails."""
    t0 = time.time()
    with open(log, "w") as f:
        proc = subprocess.Popen(["nice", "-n", "15"] + cmd, stdout=f, stderr=subprocess.STDOUT, env=env, cwd=cwd)
        _, status, ru = os.wait4(proc.pid, 0)
    rc = os.waitstatus_to_exitcode(status)
    wall, cpu = time.time() - t0, ru.ru_utime + ru.ru_stime
    if rc != 0:
        sys.exit(f"{case}: FAIL ({' '.join(cmd[:2])} exited with {rc}; see {log})")
    return wall, cpu


def run_ccx(ccx, d, job, reuse, env, case):
    """ccx on d/job.inp, single-threaded through env, timed (d/job.time); with `reuse`
    (development only) a finished run's recorded times instead. Returns (wall, cpu) [s]."""
    if reuse and os.path.exists(f"{d}/{job}.time"):
        wall, cpu = map(float, open(f"{d}/{job}.time").read().split())
        return wall, cpu
    for ext in ("dat", "frd", "time"):
        if os.path.exists(f"{d}/{job}.{ext}"):
            os.remove(f"{d}/{job}.{ext}")
    wall, cpu = timed([ccx, job], f"{d}/{job}.log", env=env, cwd=d, case=case)
    with open(f"{d}/{job}.time", "w") as f:
        f.write(f"{wall} {cpu}\n")
    return wall, cpu


def write_csv(path, rows):
    """rows (dicts with the same keys) as CSV, through a temporary file."""
    tmp = path + ".tmp"
    with open(tmp, "w", newline="") as f:
        wr = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        wr.writeheader()
        wr.writerows(rows)
    os.replace(tmp, path)


def write_deck(path, g, b1, b2, phi1_deg, rotations_urad, slope, thickness, E, nu, pinion_slave_radius,
               band=(1.0, 1.5), slab=1e-3):
    """The ccx input for one position: one *STEP per pinion bore rotation [urad]. The contact
    surfaces of a tooth pair are the faces within band = (slave, master) radii [mm] of the
    pair's closest unloaded approach (4-6 Hertz half-widths at LS9: the patch and its
    movement under load; fewer contact elements converge in fewer ccx iterations).

    Plane stress: ccx expands a CPS8 element into a 3-D C3D20 slab of the section thickness,
    which is plane stress only when the slab is thin against the in-plane sizes (a CPS8
    cantilever 1 mm deep deflects like plane stress at thickness 0.1 mm, -0.3 %, but like plane
    strain at 14 mm). So the slab is `slab` x thickness thick and every force and moment read
    back is scaled by 1/slab (stresses and the pressure-overclosure slope do not change).
    Returns the tooth pairs in contact and the node numbering offsets."""
    phi1 = math.radians(phi1_deg)
    x1 = placed(b1, (0.0, 0.0), g["phase1"] + phi1)
    x2 = placed(b2, (0.0, g["a"]), g["phase2"] - phi1 / g["u"])
    off2 = len(x1)
    eoff2 = len(b1.elems)
    pairs = mesh_pairs(g, b1, b2, x1, x2)
    L = []
    w = L.append
    w("*HEADING\ngearfem calculix_peer: FZG type C pair, roll angle %.4f deg (mm, N, MPa)" % phi1_deg)
    deck_bodies(w, b1, b2, x1, x2, E, nu, thickness * slab)

    def nset(name, ids):
        deck_nset(w, name, ids)

    bore1 = [v + 1 for v in b1.group_nodes(1)]
    bore2 = [off2 + v + 1 for v in b2.group_nodes(1)]
    nset("BORE1", bore1)
    nset("BORE2", bore2)
    fil1 = {i: [v + 1 for v in b1.group_nodes(tooth_tag(i, FILLET_DRIVE))] for i in b1.teeth_with(FILLET_DRIVE)}
    fil2 = {j: [off2 + v + 1 for v in b2.group_nodes(tooth_tag(j, FILLET_DRIVE))] for j in b2.teeth_with(FILLET_DRIVE)}
    nset("FILLETS", sorted({v for s in list(fil1.values()) + list(fil2.values()) for v in s}))

    def surface(name, body, xb, eo, tags, centre, radius):
        deck_surface(w, name, body, xb, eo, tags, centre, radius)

    w("*SURFACE INTERACTION, NAME=SI\n*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR\n%.6g" % slope)
    contact = []
    for i, j, gap, r1, close in pairs:
        # pinion surfaces: drive flank, tip land, drive fillet; gear the same
        s1 = [tooth_tag(i, s) for s in (DRIVE_FLANK, 6, TIP)]
        s2 = [tooth_tag(j, s) for s in (DRIVE_FLANK, 6, TIP)]
        m1 = s1 + [tooth_tag(i, FILLET_DRIVE)]
        m2 = s2 + [tooth_tag(j, FILLET_DRIVE)]
        pin_slave = r1 >= pinion_slave_radius  # the pinion's tip is nearer the contact
        sl, ms = f"P{i}_{j}_S", f"P{i}_{j}_M"
        if pin_slave:
            surface(sl, b1, x1, 0, s1, close, band[0])
            surface(ms, b2, x2, eoff2, m2, close, band[1])
        else:
            surface(sl, b2, x2, eoff2, s2, close, band[0])
            surface(ms, b1, x1, 0, m1, close, band[1])
        w(f"*CONTACT PAIR, INTERACTION=SI, TYPE=SURFACE TO SURFACE\n{sl}, {ms}")
        contact.append(dict(pinion_tooth=i, gear_tooth=j, gap_mm=gap, slave=1 if pin_slave else 2,
                            slave_name=sl, master_name=ms))
    w("*BOUNDARY\nBORE2, 1, 2, 0.")
    for s, urad in enumerate(rotations_urad):
        dth = urad * 1e-6
        w("*STEP, INC=200\n*STATIC\n1., 1., 1e-5, 1.")
        w("*BOUNDARY")
        for v in bore1:
            x, y = x1[v - 1]
            w(f"{v}, 1, 1, {-dth * y:.12g}")
            w(f"{v}, 2, 2, {dth * x:.12g}")
        w("*NODE PRINT, NSET=BORE1\nRF\n*NODE PRINT, NSET=BORE2\nRF")
        for c in contact:
            w(f"*CONTACT PRINT, SLAVE={c['slave_name']}, MASTER={c['master_name']}\nCF")
        w("*EL FILE, NSET=FILLETS\nS\n*END STEP")
    tmp = path + ".tmp"
    with open(tmp, "w") as f:
        f.write("\n".join(L) + "\n")
    os.replace(tmp, path)
    return dict(contact=contact, x1=x1, x2=x2, off2=off2, fillets1=fil1, fillets2=fil2,
                bore1=bore1, bore2=bore2, force_scale=1.0 / slab)


# --------------------------------------------------------------------------- results
def read_dat(path, model):
    """Per step: T1 from the pinion support reactions [N m], the gear support's moment about O2
    (model["O2"] when given, else the middle of its bore) [N m], and per contact pair the force
    and moment about O1 [N, N m]."""
    x1, x2, off2 = model["x1"], model["x2"], model["off2"]
    steps, cur = [], None
    with open(path) as f:
        text = f.read().split("\n")
    i = 0
    while i < len(text):
        s = text[i]
        m = re.match(r"\s*forces \(fx,fy,fz\) for set (\S+) and time\s+(\S+)", s)
        if m:
            name, t = m.group(1), float(m.group(2))
            if cur is None or cur["time"] != t or name in cur["sets"]:
                cur = dict(time=t, sets={}, cf=[])
                if steps and steps[-1]["time"] == t:
                    steps[-1] = cur  # a further increment at the same time (ccx ends some steps with a
                else:                # zero-size increment): its output replaces the earlier one
                    steps.append(cur)
            i += 1
            rows = []
            while i < len(text) and (not text[i].strip() or re.match(r"\s*\d+\s", text[i])):
                if text[i].strip():
                    w = text[i].split()
                    rows.append((int(w[0]), float(w[1]), float(w[2])))
                i += 1
            cur["sets"][name] = rows
            continue
        m = re.match(r"\s*statistics for slave set (\S+), master set (\S+) and time\s+(\S+)", s)
        if m:
            j = i + 1
            while "total surface force" not in text[j]:
                j += 1
            j += 1
            while not text[j].strip():
                j += 1
            vals = text[j].split()
            cur["cf"].append(dict(slave=m.group(1), master=m.group(2), F=[float(v) for v in vals[:3]],
                                  M=[float(v) for v in vals[3:6]]))
            i += 3
            continue
        i += 1
    out = []
    for st in steps:
        def moment(rows, xy, off, centre):
            M = 0.0
            for n, fx, fy in rows:
                x, y = xy[n - 1 - off] - centre
                M += x * fy - y * fx
            return M * 1e-3 * model["force_scale"]  # N mm -> N m, slab -> face width
        T1 = moment(st["sets"]["BORE1"], x1, 0, np.zeros(2))
        # Gear 2's centre: given (a ring held on an outer arc), or the middle of its bore.
        O2c = np.asarray(model["O2"], dtype=float) if "O2" in model else \
            np.array([0.0, float(np.mean(x2[[n - 1 - off2 for n, _, _ in st["sets"]["BORE2"]]][:, 1]))])
        T2 = moment(st["sets"]["BORE2"], x2, off2, O2c)
        pairs = []
        for c, cf in zip(model["contact"], st["cf"]):
            F = np.array(cf["F"][:2]) * model["force_scale"]
            # moment about O1 of the force on the pinion (the slave force, or minus it)
            Mz = cf["M"][2] * 1e-3 * model["force_scale"]
            sign = 1.0 if c["slave"] == 1 else -1.0
            pairs.append(dict(c, F=float(np.linalg.norm(F)), M1=sign * Mz))
        out.append(dict(T1=T1, T2=T2, pairs=pairs))
    return out


def read_frd_stress(path):
    """Nodal stresses per result block (one block per step) of a ccx ASCII .frd:
    list of {node: (sxx, syy, szz, sxy, syz, szx)}."""
    blocks, cur = [], None
    with open(path) as f:
        for line in f:
            if line.startswith(" -4  STRESS"):
                cur = {}
                blocks.append(cur)
                continue
            if cur is not None:
                if line.startswith(" -3"):
                    cur = None
                elif line.startswith(" -1"):
                    n = int(line[3:13])
                    vals = [float(line[13 + 12 * k:25 + 12 * k]) for k in range(6)]
                    cur[n] = vals
    return blocks


def sigma1(s):
    sxx, syy, sxy = s[0], s[1], s[3]
    c, r = (sxx + syy) / 2, math.hypot((sxx - syy) / 2, sxy)
    return c + r
