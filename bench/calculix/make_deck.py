#!/usr/bin/env python3
"""Write the CalculiX (ccx 2.20) deck of the centre indent of the line-test sheet.

The same problem as bench/calculix/indent_centre.toml for spifit: a square sheet (side L,
thickness t, mid-surface at z = 0, edges clamped) of S4 shells, pushed at its centre by a rigid
sphere of radius R along -z, frictionless penalty contact, von Mises + Swift plasticity.

- Sheet: n x n S4 elements (full model), normals +z, clamped edges (all six DOFs); or, with
  --element C3D8I, n x n x layers incompatible-mode bricks through the thickness (the element
  ccx expands each S4 into), clamped edges (every node of the edge columns), the top faces (S2)
  as the slave surface.
- Material: *ELASTIC E, nu and a *PLASTIC table sampled from sigma = K (eps0 + p)^n
  (p = 0, then a geometric grid up to 2; ccx interpolates linearly).
- Tool: the lower hemisphere of a sphere, one layer of C3D8 elements (a cube-sphere mesh, no
  pole), made a *RIGID BODY around a reference node at the centre; the reference node is moved
  by -depth in z and its reaction force is printed (*NODE PRINT RF) at every increment.
- Contact: *CONTACT PAIR, TYPE=SURFACE TO SURFACE (default) or NODE TO SURFACE (penalty,
  linear pressure-overclosure, slope = the spifit penalty in N/mm^3); slave = the sheet's SPOS
  faces (or nodes) around the centre, master = the sphere's outer faces.

Contact offset: spifit's tool touches the tool-side surface, the mid-surface + t/2. Measured
with ccx 2.20 (README.md, "Contact offset"; --gap and --centre-print reproduce the check):
- slave = the sheet's SPOS faces (default): contact acts on the expanded shell's top face, the
  mid-surface + t/2, with NODE TO SURFACE and SURFACE TO SURFACE alike: no offset needed;
- slave = the sheet's nodes (--slave nodes): contact acts at the mid-surface nodes.
--offset auto (default) therefore meshes the sphere with radius R (faces) or R + t/2 (nodes)
around spifit's tool centre: a sphere of radius R touching the mid-surface + t/2 is a sphere of
radius R + t/2 touching the mid-surface (offset surfaces of a sphere are spheres; exact while
the thickness is t). --offset none meshes radius R in both cases.

The depth is the tool travel from first touch (tip on the top surface at depth 0), as in
spifit's path z. Standard library only (Python >= 3.8; the card is read with tomllib on
Python >= 3.11, or with a small reader of the [elastic] and [swift] tables otherwise).
"""

import argparse
import math
import os
import re
import sys


def read_card(path):
    """E, nu, K, eps0, n of a spifit card (isotropic: a [hill] table is refused)."""
    text = open(path, encoding="utf-8").read()
    try:
        import tomllib  # Python >= 3.11

        data = tomllib.loads(text)
    except ImportError:
        data = {}
        table = ""
        for line in text.splitlines():
            line = line.split("#", 1)[0].strip()
            m = re.match(r"^\[([A-Za-z0-9_.]+)\]$", line)
            if m:
                table = m.group(1)
                data.setdefault(table, {})
                continue
            m = re.match(r"^([A-Za-z0-9_]+)\s*=\s*([-+0-9.eE]+)$", line)
            if m and table:
                data[table][m.group(1)] = float(m.group(2))
    if "hill" in data:
        sys.exit("make_deck.py: %s has a [hill] table; CalculiX's *PLASTIC is von Mises: "
                 "use an isotropic card (bench/calculix/aa3003o_c4_mises.toml)" % path)
    for key in ("kinematic", "ziegler", "armstrong_frederick"):
        if key in data:
            sys.exit("make_deck.py: %s has kinematic hardening [%s]; this bench is isotropic" % (path, key))
    el, sw = data["elastic"], data["swift"]
    return float(el["E"]), float(el["nu"]), float(sw["K"]), float(sw["eps0"]), float(sw["n"])


