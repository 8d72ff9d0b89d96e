"""Tiny decks, one per element family and a few mixed meshes, for the readers' test (check_readers.py).

Each deck is two elements sharing a face (an edge in 2D), their midside nodes shared, with one steady coupled
step in two increments: displacements held, theta = 10 + 100 x prescribed at every node (ramped from 0: half of
it at t = 0.5), so that frame t holds t (10 + 100 x) and, as every family reproduces a linear field,
HFL = (-100 t k, 0, 0) in every element, k = 2. The deck's element list
is written next to it (<name>.cells: "family measure n1 n2 ..." per element, in id order, the measure its area
or volume), so that the check knows what the readers should find without parsing the deck.

usage: make_family_decks.py OUTDIR  (writes OUTDIR/<name>.inp and OUTDIR/<name>.cells for every name in DECKS)
"""
import os
import sys

# Edges that carry the midside nodes of each quadratic family, in the dialect's node order (corner indices).
MIDSIDE = {
    "tri6": [(0, 1), (1, 2), (2, 0)],
    "quad8": [(0, 1), (1, 2), (2, 3), (3, 0)],
    "tet10": [(0, 1), (1, 2), (2, 0), (0, 3), (1, 3), (2, 3)],
    "wedge15": [(0, 1), (1, 2), (2, 0), (3, 4), (4, 5), (5, 3), (0, 3), (1, 4), (2, 5)],
    "hex20": [(0, 1), (1, 2), (2, 3), (3, 0), (4, 5), (5, 6), (6, 7), (7, 4), (0, 4), (1, 5), (2, 6), (3, 7)],
}
LINEAR = {"tri6": "tri3", "quad8": "quad4", "tet10": "tet4", "wedge15": "wedge6", "hex20": "hex8"}
ELEMENT = {"tri3": "CPE3T", "tri6": "CPE6MT", "quad4": "CPE4T", "quad8": "CPE8T", "tet4": "C3D4T", "tet10": "C3D10T",
           "wedge6": "C3D6T", "wedge15": "C3D15", "hex8": "C3D8T", "hex20": "C3D20T"}


def square(x0):
    return [(x0, 0), (x0 + 1, 0), (x0 + 1, 1), (x0, 1)]


def cube(x0):
    return [(x0, 0, 0), (x0 + 1, 0, 0), (x0 + 1, 1, 0), (x0, 1, 0), (x0, 0, 1), (x0 + 1, 0, 1), (x0 + 1, 1, 1), (x0, 1, 1)]


def prism(tri):
    return [p + (0,) for p in tri] + [p + (1,) for p in tri]


# Corner coordinates of the two elements of each deck, (family, corners) per element, in the dialect's order
# (counter-clockwise in 2D; bottom counter-clockwise seen from above, then the top, in 3D).
TWO = {
    "tri": [("tri", [(0, 0), (1, 0), (1, 1)]), ("tri", [(0, 0), (1, 1), (0, 1)])],
    "quad": [("quad", square(0)), ("quad", square(1))],
    "tet": [("tet", [(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1)]), ("tet", [(1, 0, 0), (1, 1, 1), (0, 1, 0), (0, 0, 1)])],
    "wedge": [("wedge", prism([(0, 0), (1, 0), (1, 1)])), ("wedge", prism([(0, 0), (1, 1), (0, 1)]))],
    "hex": [("hex", cube(0)), ("hex", cube(1))],
    # mixed: a quadrilateral and a triangle sharing the edge x = 1; a brick and a wedge sharing the face x = 1
    "quadtri": [("quad", square(0)), ("tri", [(1, 0), (2, 0), (1, 1)])],
    "hexwedge": [("hex", cube(0)), ("wedge", prism([(1, 0), (2, 0), (1, 1)]))],
}
FAMILY = {"tri": ("tri3", "tri6"), "quad": ("quad4", "quad8"), "tet": ("tet4", "tet10"), "wedge": ("wedge6", "wedge15"),
          "hex": ("hex8", "hex20")}

