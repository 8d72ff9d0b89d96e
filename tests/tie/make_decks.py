#!/usr/bin/python3
"""Writes the tie decks of tests/tie/decks (run it from anywhere; the decks are committed).

Two blocks side by side, [0, 1] and [1, 2] in x (2D: x, y; 3D: x, y, z in [0, 1]), meshed differently across
their common face x = 1 (block A na elements across it, block B nb), the face of B tied to that of A, and every
outer boundary node given the linear displacement U(x) and temperature T(x) of FIELD below (patch decks) or the
explicit bar's loads (bar decks). Node ids: block A from 1, block B from 10001; elements from 1 and 1001.
"""
import os

HERE = os.path.dirname(os.path.abspath(__file__))
OUT = os.path.join(HERE, "decks")

# the linear fields of the patch tests (check_tie.py has the same numbers)
UX = (1e-3, 0.5e-3, -0.2e-3)  # u_x = a . x
UY = (0.3e-3, -0.7e-3, 0.4e-3)
UZ = (-0.1e-3, 0.2e-3, 0.6e-3)
TH = (20.0, 10.0, 5.0, -3.0)  # theta = t0 + g . x


# axisymmetric: u_r = a r, u_z = d z (a uniform stress with sigma_rr = sigma_thth and no shear, which equilibrium
# about the axis needs) and theta = t0 + g z (a gradient in r is not harmonic there)
UXA, UYA, THA = (1e-3, 0.0), (0.0, -0.7e-3), (20.0, 0.0, 5.0)


# uniaxial stress along x (the tet deck): no traction on the faces y, z = 0, 1 and no flux through them
UNI = ((1e-3, 0.0, 0.0), (0.0, -0.3e-3, 0.0), (0.0, 0.0, -0.3e-3))
THU = (20.0, 10.0, 0.0, 0.0)


def ux(p, axi=False, uni=False):
    return [sum(c * x for c, x in zip(U, p)) for U in (UNI if uni else (UXA, UYA) if axi else (UX, UY, UZ))[: len(p)]]


def theta(p, axi=False, uni=False):
    T = THU if uni else THA if axi else TH
    return T[0] + sum(g * x for g, x in zip(T[1:], p))


def block2d(x0, nx, ny, quad, n0, e0):
    """Nodes and elements of [x0, x0 + 1] x [0, 1] with nx x ny elements (CPE4T or CPE8T numbering)."""
    nodes, elems = {}, []
    # a grid of 2 nx + 1 by 2 ny + 1 points; linear elements use the even ones
    k = 2 if quad else 1
    ids = {}
    for j in range(k * ny + 1):
        for i in range(k * nx + 1):
            if quad and i % 2 and j % 2:
                continue
            nid = n0 + len(ids)
            ids[i, j] = nid
            nodes[nid] = (x0 + i / (k * nx), j / (k * ny))
    for j in range(ny):
        for i in range(nx):
            a, b = k * i, k * j
            c = [ids[a, b], ids[a + k, b], ids[a + k, b + k], ids[a, b + k]]
            if quad:
                c += [ids[a + 1, b], ids[a + 2, b + 1], ids[a + 1, b + 2], ids[a, b + 1]]
            elems.append((e0 + len(elems), c, i, j))
    return nodes, elems


def block3d(x0, nx, ny, nz, n0, e0):
    nodes, elems, ids = {}, [], {}
    for k in range(nz + 1):
        for j in range(ny + 1):
            for i in range(nx + 1):
                nid = n0 + len(ids)
                ids[i, j, k] = nid
                nodes[nid] = (x0 + i / nx, j / ny, k / nz)
    for k in range(nz):
        for j in range(ny):
            for i in range(nx):
                c = [ids[i, j, k], ids[i + 1, j, k], ids[i + 1, j + 1, k], ids[i, j + 1, k],
                     ids[i, j, k + 1], ids[i + 1, j, k + 1], ids[i + 1, j + 1, k + 1], ids[i, j + 1, k + 1]]
                elems.append((e0 + len(elems), c, i, j, k))
    return nodes, elems


MATERIAL = """*MATERIAL, NAME=STEEL
*ELASTIC
200000., 0.3
*CONDUCTIVITY
50.
*DENSITY
7.8e-9
*SPECIFIC HEAT
5.e5
"""


def write(name, text):
    with open(os.path.join(OUT, name), "w") as f:
        f.write(text)


def lines(items, per=8):
    items = [str(i) for i in items]
    return "".join(", ".join(items[i:i + per]) + "\n" for i in range(0, len(items), per))


