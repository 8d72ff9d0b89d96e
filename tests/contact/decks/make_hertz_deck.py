#!/usr/bin/python3
"""Writes the Hertz line-contact deck (tests/contact/decks/contact_hertz_s2s_cpe8t.inp): a steel punch whose
contact face is a circular arc of radius R = 50 pressed into a steel block, plane strain CPE8 (read as CPE8T
under *STATIC), half model (y >= 0, symmetry at y = 0), surface to surface with a linear pressure-overclosure
law, touching at one point (x = 30, y = 0) at the start, the punch's top driven by -DELTA in x in one *STATIC
step. Hertz needs only the gap's profile near the contact, y^2 / (2 R), and bodies large against the contact
width: the punch is the block x in [30 + f(y), 50], y in [0, 20] with f(y) = R - sqrt(R^2 - y^2) (not a whole
cylinder), the block [0, 30] x [0, 30]; both meshes graded towards the contact point (first element 0.1 mm,
growing geometrically). The deck's *CONTROLS line (when --controls is given) sets the increment controller.
usage: make_hertz_deck.py OUTDIR [--controls] [--delta D] [--name NAME]
"""
import math
import sys

R, HB, WB, DP, WP = 50.0, 30.0, 30.0, 20.0, 20.0
E, NU, K = 210000.0, 0.3, 1.0e7


def graded(length, n, first):
    """n intervals over [0, length], the first of size `first`, growing by a constant ratio."""
    lo, hi = 1.0 + 1e-9, 2.0
    for _ in range(200):
        r = 0.5 * (lo + hi)
        if first * (r**n - 1) / (r - 1) > length:
            hi = r
        else:
            lo = r
    x = [0.0]
    for k in range(n):
        x.append(x[-1] + first * r**k)
    return [length * v / x[-1] for v in x]


def quadratic(points):
    """The corner coordinates with midpoints between them (the CPE8 node lines)."""
    out = []
    for a, b in zip(points[:-1], points[1:]):
        out += [a, 0.5 * (a + b)]
    return out + [points[-1]]


def body(xy, nx, ny, nid0, eid0, nodes, elems):
    """A structured CPE8 mesh of (2 nx + 1) x (2 ny + 1) node lines, xy(i, j) the node at line (i, j)."""
    nid = {}
    for j in range(2 * ny + 1):
        for i in range(2 * nx + 1):
            if i % 2 and j % 2:
                continue
            nid[i, j] = nid0 + len(nid) + 1
            nodes.append((nid[i, j],) + xy(i, j))
    ids = {}
    for j in range(ny):
        for i in range(nx):
            c = [(2 * i, 2 * j), (2 * i + 2, 2 * j), (2 * i + 2, 2 * j + 2), (2 * i, 2 * j + 2)]
            m = [(2 * i + 1, 2 * j), (2 * i + 2, 2 * j + 1), (2 * i + 1, 2 * j + 2), (2 * i, 2 * j + 1)]
            ids[i, j] = eid0 + len(ids) + 1
            elems.append((ids[i, j], [nid[p] for p in c + m]))
    return nid, ids


def main():
    out = sys.argv[1]
    controls = "--controls" in sys.argv
    delta = float(sys.argv[sys.argv.index("--delta") + 1]) if "--delta" in sys.argv else 0.04
    name = sys.argv[sys.argv.index("--name") + 1] if "--name" in sys.argv else "contact_hertz_s2s_cpe8t"
    nodes, belems, pelems = [], [], []
    # block: x from 0 to HB (graded towards the contact face x = HB), y from 0 (graded towards y = 0)
    bx = quadratic([HB - v for v in reversed(graded(HB, 14, 0.12))])
    by = quadratic(graded(WB, 22, 0.1))
    bn, be = body(lambda i, j: (bx[i], by[j]), 14, 22, 0, 0, nodes, belems)
    # punch: x from the arc HB + f(y) to HB + DP, graded towards the arc
    px = quadratic(graded(1.0, 12, 0.1 / DP))
    py = quadratic(graded(WP, 22, 0.1))

    def pxy(i, j):
        y = py[j]
        f = R - math.sqrt(R * R - y * y)
        return (HB + f + px[i] * (DP - f), y)

    pn, pe = body(pxy, 12, 22, 10000, 1000, nodes, pelems)
    L = []
    w = L.append
    w("*HEADING")
    w(" Hertz line contact (own deck): an arc of radius %g pressed into a block, CPE8, surface to surface, linear" % R)
    w(" pressure-overclosure %g; half model; written by tests/contact/decks/make_hertz_deck.py" % K)
    w("*NODE, NSET=NALL")
    for n in nodes:
        w(" %d, %.15g, %.15g" % n)
    for tag, el in (("BLOCK", belems), ("PUNCH", pelems)):
        w("*ELEMENT, TYPE=CPE8, ELSET=%s" % tag)
        for e, c in el:
            w(" %d, %s" % (e, ", ".join(str(v) for v in c)))
    w("*ELSET, ELSET=EALL")
    w(" BLOCK, PUNCH")

    def nset(label, ids):
        w("*NSET, NSET=%s" % label)
        for k in range(0, len(ids), 12):
            w(" " + ", ".join(str(v) for v in ids[k : k + 12]))

    def elset(label, ids):
        w("*ELSET, ELSET=%s" % label)
        for k in range(0, len(ids), 12):
            w(" " + ", ".join(str(v) for v in ids[k : k + 12]))

    nset("SUPPORT", [bn[0, j] for j in range(2 * 22 + 1)])
    nset("SYMMETRY", [bn[i, 0] for i in range(2 * 14 + 1)] + [pn[i, 0] for i in range(2 * 12 + 1)])
    nset("TOP", [pn[2 * 12, j] for j in range(2 * 22 + 1)])
    elset("BLOCKFACE", [be[13, j] for j in range(22)])
    elset("PUNCHFACE", [pe[0, j] for j in range(22)])
    w("*SURFACE, NAME=SBLOCK, TYPE=ELEMENT")
    w(" BLOCKFACE, S2")
    w("*SURFACE, NAME=SPUNCH, TYPE=ELEMENT")
    w(" PUNCHFACE, S4")
    w("*MATERIAL, NAME=STEEL")
    w("*ELASTIC")
    w(" %g, %g" % (E, NU))
    w("*SOLID SECTION, ELSET=EALL, MATERIAL=STEEL")
    w("*SURFACE INTERACTION, NAME=CONTACT")
    w("*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR")
    w(" %g" % K)
    w("*CONTACT PAIR, INTERACTION=CONTACT, TYPE=SURFACE TO SURFACE")
    w(" SPUNCH, SBLOCK")
    w("*BOUNDARY")
    w(" SUPPORT, 1, 1")
    w(" SYMMETRY, 2, 2")
    w("*STEP, NAME=PRESS, INC=100")
    if controls:
        # the dialect's increment controls: grow by 2 after two increments of at most 4 iterations (raised by 12
        # for surface-to-surface contact: the field is blank), at most 6 cutbacks of an increment
        w("*CONTROLS, PARAMETERS=TIME INCREMENTATION")
        w(" 4, 8, 9, 16, 10, , , 6")
        w(" 0.25, 0.5, 0.75, 0.85, , , 2.0")
    w("*STATIC")
    w(" %s" % ("0.05, 1." if controls else "1., 1."))
    w("*BOUNDARY")
    w(" TOP, 1, 1, %g" % -delta)
    w("*END STEP")
    with open("%s/%s.inp" % (out, name), "w") as f:
        f.write("\n".join(L) + "\n")


main()
