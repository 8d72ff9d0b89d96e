#!/usr/bin/python3
"""Writes the finite-strain (NLGEOM) decks of decks/ (checked by check.py; tests/nlgeom/CMakeLists.txt):

turn_{c3d8t,cps4t,cgax4t}  a free block (or ring) heated uniformly by alpha dT = 0.2 in its first step and turned
          rigidly about an axis through the origin by 45 degrees a step through 360 (8 steps; NLGEOM on the first only,
          inherited by the rest): three corners (two in the plane) prescribed at x = 1.2 Q X, the ring's phi at one
          node (and u_z there), every temperature by *BOUNDARY dof 11
homog_c3d8t  one C3D8T cube with every node prescribed: simple shear to gamma = 1, then a general F0, then Q F0 (Q 90
          degrees about (1, 2, 3))
uniaxial_{c3d8t,c3d8rht,cps4t}  a 2 x 1 x 1 bar on symmetry supports pulled to twice its length (x = 2 -> 4) in 20 increments
compress_cps4t  the CPS4T bar compressed to 0.7 of its length asked in one increment: the first iterate turns the end
          element (0.5 long, its end moved by 0.6) inside out, and the increment is cut back
pressure_{c3d8t,cpe4t,cax4t}  a unit block (ring) on symmetry supports pressed by a follower pressure p = 2e4 (E = 2e5): the
          Cauchy stress -p along the load on the deformed face
spin_{c3d8t,cpe4t}  a free block spinning about z (initial velocities omega x X), explicit with NLGEOM, through a quarter
          turn
jacobian_{c3d8t,cgax4rht}  distorted elements at a finite deformation (pressure, flux, film, twist) for -snes_test_jacobian

usage: make_decks.py [OUTDIR]  (default: decks/ beside this script)"""
import math
import os
import sys

OUT = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(os.path.abspath(__file__)), "decks")
E, NU, ALPHA, THETA0, DT = 2.0e5, 0.3, 1.0e-3, 20.0, 200.0  # alpha dT = 0.2
S = 1 + ALPHA * DT
AXIS = (1 / math.sqrt(14), 2 / math.sqrt(14), 3 / math.sqrt(14))


def rotation(angle, axis=(0.0, 0.0, 1.0)):
    c, s, n = math.cos(angle), math.sin(angle), axis
    k = [[0, -n[2], n[1]], [n[2], 0, -n[0]], [-n[1], n[0], 0]]
    return [[c * (i == j) + s * k[i][j] + (1 - c) * n[i] * n[j] for j in range(3)] for i in range(3)]


def material(e=E, alpha=ALPHA):
    return ("*MATERIAL, NAME=M\n*ELASTIC\n%g, %g\n*CONDUCTIVITY\n10.\n*DENSITY\n1.\n*SPECIFIC HEAT\n1.\n*EXPANSION\n%g\n"
            % (e, NU, alpha))


def section(etype):
    """The section: a thickness line for the plane types only."""
    return "*SOLID SECTION, ELSET=EALL, MATERIAL=M\n" + ("1.\n" if etype.startswith(("CPS", "CPE")) else "")


def grid(nx, ny, nz, lx, ly, lz, x0=(0.0, 0.0, 0.0)):
    """Nodes (id: (x, y, z)) and brick connectivity (or quads when nz = 0) of a structured block."""
    nodes, elems = {}, []
    nid = lambda i, j, k: 1 + i + (nx + 1) * (j + (ny + 1) * k)
    for k in range(nz + 1):
        for j in range(ny + 1):
            for i in range(nx + 1):
                nodes[nid(i, j, k)] = (x0[0] + lx * i / nx, x0[1] + ly * j / ny, x0[2] + (lz * k / nz if nz else 0.0))
    for k in range(max(nz, 1)):
        for j in range(ny):
            for i in range(nx):
                if nz:
                    elems.append([nid(i, j, k), nid(i + 1, j, k), nid(i + 1, j + 1, k), nid(i, j + 1, k), nid(i, j, k + 1),
                                  nid(i + 1, j, k + 1), nid(i + 1, j + 1, k + 1), nid(i, j + 1, k + 1)])
                else:
                    elems.append([nid(i, j, 0), nid(i + 1, j, 0), nid(i + 1, j + 1, 0), nid(i, j + 1, 0)])
    return nodes, elems


def mesh(nodes, elems, etype, dim):
    out = "*NODE, NSET=NALL\n"
    for n, x in nodes.items():
        out += "%d, %s\n" % (n, ", ".join("%.15g" % v for v in x[:dim]))
    out += "*ELEMENT, TYPE=%s, ELSET=EALL\n" % etype
    for e, conn in enumerate(elems):
        out += "%d, %s\n" % (e + 1, ", ".join(str(c) for c in conn))
    return out


def nset(name, ids):
    return "*NSET, NSET=%s\n%s\n" % (name, "\n".join(", ".join(str(i) for i in ids[k:k + 12]) for k in range(0, len(ids), 12)))


def write(name, text):
    os.makedirs(OUT, exist_ok=True)
    with open(os.path.join(OUT, name + ".inp"), "w") as f:
        f.write(text)


