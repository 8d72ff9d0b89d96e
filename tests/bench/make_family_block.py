#!/usr/bin/python3
"""Writes a steady coupled benchmark deck for any continuum type of the catalogue (docs/elements.md).

usage: make_family_block.py TYPE N out.inp

Prints "elements dofs" of the deck on stdout.

Geometry: 2D types on a 2 x 1 rectangle of 2N x N cells (x in [0, 2], y in [0, 1]; axisymmetric types:
r in [1, 3], z in [0, 1]); 3D types on a 2 x 1 x 1 block of 2N x N x N cells. A cell is one quad4/quad8 or
hex8, two tri3/tri6 (cut along its 1-3 diagonal), two wedge6 (the hex cut along the vertical plane through
its 1-3 edge) or six tet4/tet10 (Kuhn's split along the 1-7 diagonal, the same in every cell, so the
faces of neighbouring cells match). Second-order types get midside nodes from an edge dictionary, so
neighbours share them. Every element's orientation is checked (signed area or volume > 0) and fixed by
swapping two corners when negative.

Problem (as make_block.py): face x = 0 (axisymmetric: the inner face r = 1) held at theta = 100 with its
displacements fixed (and the twist, dof 5, of CGAX types), a film (h = 50, sink 0) on x = 2, a pressure
1e3 on y = 1, thermal expansion on. Generalized plane strain types get a free reference node (so the
planes expand freely out of plane).
"""
import itertools
import re
import sys

# corner faces of each family, 1-based, in the dialect's order (only the corners: enough to locate a face)
FACES = {
    "tri": [(1, 2), (2, 3), (3, 1)],
    "quad": [(1, 2), (2, 3), (3, 4), (4, 1)],
    "tet": [(1, 3, 2), (1, 2, 4), (2, 3, 4), (3, 1, 4)],
    "wedge": [(1, 3, 2), (4, 5, 6), (1, 2, 5, 4), (2, 3, 6, 5), (3, 1, 4, 6)],
    "hex": [(1, 4, 3, 2), (5, 6, 7, 8), (1, 2, 6, 5), (2, 3, 7, 6), (3, 4, 8, 7), (4, 1, 5, 8)],
}
# midside nodes of the quadratic families: the corner pair of each, in node order
MIDSIDE = {
    "tri": [(1, 2), (2, 3), (3, 1)],
    "quad": [(1, 2), (2, 3), (3, 4), (4, 1)],
    "tet": [(1, 2), (2, 3), (3, 1), (1, 4), (2, 4), (3, 4)],
}


def family(typ):
    """(shape, order, kinematics) of a type name: CPE6MT -> ("tri", 2, "PE"), C3D10MT -> ("tet", 2, "3D")."""
    m = re.match(r"C(GAX|PEG|PE|PS|AX)(\d)", typ)
    if m:
        return {"3": ("tri", 1), "4": ("quad", 1), "6": ("tri", 2), "8": ("quad", 2)}[m.group(2)] + (m.group(1),)
    m = re.match(r"C3D(\d+)", typ)
    if m:
        return {"4": ("tet", 1), "6": ("wedge", 1), "8": ("hex", 1), "10": ("tet", 2)}[m.group(1)] + ("3D",)
    sys.exit("make_family_block.py: unknown type %s" % typ)


def cells_2d(n):
    """Corner lattice points (i, j) and quad cells (counter-clockwise) of the 2N x N grid."""
    cells = [[(i, j), (i + 1, j), (i + 1, j + 1), (i, j + 1)] for j in range(n) for i in range(2 * n)]
    return cells, (lambda p: (p[0] / n, p[1] / n))


def cells_3d(n):
    cells = []
    for k in range(n):
        for j in range(n):
            for i in range(2 * n):
                b = [(i, j, k), (i + 1, j, k), (i + 1, j + 1, k), (i, j + 1, k)]
                cells.append(b + [(p[0], p[1], p[2] + 1) for p in b])
    return cells, (lambda p: (p[0] / n, p[1] / n, p[2] / n))


def split(shape, cell):
    """The linear elements (corner lattice points in the family's order) of one grid cell."""
    if shape in ("quad", "hex"):
        return [cell]
    if shape == "tri":
        c1, c2, c3, c4 = cell
        return [[c1, c2, c3], [c1, c3, c4]]
    if shape == "wedge":
        c = cell
        return [[c[0], c[1], c[2], c[4], c[5], c[6]], [c[0], c[2], c[3], c[4], c[6], c[7]]]
    # tet: Kuhn's split, one tet per order of the three axes, from the cell's lowest corner to its highest
    o = cell[0]
    tets = []
    for perm in itertools.permutations(range(3)):
        p, path = list(o), [tuple(o)]
        for ax in perm:
            p[ax] += 1
            path.append(tuple(p))
        tets.append(path)
    return tets


def signed_measure(x):
    """Signed area (2D, corners 1-2-3) or volume (3D, corners 1-2-3 and 4) of an element's corners."""
    a = [x[1][d] - x[0][d] for d in range(len(x[0]))]
    b = [x[2][d] - x[0][d] for d in range(len(x[0]))]
    if len(x[0]) == 2:
        return a[0] * b[1] - a[1] * b[0]
    c = [x[3][d] - x[0][d] for d in range(3)]
    return (a[1] * b[2] - a[2] * b[1]) * c[0] + (a[2] * b[0] - a[0] * b[2]) * c[1] + (a[0] * b[1] - a[1] * b[0]) * c[2]