def swift_table(K, eps0, n, points=150, first=1e-5, last=2.0):
    """(sigma, p) pairs: p = 0, then `points` values on a geometric grid from first to last."""
    ps = [0.0] + [first * (last / first) ** (i / (points - 1)) for i in range(points)]
    return [(K * (eps0 + p) ** n, p) for p in ps]


def fmt(x):
    """Shortest text that reads back to x, within ccx's 20 characters per number."""
    s = repr(float(x))
    return s if len(s) <= 20 else "%.13e" % x


def sphere_cap(radius, inner, m):
    """Lower hemisphere of a cube-sphere: nodes (centre at the origin) and C3D8 elements (inner
    face 1-2-3-4, outer face 5-6-7-8 = face S2, outward normal). The cube [-m, m]^3 is cut in
    m x m faces (coordinates -m, -m + 2, ..., m); m odd puts a face centre, not a node, at the
    pole, so the facet under the tool's tip is normal to z (no spurious Fx, Fy)."""
    keys = {}
    quads = []

    def key(i, j, k):
        if (i, j, k) not in keys:
            keys[(i, j, k)] = len(keys)
        return keys[(i, j, k)]

    grid = list(range(-m, m + 1, 2))
    # side faces from the bottom edge (k = -m) up to the first k >= 0 (the equator or just past)
    kmax = next(k for k in grid if k >= 0)
    ks = [k for k in grid if k <= kmax]
    for a, b in zip(grid[:-1], grid[1:]):
        for c, d in zip(grid[:-1], grid[1:]):
            quads.append([key(a, c, -m), key(b, c, -m), key(b, d, -m), key(a, d, -m)])
        for k0, k1 in zip(ks[:-1], ks[1:]):
            for s_ in (m, -m):
                quads.append([key(s_, a, k0), key(s_, b, k0), key(s_, b, k1), key(s_, a, k1)])
                quads.append([key(a, s_, k0), key(b, s_, k0), key(b, s_, k1), key(a, s_, k1)])
    dirs = [None] * len(keys)
    for (i, j, k), idx in keys.items():
        r = math.sqrt(i * i + j * j + k * k)
        dirs[idx] = (i / r, j / r, k / r)
    elems = []
    for q in quads:
        p = [tuple(radius * c for c in dirs[v]) for v in q]
        d1 = [p[2][c] - p[0][c] for c in range(3)]
        d2 = [p[3][c] - p[1][c] for c in range(3)]
        nrm = (d1[1] * d2[2] - d1[2] * d2[1], d1[2] * d2[0] - d1[0] * d2[2], d1[0] * d2[1] - d1[1] * d2[0])
        cen = [sum(pp[c] for pp in p) for c in range(3)]
        if sum(nrm[c] * cen[c] for c in range(3)) < 0.0:
            q = [q[0], q[3], q[2], q[1]]
        elems.append(q)
    nv = len(dirs)
    nodes = [tuple(inner * c for c in d) for d in dirs] + [tuple(radius * c for c in d) for d in dirs]
    # C3D8: 1-2-3-4 (inner, counter-clockwise seen from outside), 5-8 the outer copies
    c3d8 = [q + [v + nv for v in q] for q in elems]
    return nodes, c3d8


def graded_coordinates(L, N, g):
    """Node coordinates across the side: N elements (even), symmetric about 0, sizes growing
    geometrically from the centre to the edge with edge / centre size = g (1: regular)."""
    m = N // 2
    if g <= 0:
        sys.exit("make_deck.py: --grading must be > 0")
    r = g ** (1.0 / (m - 1)) if m > 1 else 1.0
    sizes = [r ** k for k in range(m)]
    scale = (L / 2) / sum(sizes)
    half = [0.0]
    for s_ in sizes:
        half.append(half[-1] + s_ * scale)
    half[-1] = L / 2
    return [-x for x in reversed(half[1:])] + half


