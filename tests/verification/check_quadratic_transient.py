#!/usr/bin/python3
"""Transient 1D conduction under a sudden surface flux, for a second-order coupled type (issue 43 item 2).

A bar 0 < s < L = 1 (s = x; the axisymmetric types: s = -z, r in [1, 1 + H]) one element wide (H = 0.25, so
the cross-section's nodes are far apart compared with the depth the heat reaches in an increment), initially at
0, k = rho = c = 1; a flux q = 1 into the face s = 0 from t = 0; every other face insulated, displacements held.
The exact solution depends on s alone (Carslaw and Jaeger, 3.3; xi = s / L, Fourier number F = k t / (rho c L^2)):

  theta = (q L / k) [F + 1/3 - xi + xi^2 / 2 - (2 / pi^2) sum_n exp(-n^2 pi^2 F) cos(n pi xi) / n^2],

positive and strictly decreasing in s at every t > 0. Five jobs per type, written here and run with the given
binary (backward Euler, fixed increments, every increment output), all with dt >= rho c dl^2 / (6 k) for element
length dl, the bound below which a second-order mesh's consistent capacity oscillates (docs/elements.md, "Capacity"):
  - 8 elements along the bar, dt = 0.01 and 0.005: the nodal error at t = 0.02, 0.05, 0.1 against the series, the
    one at dt = 0.005 within 2 % of theta(0, 0.1) = 0.357 (backward Euler's first-order error, about 1.4 %, is
    most of it), and halving dt lowers it by 30 % at least;
  - 4, 8 and 32 elements at dt = 0.0125: the spatial error of 4 and 8 against 32 at their common nodes (same
    time discretisation), falling by 2x at least from 4 to 8 elements (bricks and quadrilaterals: 9-12x);
  - in every job and frame: no temperature below -1e-6 (the exact one is positive), no rise along the bar above
    1e-5 of the surface value (monotone), and at the check times one value across the section, within 1e-6 of the
    surface value for bricks and quadrilaterals, 1.5e-2 for the simplex meshes (their sections are not symmetric:
    the difference is their discretisation error, 0.5-0.9 % on 4-8 elements, falling with h).
With the capacity lumped (HRZ for quad8 and hex20, the linear sub-elements for tri6 and tet10) the section's
nodes held different fields, 8-27 % of the surface value apart, and the base error was 4.3-12 % (docs/elements.md,
"Capacity").
usage: check_quadratic_transient.py THERMOSLIDE OUTDIR TYPE [MPIEXEC ...]
"""
import math
import os
import subprocess
import sys

sys.path.insert(0, sys.path[0] + "/../tools")
from tslcheck import Result, check, check_true, finish  # noqa: E402

import numpy as np  # noqa: E402

exe, outdir, typ = sys.argv[1:4]
mpiexec = sys.argv[4:]
L, H, Q = 1.0, 0.25, 1.0
TIMES = (0.02, 0.05, 0.1)

FAMILY = {
    "C3D20T": "hex20", "C3D20RT": "hex20", "C3D10MT": "tet10", "C3D10T": "tet10", "C3D10HT": "tet10",
}
for t in ("CPE8T", "CPE8HT", "CPS8T", "CPEG8T", "CAX8T", "CGAX8T", "CPE8RT", "CPE8RHT", "CPS8RT", "CAX8RT", "CAX8RHT"):
    FAMILY[t] = "quad8"
for t in ("CPE6MT", "CPE6MHT", "CPS6MT", "CPEG6MT", "CPEG6MHT", "CAX6MT", "CAX6MHT", "CGAX6MT", "CGAX6MHT", "CPE6T", "CPS6T", "CAX6T"):
    FAMILY[t] = "tri6"
# rows the dialect has no coupled name for: a deck names them by CalculiX's mechanical name (docs/elements.md)
DECK_TYPE = {"CPE6T": "CPE6", "CPS6T": "CPS6", "CAX6T": "CAX6"}
fam = FAMILY[typ]
axi = typ.startswith("CAX") or typ.startswith("CGAX")
dim = 3 if fam in ("hex20", "tet10") else 2
# the section of a simplex mesh (each square cut along a diagonal, each cube into six tetrahedra) is not
# symmetric: its Galerkin solution differs across the section by its discretisation error (0.5-0.9 % of the
# surface value on 4-8 elements, falling with h), where the bricks' and quadrilaterals' is 1D to round-off
RISE = 1e-5
SPREAD = 1.5e-2 if fam in ("tri6", "tet10") else 1e-6