def orient(shape, el, xyz):
    """Swaps two corners of an element whose signed measure is negative (tets of Kuhn's split alternate).
    The measure is taken at corner 1: its two (2D) or three (3D) edges, (1-2, 1-3, 1-4) for tri and tet,
    (1-2, 1-3, 1-4) for the wedge, (1-2, 1-4, 1-5) for the hex."""
    x = [xyz[p] for p in el]
    if shape in ("wedge", "hex"):
        x = [x[0], x[1], x[2 if shape == "wedge" else 3], x[3 if shape == "wedge" else 4]]
    s = signed_measure(x)
    assert s != 0, "degenerate element"
    if s > 0:
        return el
    if shape == "tet":
        return [el[0], el[2], el[1], el[3]]
    if shape == "wedge":
        return [el[0], el[2], el[1], el[3], el[5], el[4]]
    if shape == "hex":
        return [el[0], el[3], el[2], el[1], el[4], el[7], el[6], el[5]]
    return [el[0]] + el[1:][::-1]


def build(typ, n):
    shape, order, kin = family(typ)
    dim = 3 if kin == "3D" else 2
    cells, coord = cells_3d(n) if dim == 3 else cells_2d(n)
    shift = (1.0, 0.0) if kin in ("AX", "GAX") else (0.0,) * dim
    xyz = lambda p: tuple(c + s for c, s in zip(coord(p), shift))
    ids, nodes = {}, []   # lattice point or edge -> node id; nodes [(id, coordinates)]

    def node(key, x):
        if key not in ids:
            ids[key] = len(nodes) + 1
            nodes.append((ids[key], x))
        return ids[key]

    elems = []
    for cell in cells:
        for el in split(shape, cell):
            el = orient(shape, el, {p: xyz(p) for p in el})
            conn = [node(p, xyz(p)) for p in el]
            if order == 2:
                for a, b in MIDSIDE[shape]:
                    pa, pb = el[a - 1], el[b - 1]
                    x = tuple((u + v) / 2 for u, v in zip(xyz(pa), xyz(pb)))
                    conn.append(node(tuple(sorted((pa, pb))), x))
            elems.append(conn)
    return shape, kin, dim, nodes, elems


def faces_on(shape, elems, coords, axis, value):
    """Element faces whose corners all lie on the plane x[axis] = value: {face number: [elements]}."""
    out = {}
    for e, conn in enumerate(elems, 1):
        for f, corners in enumerate(FACES[shape], 1):
            if all(abs(coords[conn[c - 1]][axis] - value) < 1e-9 for c in corners):
                out.setdefault(f, []).append(e)
    return out


def id_lines(ids):
    return "".join(", ".join(str(x) for x in ids[a:a + 16]) + "\n" for a in range(0, len(ids), 16))


def main():
    typ, n, path = sys.argv[1].upper(), int(sys.argv[2]), sys.argv[3]
    shape, kin, dim, nodes, elems = build(typ, n)
    coords = dict(nodes)
    x0, x1 = (1.0, 3.0) if kin in ("AX", "GAX") else (0.0, 2.0)
    fixed = [i for i, x in nodes if abs(x[0] - x0) < 1e-9]
    hot = faces_on(shape, elems, coords, 0, x1)
    top = faces_on(shape, elems, coords, 1, 1.0)
    ndof = 4 if dim == 3 or kin == "GAX" else 3
    dofs = len(nodes) * ndof + (4 if kin == "PEG" else 0)
    with open(path, "w") as f:
        f.write("*HEADING\n steady coupled block, %d %s elements (N = %d), %d dofs\n*NODE, NSET=ALL\n" % (len(elems), typ, n, dofs))
        for i, x in nodes:
            f.write("%d, %s\n" % (i, ", ".join("%.12g" % c for c in x)))
        f.write("*ELEMENT, TYPE=%s, ELSET=BODY\n" % typ)
        for e, conn in enumerate(elems, 1):
            # 16 entries per data line at most; longer rows continue on the next line
            row = [e] + conn
            f.write(",\n".join(", ".join(str(v) for v in row[a:a + 16]) for a in range(0, len(row), 16)) + "\n")
        f.write("*NSET, NSET=FIXED\n" + id_lines(fixed))
        for name, sets in (("HOT", hot), ("TOP", top)):
            for face, els in sorted(sets.items()):
                f.write("*ELSET, ELSET=%s%d\n" % (name, face) + id_lines(els))
        f.write("*MATERIAL, NAME=STEEL\n*ELASTIC\n 30.0E6, 0.3\n*CONDUCTIVITY\n 10.0\n*DENSITY\n 1000.0\n*SPECIFIC HEAT\n 0.001\n"
                "*EXPANSION\n 1.0E-5\n")
        if kin == "PEG":
            ref = len(nodes) + 1
            f.write("*NODE\n %d, 1.0, 0.5\n*SOLID SECTION, ELSET=BODY, MATERIAL=STEEL, REF NODE=%d\n 1.0\n" % (ref, ref))
        else:
            f.write("*SOLID SECTION, ELSET=BODY, MATERIAL=STEEL\n%s" % (" 1.0\n" if dim == 2 else ""))
        f.write("*INITIAL CONDITIONS, TYPE=TEMPERATURE\n ALL, 0.0\n*STEP\n*COUPLED TEMPERATURE-DISPLACEMENT, STEADY STATE\n 1.0, 1.0\n")
        f.write("*BOUNDARY\n FIXED, 1, %d\n%s FIXED, 11, 11, 100.0\n" % (dim, " FIXED, 5, 5\n" if kin == "GAX" else ""))
        f.write("*FILM\n" + "".join(" HOT%d, F%d, 0.0, 50.0\n" % (face, face) for face in sorted(hot)))
        f.write("*DLOAD\n" + "".join(" TOP%d, P%d, 1000.0\n" % (face, face) for face in sorted(top)))
        f.write("*NODE OUTPUT\n U, NT\n*END STEP\n")
    print(len(elems), dofs)


if __name__ == "__main__":
    main()