def turn(etype):
    plane, ring = etype.startswith("CPS"), etype.startswith("CGAX")
    dim = 2 if plane or ring else 3
    nodes, elems = grid(2, 2, 0 if dim == 2 else 2, 1.0, 1.0, 1.0, (1.0, 0.0, 0.0) if ring else (0.0, 0.0, 0.0))
    text = "*HEADING\n NLGEOM: a free %s body heated by alpha dT = 0.2 and turned by 45 degrees a step (make_decks.py turn)\n" % etype
    text += mesh(nodes, elems, etype, dim) + material()
    text += section(etype)
    text += "*INITIAL CONDITIONS, TYPE=TEMPERATURE\nNALL, %g\n" % THETA0
    for k in range(1, 9):
        angle = math.radians(45 * k)
        text += "*STEP, NAME=TURN%d%s, INC=100\n*COUPLED TEMPERATURE-DISPLACEMENT, STEADY STATE\n0.25, 1.\n*BOUNDARY\n" % (k, ", NLGEOM" if k == 1 else "")
        if k == 1:
            text += "NALL, 11, 11, %g\n" % (THETA0 + DT)
        if ring:  # phi and u_z at the node (1, 0); the radius expands freely
            text += "1, 2, 2, 0.\n1, 5, 5, %.15g\n" % angle
        else:
            Q = rotation(angle, AXIS if dim == 3 else (0.0, 0.0, 1.0))
            held = [1, 3] if dim == 2 else [1, 3, 7]  # (0,0,0), (1,0,0) and (0,1,0) in 3D
            for n in held:
                X = nodes[n]
                for i in range(dim):
                    text += "%d, %d, %d, %.15g\n" % (n, i + 1, i + 1, S * sum(Q[i][j] * X[j] for j in range(3)) - X[i])
        text += "*END STEP\n"
    write("turn_" + etype.lower(), text)


F0 = [[1.12, 0.06, 0.02], [-0.04, 0.93, 0.05], [0.03, -0.02, 1.05]]


def homog():
    nodes, elems = grid(1, 1, 1, 1.0, 1.0, 1.0)
    text = "*HEADING\n NLGEOM: one C3D8T cube with every node prescribed (make_decks.py homog)\n" + mesh(nodes, elems, "C3D8T", 3) + material()
    text += section("C3D8T") + "*INITIAL CONDITIONS, TYPE=TEMPERATURE\nNALL, %g\n" % THETA0
    Q = rotation(math.pi / 2, AXIS)
    QF0 = [[sum(Q[i][k] * F0[k][j] for k in range(3)) for j in range(3)] for i in range(3)]
    for name, F in (("SHEAR", [[1, 1, 0], [0, 1, 0], [0, 0, 1]]), ("F0", F0), ("QF0", QF0)):
        text += "*STEP, NAME=%s, NLGEOM\n*STATIC\n0.5, 1.\n*ELEMENT OUTPUT\nS, E, LE\n*BOUNDARY\n" % name
        for n, X in nodes.items():
            for i in range(3):
                text += "%d, %d, %d, %.15g\n" % (n, i + 1, i + 1, sum(F[i][j] * X[j] for j in range(3)) - X[i])
        text += "*END STEP\n"
    write("homog_c3d8t", text)


def supports(nodes, dim, axi=False):
    """Symmetry supports: x = 0 (not for a ring), y = 0, z = 0."""
    sets = ""
    names = []
    for d, nm in enumerate("XYZ"[:dim]):
        if axi and d == 0:
            continue
        ids = [n for n, x in nodes.items() if abs(x[d] - (1.0 if axi and d == 0 else 0.0)) < 1e-12]
        sets += nset("SYM" + nm, ids)
        names.append(("SYM" + nm, d + 1))
    return sets, names


def uniaxial(etype, stretch=2.0, first=0.05, name="uniaxial"):
    dim = 2 if etype.startswith("CP") else 3
    nodes, elems = grid(4, 2, 0 if dim == 2 else 2, 2.0, 1.0, 1.0)
    sets, sym = supports(nodes, dim)
    end = [n for n, x in nodes.items() if abs(x[0] - 2.0) < 1e-12]
    text = "*HEADING\n NLGEOM: a %s bar taken to %g times its length (make_decks.py uniaxial)\n" % (etype, stretch)
    text += mesh(nodes, elems, etype, dim) + sets + nset("END", end) + material() + section(etype)
    text += "*STEP, NLGEOM, INC=100\n*STATIC\n%g, 1.\n*BOUNDARY\n" % first
    text += "".join("%s, %d, %d\n" % (nm, d, d) for nm, d in sym) + "END, 1, 1, %.15g\n*END STEP\n" % (2.0 * (stretch - 1))
    write(name + "_" + etype.lower(), text)