# name: (mesh, quadratic)
DECKS = {
    "family_tri3": ("tri", False), "family_tri6": ("tri", True), "family_quad4": ("quad", False), "family_quad8": ("quad", True),
    "family_tet4": ("tet", False), "family_tet10": ("tet", True), "family_wedge6": ("wedge", False),
    "family_wedge15": ("wedge", True), "family_hex8": ("hex", False), "family_hex20": ("hex", True),
    "mixed_quad4_tri3": ("quadtri", False), "mixed_quad8_tri6": ("quadtri", True),
    "mixed_hex8_wedge6": ("hexwedge", False), "mixed_hex20_wedge15": ("hexwedge", True),
}


def measure(shape, c):
    """Area or volume of the straight-sided element of corners c (the shapes of TWO)."""
    def area(p):  # shoelace, counter-clockwise positive
        return 0.5 * sum(p[i][0] * p[(i + 1) % len(p)][1] - p[(i + 1) % len(p)][0] * p[i][1] for i in range(len(p)))
    if shape in ("tri", "quad"):
        return area(c)
    if shape == "tet":
        a, b, d, e = c
        u, v, w = [[q[k] - a[k] for k in range(3)] for q in (b, d, e)]
        return (u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0]) + u[2] * (v[0] * w[1] - v[1] * w[0])) / 6
    if shape == "wedge":
        return area(c[:3]) * (c[3][2] - c[0][2])
    return (c[6][0] - c[0][0]) * (c[6][1] - c[0][1]) * (c[6][2] - c[0][2])  # an axis-aligned brick


def build(mesh, quadratic):
    """Nodes {coordinates: id} and elements [(family, measure, [ids])]."""
    nodes, elems = {}, []

    def node(p):
        p = tuple(float(c) for c in p)
        if p not in nodes:
            nodes[p] = len(nodes) + 1
        return nodes[p]

    for shape, corners in TWO[mesh]:
        fam = FAMILY[shape][1 if quadratic else 0]
        ids = [node(c) for c in corners]
        if quadratic:
            ids += [node([(a + b) / 2 for a, b in zip(corners[i], corners[j])]) for i, j in MIDSIDE[fam]]
        elems.append((fam, measure(shape, corners), ids))
    return nodes, elems


def write(outdir, name, mesh, quadratic):
    nodes, elems = build(mesh, quadratic)
    dim = len(next(iter(nodes)))
    lines = ["*HEADING", " %s: two %s elements for the readers' test (tests/output/make_family_decks.py)" % (name, mesh), "*NODE, NSET=NALL"]
    for p, i in sorted(nodes.items(), key=lambda t: t[1]):
        lines.append("%d, %s" % (i, ", ".join("%g" % c for c in p)))
    for fam in sorted(set(e[0] for e in elems)):
        lines.append("*ELEMENT, TYPE=%s, ELSET=EALL" % ELEMENT[fam])
        for k, (f, _, ids) in enumerate(elems):
            if f == fam:
                lines.append("%d, %s" % (k + 1, ", ".join(str(i) for i in ids)))
    lines += ["*MATERIAL, NAME=M", "*ELASTIC", "1000., 0.3", "*CONDUCTIVITY", "2.", "*DENSITY", "1.", "*SPECIFIC HEAT", "1.",
              "*SOLID SECTION, ELSET=EALL, MATERIAL=M", "*STEP", "*COUPLED TEMPERATURE-DISPLACEMENT, STEADY STATE", "0.5, 1., 0.5, 0.5",
              "*BOUNDARY", "NALL, 1, %d" % dim] + ["%d, 11, 11, %.17g" % (i, 10 + 100 * p[0]) for p, i in sorted(nodes.items(), key=lambda t: t[1])]
    lines += ["*NODE OUTPUT", "NT, U", "*ELEMENT OUTPUT", "HFL", "*END STEP"]
    with open(os.path.join(outdir, name + ".inp"), "w") as f:
        f.write("\n".join(lines) + "\n")
    with open(os.path.join(outdir, name + ".cells"), "w") as f:
        for fam, size, ids in elems:
            f.write("%s %.17g %s\n" % (fam, size, " ".join(str(i) for i in ids)))


if __name__ == "__main__":
    os.makedirs(sys.argv[1], exist_ok=True)
    for name, (mesh, quadratic) in DECKS.items():
        write(sys.argv[1], name, mesh, quadratic)