# corner faces in the dialect's numbering (1-based node positions), S1, S2, ...
FACES = {
    "tri6": [(1, 2), (2, 3), (3, 1)],
    "quad8": [(1, 2), (2, 3), (3, 4), (4, 1)],
    "tet10": [(1, 3, 2), (1, 2, 4), (2, 3, 4), (3, 1, 4)],
    "hex20": [(1, 4, 3, 2), (5, 6, 7, 8), (1, 2, 6, 5), (2, 3, 7, 6), (3, 4, 8, 7), (4, 1, 5, 8)],
}
# midside nodes as pairs of corners, in the catalogue's order (docs/elements.md, "Node numbering")
EDGES = {
    "tri6": [(1, 2), (2, 3), (3, 1)],
    "quad8": [(1, 2), (2, 3), (3, 4), (4, 1)],
    "tet10": [(1, 2), (2, 3), (3, 1), (1, 4), (2, 4), (3, 4)],
    "hex20": [(1, 2), (2, 3), (3, 4), (4, 1), (5, 6), (6, 7), (7, 8), (8, 5), (1, 5), (2, 6), (3, 7), (4, 8)],
}


def exact(s, t):
    xi, F = s / L, t / L ** 2
    v = F + 1.0 / 3 - xi + xi * xi / 2
    for n in range(1, 400):
        v -= 2 / math.pi ** 2 * math.exp(-n * n * math.pi ** 2 * F) * math.cos(n * math.pi * xi) / (n * n)
    return Q * L * v


def corners(n):
    """Corner coordinates and the linear elements (corner tuples) of the bar, s along the first axis."""
    if dim == 2:
        pts = {(i, j): (L * i / n, H * j) for i in range(n + 1) for j in range(2)}
        quads = [((i, 0), (i + 1, 0), (i + 1, 1), (i, 1)) for i in range(n)]
        if fam == "quad8":
            return pts, quads
        return pts, [t for q in quads for t in ((q[0], q[1], q[2]), (q[0], q[2], q[3]))]
    pts = {(i, j, k): (L * i / n, H * j, H * k) for i in range(n + 1) for j in range(2) for k in range(2)}
    hexes = [((i, 0, 0), (i + 1, 0, 0), (i + 1, 1, 0), (i, 1, 0), (i, 0, 1), (i + 1, 0, 1), (i + 1, 1, 1), (i, 1, 1)) for i in range(n)]
    if fam == "hex20":
        return pts, hexes
    tets = []
    for h in hexes:  # six tetrahedra around the diagonal 1-7 (Kuhn), each oriented to a positive volume
        for p in ((0, 1, 2, 6), (0, 2, 3, 6), (0, 3, 7, 6), (0, 7, 4, 6), (0, 4, 5, 6), (0, 5, 1, 6)):
            c = [h[m] for m in p]
            a = [np.array(pts[m]) for m in c]
            if np.dot(np.cross(a[1] - a[0], a[2] - a[0]), a[3] - a[0]) < 0:
                c[1], c[2] = c[2], c[1]
            tets.append(tuple(c))
    return pts, tets


def mesh(n):
    pts, elems = corners(n)
    ids, coords = {}, []

    def node(x):
        key = tuple(round(v, 12) for v in x)
        if key not in ids:
            ids[key] = len(coords) + 1
            coords.append(x)
        return ids[key]

    out, flux = [], []
    for e, c in enumerate(elems):
        xc = [np.array(pts[m]) for m in c]
        conn = [node(tuple(x)) for x in xc] + [node(tuple((xc[a - 1] + xc[b - 1]) / 2)) for a, b in EDGES[fam]]
        out.append(conn)
        for f, face in enumerate(FACES[fam]):
            if all(abs(xc[m - 1][0]) < 1e-12 for m in face):
                flux.append((e + 1, f + 1))
    coords = np.array(coords)
    if axi:  # the bar along -z at r in [1, 1 + H]: (s, y) -> (r, z) = (1 + y, -s), a rotation (elements stay counter-clockwise)
        coords = np.column_stack([1 + coords[:, 1], -coords[:, 0]])
    return coords, out, flux


def deck(n, dt):
    coords, elems, flux = mesh(n)
    ref = len(coords) + 1
    lines = ["*HEADING", " %s: transient 1D conduction, flux 1 into s = 0 of a bar 0 < s < 1 from t = 0" % typ, "*NODE, NSET=ALL"]
    lines += [" %d, " % (i + 1) + ", ".join("%.12g" % v for v in x) for i, x in enumerate(coords)]
    gen = typ.startswith("CPEG")
    if gen:
        lines += ["*NODE, NSET=REF", " %d, -1, 0" % ref]  # outside the bar: examine() leaves it out
    lines += ["*ELEMENT, TYPE=%s, ELSET=BODY" % DECK_TYPE.get(typ, typ)] + [" %d, " % (e + 1) + ", ".join(str(v) for v in c) for e, c in enumerate(elems)]
    lines += ["*MATERIAL, NAME=M", "*ELASTIC", " 1000.0, 0.3", "*EXPANSION", " 1e-5", "*CONDUCTIVITY", " 1.0", "*DENSITY", " 1.0",
              "*SPECIFIC HEAT", " 1.0"]
    lines += ["*SOLID SECTION, ELSET=BODY, MATERIAL=M" + (", REF NODE=%d" % ref if gen else ""), " 1.0"]
    lines += ["*INITIAL CONDITIONS, TYPE=TEMPERATURE", " ALL, 0.0"]
    lines += ["*STEP, INC=100000", "*COUPLED TEMPERATURE-DISPLACEMENT, DIRECT", " %.10g, %.10g" % (dt, TIMES[-1])]
    lines += ["*BOUNDARY", " ALL, 1, %d" % dim]
    if typ.startswith("CGAX"):
        lines += [" ALL, 5, 5"]
    lines += ["*DFLUX"] + [" %d, S%d, %.10g" % (e, f, Q) for e, f in flux]
    lines += ["*NODE OUTPUT", " NT", "*END STEP", ""]
    return "\n".join(lines)