def pressure(etype):
    axi, dim = etype.startswith("CAX"), 2 if etype.startswith(("CPE", "CAX")) else 3
    nodes, elems = grid(2, 2, 0 if dim == 2 else 2, 1.0, 1.0, 1.0, (1.0, 0.0, 0.0) if axi else (0.0, 0.0, 0.0))
    sets, sym = supports(nodes, dim, axi)
    # the loaded face: x = 1 (the ring: its top z = 1, face 3 of a quad, the bricks' face 4 at x = 1, the quads' face 2)
    if axi:
        loaded = [e + 1 for e, c in enumerate(elems) if all(abs(nodes[c[k]][1] - 1.0) < 1e-12 for k in (2, 3))]
        face = "P3"
    else:
        loaded = [e + 1 for e, c in enumerate(elems) if all(abs(nodes[c[k]][0] - 1.0) < 1e-12 for k in (1, 2))]
        face = "P2" if dim == 2 else "P4"
    text = "*HEADING\n NLGEOM: a %s block pressed by a follower pressure (make_decks.py pressure)\n" % etype
    text += mesh(nodes, elems, etype, dim) + sets + material()
    text += "*ELSET, ELSET=LOADED\n%s\n" % ", ".join(str(e) for e in loaded)
    text += section(etype)
    text += "*STEP, NLGEOM, INC=100\n*STATIC\n0.25, 1.\n*BOUNDARY\n" + "".join("%s, %d, %d\n" % (nm, d, d) for nm, d in sym)
    text += "*DLOAD\nLOADED, %s, 2.e4\n*END STEP\n" % face
    write("pressure_" + etype.lower(), text)


def jacobian(etype):
    ring = etype.startswith("CGAX")
    dim = 2 if ring else 3
    nodes, elems = grid(2, 1, 0 if ring else 1, 1.0, 1.0, 1.0, (1.0, 0.0, 0.0) if ring else (0.0, 0.0, 0.0))
    for n, x in nodes.items():  # distorted
        nodes[n] = tuple(v + 0.04 * math.sin(3.1 * n + 1.3 * d) for d, v in enumerate(x))
    bottom = [n for n, x in nodes.items() if abs(x[1]) < 0.1] if ring else [n for n, x in nodes.items() if abs(x[2]) < 0.1]
    text = "*HEADING\n NLGEOM: distorted %s elements at a finite deformation for -snes_test_jacobian (make_decks.py jacobian)\n" % etype
    text += mesh(nodes, elems, etype, dim) + nset("BOTTOM", bottom)
    text += material(1000.0, 0.01) + section(etype) + "*INITIAL CONDITIONS, TYPE=TEMPERATURE\nNALL, 20.\n"
    text += "*STEP, NLGEOM, INC=20\n*COUPLED TEMPERATURE-DISPLACEMENT\n0.5, 1.\n*BOUNDARY\nBOTTOM, 1, %d\n" % (2 if ring else 3)
    if ring:
        text += "BOTTOM, 5, 5\n%d, 5, 5, 0.3\n" % max(nodes)
    text += "*DLOAD\n2, P3, 100.\n*DFLUX\n1, S%d, 50.\n*FILM\n2, F%d, 0., 10.\n*END STEP\n" % ((3, 2) if ring else (2, 4))
    write("jacobian_" + etype.lower(), text)


OMEGA = 5.0  # rad/s: 1e-2 of c / L (c = 519 for E = 2e5, rho = 1, L = 1): the centrifugal strain rho omega^2 L^2 / E = 1.2e-4


def spin(etype):
    dim = 2 if etype.startswith("CP") else 3
    nodes, elems = grid(2, 2, 0 if dim == 2 else 2, 1.0, 1.0, 1.0, (-0.5, -0.5, -0.5 if dim == 3 else 0.0))
    text = "*HEADING\n NLGEOM: a free %s block spinning about z at %g rad/s, explicit, through a quarter turn (make_decks.py spin)\n" % (etype, OMEGA)
    text += mesh(nodes, elems, etype, dim) + material() + section(etype)
    text += "*INITIAL CONDITIONS, TYPE=TEMPERATURE\nNALL, %g\n*INITIAL CONDITIONS, TYPE=VELOCITY\n" % THETA0
    for n, X in nodes.items():
        text += "%d, 1, %.15g\n%d, 2, %.15g\n" % (n, -OMEGA * X[1], n, OMEGA * X[0])
    text += "*STEP, NLGEOM\n*DYNAMIC TEMPERATURE-DISPLACEMENT, EXPLICIT\n, %.15g\n" % (math.pi / 2 / OMEGA)
    text += "*OUTPUT, FIELD, NUMBER INTERVAL=4\n*NODE OUTPUT\nU, NT\n*ELEMENT OUTPUT\nS, E\n*END STEP\n"
    write("spin_" + etype.lower(), text)


for t in ("C3D8T", "CPS4T", "CGAX4T"):
    turn(t)
for t in ("C3D8T", "CPE4T"):
    spin(t)
homog()
for t in ("C3D8T", "C3D8RHT", "CPS4T"):
    uniaxial(t)
uniaxial("CPS4T", 0.7, 1.0, "compress")  # in one increment: the end element turned inside out, then cut back
for t in ("C3D8T", "CPE4T", "CAX4T"):
    pressure(t)
for t in ("C3D8T", "CGAX4RHT"):
    jacobian(t)