def write_deck(a, out):
    E, nu, K, eps0, n = read_card(a.card)
    L, t, R, N = a.length, a.thickness, a.radius, a.elements
    if N < 2 or N % 2:
        sys.exit("make_deck.py: --elements must be even (a node at the centre)")
    if a.offset == "auto":
        Rs = R if a.slave == "faces" else R + t / 2
    else:
        Rs = R
    zc = t / 2 + R + a.gap  # tool centre: tip on the top surface (spifit's depth 0) + the gap
    w = []
    w.append("** Centre indent of the line-test sheet: written by bench/calculix/make_deck.py")
    w.append("** sheet %g x %g mm, t = %g mm, %d x %d S4 (mid-surface z = 0, grading %g), clamped edges"
             % (L, L, t, N, N, a.grading))
    w.append("** tool R = %g mm (contact sphere radius %g mm: offset %s), depth %g mm, penalty %g N/mm^3"
             % (R, Rs, a.offset, a.depth, a.penalty))
    w.append("** card %s: E = %g, nu = %g, Swift K = %g, eps0 = %g, n = %g, von Mises"
             % (os.path.basename(a.card), E, nu, K, eps0, n))
    w.append("*HEADING")
    solid = a.element == "C3D8I"
    levels = a.layers + 1 if solid else 1
    w.append("spifit bench: centre indent, CalculiX %s %dx%d%s" % (a.element, N, N, " x %d" % a.layers if solid else ""))
    # --- sheet nodes: shells one level (the mid-surface); bricks levels k = 0..layers at
    # z = -t/2 + k t / layers
    w.append("*NODE, NSET=NSHEET")
    nid = lambda i, j, k=0: k * (N + 1) ** 2 + j * (N + 1) + i + 1
    xs = graded_coordinates(L, N, a.grading)
    h = max(xs[N // 2 + 1] - xs[N // 2], 1e-12)  # the central element size
    for k in range(levels):
        z = -t / 2 + t * k / a.layers if solid else 0.0
        for j in range(N + 1):
            for i in range(N + 1):
                w.append("%d, %s, %s, %s" % (nid(i, j, k), fmt(xs[i]), fmt(xs[j]), fmt(z) if solid else "0."))
    nsheet = levels * (N + 1) ** 2
    # --- sheet elements (eid's default layer is the top one, whose faces are the slave surface)
    w.append("*ELEMENT, TYPE=%s, ELSET=SHEET" % a.element)
    top = a.layers - 1 if solid else 0
    eid = lambda i, j, k=top: k * N * N + j * N + i + 1
    for k in range(a.layers if solid else 1):
        for j in range(N):
            for i in range(N):
                corners = [nid(i, j, k), nid(i + 1, j, k), nid(i + 1, j + 1, k), nid(i, j + 1, k)]
                if solid:
                    corners += [nid(i, j, k + 1), nid(i + 1, j, k + 1), nid(i + 1, j + 1, k + 1), nid(i, j + 1, k + 1)]
                w.append("%d, " % eid(i, j, k) + ", ".join(str(c) for c in corners))
    nelem = N * N * (a.layers if solid else 1)
    # clamped edges (every level's edge nodes for bricks)
    edge = [nid(i, j, k) for k in range(levels) for j in range(N + 1) for i in range(N + 1) if i in (0, N) or j in (0, N)]
    w.append("*NSET, NSET=NCENTRE")
    w.append("%d" % nid(N // 2, N // 2, levels - 1))
    w.append("*NSET, NSET=EDGE")
    for k in range(0, len(edge), 8):
        w.append(", ".join(str(v) for v in edge[k:k + 8]) + ",")
    # slave: sheet elements within a radius of the centre (the contact patch and a margin)
    rc = min(L / 2, a.slave_radius)
    slave = [eid(i, j) for j in range(N) for i in range(N)
             if math.hypot(0.5 * (xs[i] + xs[i + 1]), 0.5 * (xs[j] + xs[j + 1])) <= rc + h]
    # --- tool
    tnodes, tel = sphere_cap(Rs, Rs - a.tool_layer, a.tool_divisions)
    t0 = nsheet
    w.append("*NODE, NSET=NTOOL")
    for k, p in enumerate(tnodes):
        w.append("%d, %s, %s, %s" % (t0 + k + 1, fmt(p[0]), fmt(p[1]), fmt(p[2] + zc)))
    ref = t0 + len(tnodes) + 1
    rot = ref + 1
    w.append("*NODE, NSET=NREF")
    w.append("%d, 0., 0., %s" % (ref, fmt(zc)))
    w.append("*NODE, NSET=NROT")
    w.append("%d, 0., 0., %s" % (rot, fmt(zc)))
    w.append("*ELEMENT, TYPE=C3D8, ELSET=TOOL")
    for k, e in enumerate(tel):
        w.append("%d, " % (nelem + k + 1) + ", ".join(str(t0 + v + 1) for v in e))
    # --- materials and sections
    w.append("*MATERIAL, NAME=SHEETMAT")
    w.append("*ELASTIC")
    w.append("%s, %s" % (fmt(E), fmt(nu)))
    w.append("*PLASTIC")
    for s, p in swift_table(K, eps0, n, a.table_points):
        w.append("%s, %s" % (fmt(s), fmt(p)))
    w.append("*MATERIAL, NAME=TOOLMAT")
    w.append("*ELASTIC")
    w.append("210000., 0.3")
    if solid:
        w.append("*SOLID SECTION, ELSET=SHEET, MATERIAL=SHEETMAT")
    else:
        w.append("*SHELL SECTION, ELSET=SHEET, MATERIAL=SHEETMAT")
        w.append(fmt(t))
    w.append("*SOLID SECTION, ELSET=TOOL, MATERIAL=TOOLMAT")
    w.append("*RIGID BODY, ELSET=TOOL, REF NODE=%d, ROT NODE=%d" % (ref, rot))
    # --- contact
    if a.slave == "faces":
        w.append("*SURFACE, NAME=SSHEET, TYPE=ELEMENT")
        for e in slave:
            w.append("%d, %s" % (e, "S2" if solid else a.slave_face))
    else:
        ids = sorted({nid(i + di, j + dj) for j in range(N) for i in range(N) if eid(i, j) in set(slave)
                      for di in (0, 1) for dj in (0, 1)})
        w.append("*SURFACE, NAME=SSHEET, TYPE=NODE")
        for v in ids:
            w.append("%d" % v)
    w.append("*SURFACE, NAME=STOOL, TYPE=ELEMENT")
    for k in range(len(tel)):
        w.append("%d, S2" % (nelem + k + 1))
    w.append("*CONTACT PAIR, INTERACTION=SI, TYPE=%s" % a.contact_type)
    w.append("SSHEET, STOOL")
    w.append("*SURFACE INTERACTION, NAME=SI")
    w.append("*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR")
    w.append("%s, %s" % (fmt(a.penalty), fmt(a.tension)))
    # --- boundary conditions
    w.append("*BOUNDARY")
    w.append("EDGE, 1, %d" % (3 if solid else 6))
    w.append("NREF, 1, 2")
    w.append("NROT, 1, 3")
    # --- step
    travel = a.depth + a.gap
    inc0 = min(1.0, a.first_increment / travel)
    incmax = min(1.0, a.max_increment / travel)
    w.append("*STEP, NLGEOM, INC=%d" % a.max_increments)
    w.append("*STATIC")
    w.append("%s, 1., %s, %s" % (fmt(inc0), fmt(min(inc0, 1e-6)), fmt(incmax)))
    w.append("*BOUNDARY")
    w.append("NREF, 3, 3, %s" % fmt(-travel))
    w.append("*NODE PRINT, NSET=NREF")
    w.append("U, RF")
    if a.centre_print:
        w.append("*NODE PRINT, NSET=NCENTRE")
        w.append("U")
    if a.frd:
        w.append("*NODE FILE")
        w.append("U")
    w.append("*END STEP")
    out.write("\n".join(w) + "\n")
    return nelem, len(tel), len(slave)


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("-o", "--output", default="-", help="deck file (default: stdout)")
    p.add_argument("--card", default=os.path.join(here, "aa3003o_c4_mises.toml"), help="isotropic spifit card")
    p.add_argument("--elements", type=int, default=40, help="S4 elements across the side (even; default 40 = 1600)")
    p.add_argument("--grading", type=float, default=1.0,
                   help="edge / centre element size, geometric (spifit's [sheet] grading; 1: regular)")
    p.add_argument("--element", choices=["S4", "C3D8I"], default="S4",
                   help="sheet elements: S4 shells (ccx expands each into one C3D8I) or C3D8I bricks in --layers layers")
    p.add_argument("--layers", type=int, default=1, help="C3D8I layers through the thickness (default 1)")
    p.add_argument("--length", type=float, default=182.0, help="side of the square sheet [mm]")
    p.add_argument("--thickness", type=float, default=1.2, help="sheet thickness [mm]")
    p.add_argument("--radius", type=float, default=5.0, help="tool radius [mm]")
    p.add_argument("--depth", type=float, default=5.0, help="tool travel from first touch [mm]")
    p.add_argument("--gap", type=float, default=0.0,
                   help="start the tool this far above the top surface (a check of where contact begins; "
                        "the printed U3 then includes the gap)")
    p.add_argument("--centre-print", action="store_true", help="also print U of the sheet's centre node")
    p.add_argument("--penalty", type=float, default=1000.0, help="contact penalty [N/mm^3]")
    p.add_argument("--contact-type", choices=["SURFACE TO SURFACE", "NODE TO SURFACE"], default="SURFACE TO SURFACE",
                   help="ccx contact formulation (face-to-face penalty, or node-to-face springs)")
    p.add_argument("--tension", type=float, default=1e-3, help="ccx tension at large clearance [MPa] (small)")
    p.add_argument("--offset", choices=["auto", "none"], default="auto",
                   help="auto: sphere radius R for face slaves (ccx's contact acts on the top face), "
                        "R + t/2 for node slaves (it acts at the mid-surface nodes); none: R")
    p.add_argument("--slave", choices=["faces", "nodes"], default="faces",
                   help="slave surface: the sheet's element faces (--slave-face) or its mid-surface nodes")
    p.add_argument("--slave-face", default="SPOS", help="face label of the sheet's slave faces")
    p.add_argument("--slave-radius", type=float, default=20.0, help="slave faces within this distance of the centre [mm]")
    p.add_argument("--tool-divisions", type=int, default=21, help="cube-sphere divisions of the tool (odd: no node at the pole)")
    p.add_argument("--tool-layer", type=float, default=1.0, help="thickness of the tool's element layer [mm]")
    p.add_argument("--table-points", type=int, default=150, help="plastic strains of the *PLASTIC table after 0")
    p.add_argument("--first-increment", type=float, default=0.1, help="first increment [mm of travel]")
    p.add_argument("--max-increment", type=float, default=0.25, help="largest increment [mm of travel]")
    p.add_argument("--max-increments", type=int, default=1000, help="*STEP INC")
    p.add_argument("--frd", action="store_true", help="also write displacements to the .frd file")
    a = p.parse_args()
    if a.element == "C3D8I" and a.slave == "nodes":
        p.error("--slave nodes is for shells: the bricks' slave surface is their top faces")
    if a.layers < 1:
        p.error("--layers must be >= 1")
    if a.slave == "nodes" and a.contact_type != "NODE TO SURFACE":
        p.error("--slave nodes needs --contact-type 'NODE TO SURFACE' (ccx: a face-to-face slave must be faces)")
    if a.output == "-":
        ne, nt, ns = write_deck(a, sys.stdout)
    else:
        with open(a.output, "w", encoding="utf-8") as f:
            ne, nt, ns = write_deck(a, f)
    print("make_deck.py: %d %s, %d tool C3D8, %d slave faces -> %s" % (ne, a.element, nt, ns, a.output), file=sys.stderr)


if __name__ == "__main__":
    main()