def mesh_text(etype, nodes, elemsA, elemsB):
    s = "*NODE, NSET=NALL\n" + "".join("%d, %.17g, %s\n" % (n, p[0], ", ".join("%.17g" % c for c in p[1:])) for n, p in sorted(nodes.items()))
    s += "*ELEMENT, TYPE=%s, ELSET=A\n" % etype + "".join("%d, %s\n" % (e[0], ", ".join(map(str, e[1]))) for e in elemsA)
    s += "*ELEMENT, TYPE=%s, ELSET=B\n" % etype + "".join("%d, %s\n" % (e[0], ", ".join(map(str, e[1]))) for e in elemsB)
    s += "*SOLID SECTION, ELSET=A, MATERIAL=STEEL\n*SOLID SECTION, ELSET=B, MATERIAL=STEEL\n" + MATERIAL
    return s


def patch2d(quad, na, nb, tie_text, name, title, axi=False):
    etype = ("CAX8T" if quad else "CAX4T") if axi else ("CPE8T" if quad else "CPE4T")
    nA, eA = block2d(0.0, 2, na, quad, 1, 1)
    nB, eB = block2d(1.0, 2, nb, quad, 10001, 1001)
    nodes = {**nA, **nB}
    # interface faces: A's elements at i = 1 face 2 (x = 1), B's at i = 0 face 4 (x = 1)
    sA = [(e[0], "S2") for e in eA if e[2] == 1]
    sB = [(e[0], "S4") for e in eB if e[2] == 0]
    outer = [n for n, p in sorted(nodes.items()) if p[0] in (0.0, 2.0) or p[1] in (0.0, 1.0)]
    s = "*HEADING\n%s\n" % title + mesh_text(etype, nodes, eA, eB)
    s += "*SURFACE, NAME=SA, TYPE=ELEMENT\n" + "".join("%d, %s\n" % f for f in sA)
    s += "*SURFACE, NAME=SB, TYPE=ELEMENT\n" + "".join("%d, %s\n" % f for f in sB)
    s += tie_text
    s += "*STEP\n*COUPLED TEMPERATURE-DISPLACEMENT, STEADY STATE\n1., 1.\n*BOUNDARY\n"
    for n in outer:
        u = ux(nodes[n], axi)
        s += "%d, 1, 1, %.17g\n%d, 2, 2, %.17g\n%d, 11, 11, %.17g\n" % (n, u[0], n, u[1], n, theta(nodes[n], axi))
    s += "*NODE FILE\nU, NT, RFL\n*EL FILE\nS\n*END STEP\n"
    write(name, s)


def tie3d(nodes, sA, sB, outer, uni=False):
    """The 3D decks' surfaces, *TIE (SB to SA) and steady step with the linear fields at the outer nodes."""
    s = "*SURFACE, NAME=SA, TYPE=ELEMENT\n" + "".join("%d, %s\n" % f for f in sA)
    s += "*SURFACE, NAME=SB, TYPE=ELEMENT\n" + "".join("%d, %s\n" % f for f in sB)
    s += "*TIE, NAME=T1\nSB, SA\n"
    s += "*STEP\n*COUPLED TEMPERATURE-DISPLACEMENT, STEADY STATE\n1., 1.\n*BOUNDARY\n"
    for n in outer:
        u = ux(nodes[n], uni=uni)
        s += "".join("%d, %d, %d, %.17g\n" % (n, d + 1, d + 1, u[d]) for d in range(3)) + "%d, 11, 11, %.17g\n" % (n, theta(nodes[n], uni=uni))
    return s + "*NODE FILE\nU, NT, RFL\n*EL FILE\nS\n*END STEP\n"


def patch3d(na, nb, name):
    nA, eA = block3d(0.0, 1, na, na, 1, 1)
    nB, eB = block3d(1.0, 1, nb, nb, 10001, 1001)
    nodes = {**nA, **nB}
    sA = [(e[0], "S4") for e in eA]  # hex8 face 4: nodes 2 3 7 6 (x = 1 of A)
    sB = [(e[0], "S6") for e in eB]  # face 6: nodes 4 1 5 8 (x = 1 of B)
    outer = [n for n, p in sorted(nodes.items()) if p[0] in (0.0, 2.0) or p[1] in (0.0, 1.0) or p[2] in (0.0, 1.0)]
    s = "*HEADING\nTIE patch test, C3D8T, %d x %d elements tied to %d x %d across x = 1\n" % (nb, nb, na, na)
    s += mesh_text("C3D8T", nodes, eA, eB)
    write(name, s + tie3d(nodes, sA, sB, outer))