def run(name, n, dt):
    d = os.path.join(outdir, name)
    os.makedirs(d, exist_ok=True)
    path = os.path.join(d, "%s.inp" % name)
    with open(path, "w") as f:
        f.write(deck(n, dt))
    with open(path[:-4] + ".log", "w") as log:
        rc = subprocess.call(mpiexec + [exe, path, "-o", d], stdout=log, stderr=subprocess.STDOUT)
    check_true("%s: job completed" % name, rc == 0, "(exit %d, log %s)" % (rc, path[:-4] + ".log"))
    if rc:
        finish()
    return Result(d, name)


def examine(name, r):
    """Largest nodal error over the check times; positivity, monotonicity and the section's spread checked."""
    s = -r.xyz[:, 1] if axi else r.xyz[:, 0]
    bar = s > -1e-9  # not a generalized plane strain reference node
    s, order = s[bar], np.argsort(s[bar], kind="stable")
    times = [float(r.frame(i).attrs["time"]) for i in range(len(r.frames))]
    worst, low, rise, spread = 0.0, np.inf, 0.0, 0.0
    for i, t in enumerate(times):
        nt = r.field("NT", i)[bar, 0]
        low = min(low, nt.min())
        ss, vv = s[order], nt[order]
        levels = [vv[np.abs(ss - lv) < 1e-9] for lv in np.unique(np.round(ss, 9))]
        surface = exact(0, t)
        # monotone: no value at a level above the smallest one at the level before it
        for a in range(1, len(levels)):
            rise = max(rise, (levels[a].max() - levels[a - 1].min()) / surface)
        if any(abs(t - tt) < 1e-9 for tt in TIMES):
            spread = max(spread, max((v.max() - v.min()) / surface for v in levels))
            worst = max(worst, np.abs(nt - np.array([exact(v, t) for v in s])).max())
    check("%s: smallest temperature over all frames" % name, min(low, 0.0), 0.0, 1e-6)
    check("%s: largest rise along the bar / surface value, all frames (monotone profile)" % name, max(rise, 0.0), 0.0, RISE)
    check("%s: largest spread across the section / surface value" % name, spread, 0.0, SPREAD)
    return worst


def levels(r, t):
    """The frame at time t: its nodal temperatures averaged over each s-level, by s rounded."""
    s = np.round(-r.xyz[:, 1] if axi else r.xyz[:, 0], 9)
    i = min(range(len(r.frames)), key=lambda j: abs(float(r.frame(j).attrs["time"]) - t))
    nt = r.field("NT", i)[:, 0]
    return {v: nt[s == v].mean() for v in np.unique(s)}


# accuracy and time: 8 elements, dt = 0.01 and 0.005 (mesh Fourier numbers 0.64 and 0.32)
coarse_dt = examine("dt_0.01", run("dt_0.01", 8, 0.01))
base = examine("base", run("base", 8, 0.005))
# space at a fixed dt = 0.0125 (mesh Fourier number 0.2 on 4 elements): 4 and 8 elements against 32, the
# time-discrete solution's spatial error, at the common levels s = 0, 1/4, ..., 1 and every increment
space = [run("h_%d" % n, n, 0.0125) for n in (4, 8, 32)]
for n, r in zip((4, 8), space[:2]):
    examine("h_%d" % n, r)
err_h = []
for r in space[:2]:
    e = 0.0
    for t in np.arange(0.0125, TIMES[-1] + 1e-9, 0.0125):
        a, b = levels(r, t), levels(space[2], t)
        e = max(e, max(abs(a[v] - b[v]) for v in a if v in b))
    err_h.append(e)
scale = exact(0, TIMES[-1])
print("%s: largest nodal error over t = %s (8 elements): dt 0.01 %.4e, dt 0.005 %.4e; spatial error at dt 0.0125 "
      "(against 32 elements): 4 elements %.4e, 8 elements %.4e (of theta(0, 0.1) = %.4f)" %
      (typ, ", ".join("%g" % t for t in TIMES), coarse_dt, base, err_h[0], err_h[1], scale))
check("%s: base error (8 elements, dt 0.005) / theta(0, 0.1)" % typ, base / scale, 0.0, 0.02)
check_true("%s: halving dt lowers the error (first order: by about half)" % typ, base < 0.7 * coarse_dt, "(%.4e -> %.4e)" % (coarse_dt, base))
check_true("%s: halving the element length lowers the spatial error (by 2x at least)" % typ, err_h[1] < 0.5 * err_h[0],
           "(%.4e -> %.4e)" % (err_h[0], err_h[1]))
finish()
