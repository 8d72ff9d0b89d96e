#!/usr/bin/python3
"""A stack of identical cantilever leaves (C3D20) that touch exactly along their length, clamped at x = 0, the top
leaf's tip pushed down by a prescribed displacement; node-to-surface pairs between neighbouring leaves with a LINEAR
pressure-overclosure law. Written for check_leaf_stack.sh (issue 43, item 5: the kind of CalculiX-Examples' leaf
spring, a stack whose interfaces are closed with no pressure almost everywhere).

By symmetry of the loading each leaf carries a third of the tip force (the leaves bend alike, touching at the tip),
so the stack's tip force is n times one leaf's: n 3 E I delta / L^3 in beam theory.

usage: make_leaf_stack.py OUT.inp [--leaves N] [--extrapolation LINEAR|NO] [--field]"""
import argparse

ap = argparse.ArgumentParser()
ap.add_argument("out")
ap.add_argument("--leaves", type=int, default=3)
ap.add_argument("--extrapolation", default="")
ap.add_argument("--field", action="store_true", help="*CONTROLS, PARAMETERS=FIELD with the dialect's defaults")
ap.add_argument("--single", action="store_true", help="one leaf, its tip pushed alone (the reference stiffness)")
a = ap.parse_args()

L, b, t, nx = 10.0, 1.0, 0.5, 10
E, nu, K, delta = 210000.0, 0.3, 1.0e6, 0.1
n = 1 if a.single else a.leaves

# C3D20 node numbering of one brick (corner nodes 1-8, midside 9-20) in local (i, j, k) on a 2-spaced grid
corners = [(0, 0, 0), (2, 0, 0), (2, 2, 0), (0, 2, 0), (0, 0, 2), (2, 0, 2), (2, 2, 2), (0, 2, 2)]
mids = [(1, 0, 0), (2, 1, 0), (1, 2, 0), (0, 1, 0), (1, 0, 2), (2, 1, 2), (1, 2, 2), (0, 1, 2),
        (0, 0, 1), (2, 0, 1), (2, 2, 1), (0, 2, 1)]
local = corners + mids

nodes, ids = [], {}
def node(leaf, i, j, k):
    key = (leaf, i, j, k)
    if key not in ids:
        ids[key] = len(nodes) + 1
        nodes.append((ids[key], L * i / (2 * nx), b * j / 2, t * (leaf + k / 2)))
    return ids[key]

elems = []
for leaf in range(n):
    for e in range(nx):
        elems.append((leaf, e, [node(leaf, 2 * e + di, dj, dk) for di, dj, dk in local]))

with open(a.out, "w") as f:
    f.write("*HEADING\nleaf stack: %d C3D20 leaves touching exactly, tip of the top one pushed down %g\n" % (n, delta))
    f.write("*NODE\n")
    for nid, x, y, z in nodes:
        f.write("%d, %.12g, %.12g, %.12g\n" % (nid, x, y, z))
    f.write("*ELEMENT, TYPE=C3D20, ELSET=EALL\n")
    for k, (leaf, e, c) in enumerate(elems):
        f.write("%d, %s,\n%s\n" % (k + 1, ", ".join(map(str, c[:15])), ", ".join(map(str, c[15:]))))
    for leaf in range(n):
        f.write("*ELSET, ELSET=LEAF%d, GENERATE\n%d, %d, 1\n" % (leaf + 1, leaf * nx + 1, (leaf + 1) * nx))
    clamp = [i for (lf, ii, j, k), i in ids.items() if ii == 0]
    tip = [i for (lf, ii, j, k), i in ids.items() if ii == 2 * nx and lf == n - 1]
    f.write("*NSET, NSET=CLAMP\n%s\n" % ",\n".join(str(i) for i in sorted(clamp)))
    f.write("*NSET, NSET=TIP\n%s\n" % ",\n".join(str(i) for i in sorted(tip)))
    lowtip = [i for (lf, ii, j, k), i in ids.items() if ii == 2 * nx and lf == 0 and k == 0]
    f.write("*NSET, NSET=LOWTIP\n%s\n" % ",\n".join(str(i) for i in sorted(lowtip)))
    # faces: S1 is the bottom (z = 0 of the brick: nodes 1-4), S2 the top (nodes 5-8)
    for leaf in range(n):
        f.write("*SURFACE, NAME=TOP%d, TYPE=ELEMENT\nLEAF%d, S2\n" % (leaf + 1, leaf + 1))
        f.write("*SURFACE, NAME=BOT%d, TYPE=ELEMENT\nLEAF%d, S1\n" % (leaf + 1, leaf + 1))
    f.write("*MATERIAL, NAME=STEEL\n*ELASTIC\n%g, %g\n" % (E, nu))
    f.write("*SOLID SECTION, ELSET=EALL, MATERIAL=STEEL\n")
    if n > 1:
        f.write("*SURFACE INTERACTION, NAME=LEAF\n*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR\n%g\n" % K)
        for leaf in range(n - 1):
            f.write("*CONTACT PAIR, INTERACTION=LEAF, TYPE=NODE TO SURFACE\nBOT%d, TOP%d\n" % (leaf + 2, leaf + 1))
    f.write("*BOUNDARY\nCLAMP, 1, 3\n")
    f.write("*STEP, INC=200%s\n" % (", EXTRAPOLATION=" + a.extrapolation if a.extrapolation else ""))
    if a.field:
        f.write("*CONTROLS, PARAMETERS=FIELD\n0.005, 0.01\n")
    f.write("*STATIC\n0.01, 1.0\n")
    f.write("*BOUNDARY\nTIP, 3, 3, %g\n" % -delta)
    f.write("*NODE PRINT, NSET=CLAMP, TOTALS=ONLY\nRF\n*NODE PRINT, NSET=LOWTIP\nU\n*END STEP\n")