def block3d20(x0, n, n0, e0):
    """[x0, x0 + 1] x [0, 1]^2 in n^3 C3D20T (the dialect's node order: corners, then the midsides of 1-2, 2-3, 3-4,
    4-1, 5-6, 6-7, 7-8, 8-5, 1-5, 2-6, 3-7, 4-8)."""
    nodes, ids, elems = {}, {}, []
    for k in range(2 * n + 1):
        for j in range(2 * n + 1):
            for i in range(2 * n + 1):
                if (i % 2) + (j % 2) + (k % 2) > 1:
                    continue
                ids[i, j, k] = n0 + len(ids)
                nodes[ids[i, j, k]] = (x0 + i / (2 * n), j / (2 * n), k / (2 * n))
    cor = [(0, 0, 0), (2, 0, 0), (2, 2, 0), (0, 2, 0), (0, 0, 2), (2, 0, 2), (2, 2, 2), (0, 2, 2)]
    edges = [(0, 1), (1, 2), (2, 3), (3, 0), (4, 5), (5, 6), (6, 7), (7, 4), (0, 4), (1, 5), (2, 6), (3, 7)]
    for k in range(n):
        for j in range(n):
            for i in range(n):
                pts = cor + [tuple((cor[a][m] + cor[b][m]) // 2 for m in range(3)) for a, b in edges]
                elems.append((e0 + len(elems), [ids[2 * i + p[0], 2 * j + p[1], 2 * k + p[2]] for p in pts]))
    return nodes, elems


def patch20(name):
    """C3D20T blocks, 2 x 2 on both sides of x = 1 (matching: the quad8 faces have no dual basis, so the nodes take
    the projection, which is exact on matching faces), every outer node given the linear fields."""
    nA, eA = block3d20(0.0, 2, 1, 1)
    nB, eB = block3d20(1.0, 2, 10001, 1001)
    nodes = {**nA, **nB}
    sA = [(e[0], "S4") for e in eA if nodes[e[1][1]][0] == 1.0]
    sB = [(e[0], "S6") for e in eB if nodes[e[1][0]][0] == 1.0]
    outer = [n for n, p in sorted(nodes.items()) if p[0] in (0.0, 2.0) or p[1] in (0.0, 1.0) or p[2] in (0.0, 1.0)]
    s = "*HEADING\nTIE patch test, C3D20T, matching quad8 faces across x = 1 (projection weights)\n"
    s += mesh_text("C3D20T", nodes, eA, eB)
    write(name, s + tie3d(nodes, sA, sB, outer))


def tets3d(x0, n, n0, e0):
    """[x0, x0 + 1] x [0, 1]^2 in n^3 cubes of 6 C3D4T tetrahedra each (Kuhn's split along a main diagonal)."""
    nodes, ids, elems = {}, {}, []
    for k in range(n + 1):
        for j in range(n + 1):
            for i in range(n + 1):
                ids[i, j, k] = n0 + len(ids)
                nodes[ids[i, j, k]] = (x0 + i / n, j / n, k / n)
    paths = [(0, 1, 2), (0, 2, 1), (1, 0, 2), (1, 2, 0), (2, 0, 1), (2, 1, 0)]
    for k in range(n):
        for j in range(n):
            for i in range(n):
                for path in paths:
                    c = [0, 0, 0]
                    corners = [tuple(c)]
                    for axis in path:
                        c[axis] += 1
                        corners.append(tuple(c))
                    t = [ids[i + a, j + b, k + d] for a, b, d in corners]
                    p = [nodes[q] for q in t]
                    u = [[p[m][r] - p[0][r] for r in range(3)] for m in (1, 2, 3)]
                    vol = (u[0][0] * (u[1][1] * u[2][2] - u[1][2] * u[2][1]) - u[0][1] * (u[1][0] * u[2][2] - u[1][2] * u[2][0])
                           + u[0][2] * (u[1][0] * u[2][1] - u[1][1] * u[2][0]))
                    if vol < 0:
                        t[1], t[2] = t[2], t[1]
                    elems.append((e0 + len(elems), t))
    return nodes, elems


def patch_tets(na, nb, name):
    """Block A of na^2 C3D8T across x = 1 tied as the main surface to block B of C3D4T (nb^3 cubes split in six): the
    secondary faces are triangles (tri3) cut by the hexahedra's quadrilaterals."""
    nA, eA = block3d(0.0, 1, na, na, 1, 1)
    nB, eB = tets3d(1.0, nb, 10001, 1001)
    nodes = {**nA, **nB}
    sA = [(e[0], "S4") for e in eA]
    faces = {"S1": (0, 1, 2), "S2": (0, 3, 1), "S3": (1, 3, 2), "S4": (2, 3, 0)}
    sB = [(e[0], f) for e in eB for f, q in faces.items() if all(abs(nodes[e[1][m]][0] - 1.0) < 1e-12 for m in q)]
    # uniaxial stress along x: the secondary nodes on the outer boundary are left to the tie (their outer faces carry
    # no traction and no flux). A *BOUNDARY there would win over the tie and take their share of the interface's
    # traction to the support, which on triangles reaches the inner main nodes too (docs/keywords.md *TIE; with the
    # tensor-product faces of the other decks that share is zero)
    outer = [n for n, p in sorted(nodes.items()) if (p[0] in (0.0, 2.0) or p[1] in (0.0, 1.0) or p[2] in (0.0, 1.0)) and not (n > 10000 and p[0] == 1.0)]
    s = "*HEADING\nTIE patch test, C3D4T (tri3 faces, secondary) tied to C3D8T (%d x %d) across x = 1\n" % (na, na)
    s += "*NODE, NSET=NALL\n" + "".join("%d, %.17g, %.17g, %.17g\n" % (n, p[0], p[1], p[2]) for n, p in sorted(nodes.items()))
    s += "*ELEMENT, TYPE=C3D8T, ELSET=A\n" + "".join("%d, %s\n" % (e[0], ", ".join(map(str, e[1]))) for e in eA)
    s += "*ELEMENT, TYPE=C3D4T, ELSET=B\n" + "".join("%d, %s\n" % (e[0], ", ".join(map(str, e[1]))) for e in eB)
    s += "*SOLID SECTION, ELSET=A, MATERIAL=STEEL\n*SOLID SECTION, ELSET=B, MATERIAL=STEEL\n" + MATERIAL
    write(name, s + tie3d(nodes, sA, sB, outer, uni=True))


def bar(tied, name):
    """A bar [0, 2] x [0, 0.25] of CPE4T, 8 elements along it, 1 across; tied: the same mesh cut at x = 1, its right
    half's nodes at x = 1 (ids + 10000) tied to the left half's face. Explicit: every node starts at v_x = 100 and
    x = 0 is held, the heat: theta = 100 prescribed at x = 0 under a ramp, theta = 0 at x = 2."""
    nodes, elems = {}, []
    for i in range(9):
        for j in range(2):
            nodes[1 + 2 * i + j] = (0.25 * i, 0.25 * j)
    for j in range(2):
        if tied:
            nodes[10001 + 2 * 4 + j] = (1.0, 0.25 * j)
    for i in range(8):
        c = [1 + 2 * i, 3 + 2 * i, 4 + 2 * i, 2 + 2 * i]
        if tied and i == 4:
            c = [10009, 3 + 2 * i, 4 + 2 * i, 10010]
        elems.append((1 + i, c))
    s = "*HEADING\nExplicit bar, CPE4T, %s\n" % ("cut at x = 1 and tied" if tied else "in one piece")
    s += "*NODE, NSET=NALL\n" + "".join("%d, %.17g, %.17g\n" % (n, p[0], p[1]) for n, p in sorted(nodes.items()))
    s += "*ELEMENT, TYPE=CPE4T, ELSET=ALL\n" + "".join("%d, %s\n" % (e[0], ", ".join(map(str, e[1]))) for e in elems)
    s += "*SOLID SECTION, ELSET=ALL, MATERIAL=STEEL\n" + MATERIAL
    if tied:
        s += "*SURFACE, NAME=LEFT, TYPE=ELEMENT\n4, S2\n*SURFACE, NAME=RIGHT, TYPE=ELEMENT\n5, S4\n*TIE\nRIGHT, LEFT\n"
    s += "*NSET, NSET=END0\n1, 2\n*NSET, NSET=END2\n17, 18\n*INITIAL CONDITIONS, TYPE=TEMPERATURE\nNALL, 0.\n"
    s += "*INITIAL CONDITIONS, TYPE=VELOCITY\nNALL, 1, 100.\n"
    s += "*AMPLITUDE, NAME=RAMP\n0., 0., 5.e-5, 1.\n"
    s += "*STEP\n*DYNAMIC TEMPERATURE-DISPLACEMENT, EXPLICIT\n, 5.e-5\n*BOUNDARY\nNALL, 2, 2, 0.\nEND0, 1, 1, 0.\n"
    s += "*BOUNDARY, AMPLITUDE=RAMP\nEND0, 11, 11, 100.\n*BOUNDARY\nEND2, 11, 11, 0.\n"
    s += "*OUTPUT, FIELD, NUMBER INTERVAL=4\n*NODE OUTPUT\nU, NT\n*END STEP\n"
    write(name, s)


def steps(name_static, name_transient):
    """patch_cpe4t.inp in a *STATIC step (temperatures held at their initial values, the linear field) and in a
    transient coupled step (two increments from the linear field, which stays: the capacity terms vanish)."""
    base = open(os.path.join(OUT, "patch_cpe4t.inp")).read()
    head = "*STEP\n*COUPLED TEMPERATURE-DISPLACEMENT, STEADY STATE\n1., 1.\n"
    assert head in base
    nodes = [l.split(",") for l in base[base.index("*NODE"):base.index("*ELEMENT")].splitlines()[1:]]
    init = "*INITIAL CONDITIONS, TYPE=TEMPERATURE\n" + "".join("%s, %.17g\n" % (n[0], theta((float(n[1]), float(n[2])))) for n in nodes)
    static = base.replace(head, init + "*STEP\n*STATIC\n1., 1.\n").replace("patch test, CPE4T", "patch test in a *STATIC step, CPE4T")
    # *STATIC holds the temperatures: no *BOUNDARY on dof 11 there
    static = "".join(l + "\n" for l in static.splitlines() if not (l.count(",") == 3 and l.split(",")[1].strip() == "11"))
    write(name_static, static)
    transient = base.replace(head, init + "*STEP, INC=10\n*COUPLED TEMPERATURE-DISPLACEMENT\n0.5, 1.\n")
    write(name_transient, transient.replace("patch test, CPE4T", "patch test in a transient coupled step, CPE4T"))


def heat(name):
    """patch_cpe4t.inp's thermal problem in a *HEAT TRANSFER step (its CPE4T read as DC2D4; the displacement lines
    of its *BOUNDARY left out): the tie in a temperature-only model."""
    base = open(os.path.join(OUT, "patch_cpe4t.inp")).read()
    head = "*STEP\n*COUPLED TEMPERATURE-DISPLACEMENT, STEADY STATE\n"
    assert head in base
    model, step = base.split(head)
    step = "".join(l + "\n" for l in step.splitlines() if not (l.count(",") == 3 and l.split(",")[1].strip() in ("1", "2")))
    write(name, (model + "*STEP\n*HEAT TRANSFER, STEADY STATE\n" + step).replace("patch test, CPE4T", "patch test in a *HEAT TRANSFER step, CPE4T"))


def shared(name):
    """patch_cpe4t.inp with B's tied face split into two surfaces, each tied to A by its own *TIE: the node at
    y = 0.5 is on both and is tied by the first (docs/keywords.md *TIE); the patch test still holds."""
    base = open(os.path.join(OUT, "patch_cpe4t.inp")).read()
    i, j = base.index("*SURFACE, NAME=SB"), base.index("*TIE")
    faces = base[i:j].splitlines()[1:]
    split = "*SURFACE, NAME=SB1, TYPE=ELEMENT\n" + "".join(l + "\n" for l in faces[:2])
    split += "*SURFACE, NAME=SB2, TYPE=ELEMENT\n" + "".join(l + "\n" for l in faces[2:])
    s = base[:i] + split + "*TIE, NAME=LOWER\nSB1, SA\n*TIE, NAME=UPPER\nSB2, SA\n" + base[base.index("*STEP"):]
    write(name, s.replace("patch test, CPE4T", "patch test, two ties sharing a secondary node, CPE4T"))


def fall(name):
    """The two blocks of patch_cpe4t.inp (4 elements tied to 3) falling freely under gravity (GRAV 1e4 along
    (1, -2)) from rest in an explicit step, and heated by a uniform body flux: u = g t^2 / 2 and theta = 20 + q t / (rho c)
    at every node, exact when the tie moves the secondary nodes' mass and capacity with their force and heat, as the
    lumped T^T M T and T^T F do."""
    base = open(os.path.join(OUT, "patch_cpe4t.inp")).read()
    model = base[: base.index("*STEP")]
    s = model.replace("TIE patch test, CPE4T", "TIE free fall, explicit, CPE4T") + "*ELSET, ELSET=ALL\nA, B\n"
    s += "*INITIAL CONDITIONS, TYPE=TEMPERATURE\nNALL, 20.\n"
    s += "*STEP\n*DYNAMIC TEMPERATURE-DISPLACEMENT, EXPLICIT\n, 1.e-5\n*DLOAD\nALL, GRAV, 10000., 1., -2., 0.\n"
    s += "*DFLUX\nALL, BF, 390.\n"  # rho c = 3.9e-3: theta rises at 1e5 per unit time everywhere
    s += "*OUTPUT, FIELD, NUMBER INTERVAL=2\n*NODE OUTPUT\nU, NT\n*END STEP\n"
    write(name, s)


def bad():
    """Bad inputs: variants of patch_cpe4t.inp (check the messages in CMakeLists.txt)."""
    base = open(os.path.join(OUT, "patch_cpe4t.inp")).read()
    tie = "*TIE, NAME=T1\nSB, SA\n"
    assert tie in base
    # A's face at x = 0 as the main surface: B's nodes at x = 1 are a whole length away
    far = "*SURFACE, NAME=SA0, TYPE=ELEMENT\n" + "".join("%d, S4\n" % e for e in (1, 3, 5)) + "*TIE, NAME=T1, POSITION TOLERANCE=0.01\nSB, SA0\n"
    write("bad_tie_far.inp", base.replace(tie, far))
    write("bad_tie_undefined.inp", base.replace(tie, "*TIE, NAME=T1\nSB, NOSUCH\n"))
    write("bad_tie_two_lines.inp", base.replace(tie, "*TIE, NAME=T1\nSB, SA\nSA, SB\n"))
    write("bad_tie_cyclic.inp", base.replace(tie, "*TIE, NAME=T1, CYCLIC SYMMETRY\nSB, SA\n"))
    # each surface tied to the other: A's nodes are main nodes of the first tie and secondary of the second
    write("bad_tie_chain.inp", base.replace(tie, tie + "*TIE, NAME=T2\nSA, SB\n"))
    # node 10007 (B, on x = 1 at y = 0.25) is tied and also the dependent node of an *EQUATION
    write("bad_tie_equation.inp", base.replace(tie, tie + "*EQUATION\n2\n10007, 1, 1., 10008, 1, -1.\n"))


def main():
    os.makedirs(OUT, exist_ok=True)
    patch2d(False, 3, 4, "*TIE, NAME=T1\nSB, SA\n", "patch_cpe4t.inp", "TIE patch test, CPE4T, 4 elements tied to 3 across x = 1")
    patch2d(True, 3, 4, "*TIE, NAME=T1, POSITION TOLERANCE=1.e-6\nSB, SA\n", "patch_cpe8t.inp",
            "TIE patch test, CPE8T (line3 faces), 4 elements tied to 3 across x = 1")
    patch2d(False, 4, 3, "*SURFACE INTERACTION, NAME=GLUE\n*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=TIED\n1.e7\n"
            "*CONTACT PAIR, INTERACTION=GLUE\nSA, SB\n", "patch_overclosure_tied_cpe4t.inp",
            "PRESSURE-OVERCLOSURE=TIED patch test, CPE4T, 4 elements (main) and 3 (secondary)")
    patch2d(False, 3, 5, "*SURFACE INTERACTION, NAME=GLUE\n*CONTACT PAIR, INTERACTION=GLUE, TIED\nSB, SA\n", "patch_pair_tied_cpe4t.inp",
            "CONTACT PAIR, TIED patch test, CPE4T, 5 elements tied to 3")
    patch2d(False, 3, 4, "*TIE, NAME=T1\nSB, SA\n", "patch_cax4t.inp", "TIE patch test, CAX4T, 4 elements tied to 3 across r = 1",
            axi=True)
    patch3d(2, 3, "patch_c3d8t.inp")
    patch_tets(2, 3, "patch_c3d4t.inp")
    patch20("patch_c3d20t.inp")
    bar(False, "bar_explicit_cpe4t.inp")
    bar(True, "bar_tied_explicit_cpe4t.inp")
    steps("patch_static_cpe4t.inp", "patch_transient_cpe4t.inp")
    shared("patch_shared_cpe4t.inp")
    heat("patch_heat_cpe4t.inp")
    fall("fall_explicit_cpe4t.inp")
    bad()


main()
