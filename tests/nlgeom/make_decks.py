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


# The disc turned through a full revolution under a pressed pad (issue 48: a case small strain cannot do). An annulus
# Ri = 0.5, Ro = 1 (NT segments around, NRD radial), its hub (the inner nodes) turned rigidly by per-node PERIODIC
# amplitudes, u = (Q(omega t) - I) X exactly (Abaqus's Fourier series: A0 = -X, A1 = X, B1 = -Y for u_x); a softer pad,
# an annular sector over 90 +- PAD_HALF degrees from Ro to Ro + PAD_H, pressed by the pressure Q_PAD on its outer face
# (held in x there), friction MU with gap heat generation. Step 1 presses with the hub held, step 2 turns the hub once.
DISC_RI, DISC_RO, DISC_NT, DISC_NR = 0.5, 1.0, 256, 4
PAD_HALF, PAD_H, PAD_NT, PAD_NR = 4.0, 0.1, 16, 2
DISC_E, PAD_E, Q_PAD, MU = 30.0e6, 3.0e6, 1.0e4, 0.1


def spin_disc(kind):
    """Implicit: step PRESS presses the pad with the hub held, step SPIN turns the hub once (displacement amplitudes).
    Explicit (ten times softer, so that the mass scaled to DT = 2e-5 stays small): the disc starts spinning (initial
    velocities omega x X, the hub's velocity amplitudes on total time, so nothing starts with a jerk) while step PRESS
    ramps the pressure smoothly over 0.2 of its 0.25; step SPIN is the full revolution under the constant pressure."""
    explicit = kind == "explicit"
    e_disc, e_pad = (DISC_E / 10, PAD_E / 10) if explicit else (DISC_E, PAD_E)
    nt = DISC_NT
    nodes, elems, pad_elems = {}, [], []
    did = lambda i, j: 1 + j % nt + nt * i
    for i in range(DISC_NR + 1):
        r = DISC_RI + (DISC_RO - DISC_RI) * i / DISC_NR
        for j in range(nt):
            a = 2 * math.pi * j / nt
            nodes[did(i, j)] = (r * math.cos(a), r * math.sin(a))
    for i in range(DISC_NR):
        for j in range(nt):
            elems.append([did(i, j), did(i + 1, j), did(i + 1, j + 1), did(i, j + 1)])
    pid = lambda i, j: 10001 + j + (PAD_NT + 1) * i
    for i in range(PAD_NR + 1):
        r = DISC_RO + PAD_H * i / PAD_NR
        for j in range(PAD_NT + 1):
            a = math.radians(90.0 - PAD_HALF + 2 * PAD_HALF * j / PAD_NT)
            nodes[pid(i, j)] = (r * math.cos(a), r * math.sin(a))
    for i in range(PAD_NR):
        for j in range(PAD_NT):
            pad_elems.append([pid(i, j), pid(i + 1, j), pid(i + 1, j + 1), pid(i, j + 1)])
    text = ("*HEADING\n NLGEOM: a CPE4T disc turned through a full revolution under a pad pressed by %g, friction %g, %s"
            " (make_decks.py spin_disc)\n" % (Q_PAD, MU, kind))
    text += "*NODE, NSET=NALL\n" + "".join("%d, %.15g, %.15g\n" % (n, x[0], x[1]) for n, x in nodes.items())
    text += "*ELEMENT, TYPE=CPE4T, ELSET=DISC\n" + "".join("%d, %d, %d, %d, %d\n" % ((e + 1,) + tuple(c)) for e, c in enumerate(elems))
    text += "*ELEMENT, TYPE=CPE4T, ELSET=PAD\n" + "".join("%d, %d, %d, %d, %d\n" % ((5001 + e,) + tuple(c)) for e, c in enumerate(pad_elems))
    text += "*ELSET, ELSET=RIM, GENERATE\n%d, %d\n" % (1 + nt * (DISC_NR - 1), nt * DISC_NR)
    text += "*ELSET, ELSET=PADIN, GENERATE\n5001, %d\n" % (5000 + PAD_NT)
    text += "*ELSET, ELSET=PADOUT, GENERATE\n%d, %d\n" % (5001 + PAD_NT * (PAD_NR - 1), 5000 + PAD_NT * PAD_NR)
    text += nset("HUB", [did(0, j) for j in range(nt)]) + nset("PADTOP", [pid(PAD_NR, j) for j in range(PAD_NT + 1)])
    text += "*SURFACE, NAME=DISCRIM, TYPE=ELEMENT\nRIM, S2\n*SURFACE, NAME=PADFACE, TYPE=ELEMENT\nPADIN, S4\n"
    for name, e in (("STEEL", e_disc), ("SOFT", e_pad)):
        text += "*MATERIAL, NAME=%s\n*ELASTIC\n%g, 0.3\n*CONDUCTIVITY\n10.\n*DENSITY\n%g\n*SPECIFIC HEAT\n%g\n" % (
            name, e, 1.0 if explicit else 1000.0, 100.0 if explicit else 0.001)
    text += "*SOLID SECTION, ELSET=DISC, MATERIAL=STEEL\n1.\n*SOLID SECTION, ELSET=PAD, MATERIAL=SOFT\n1.\n"
    text += ("*SURFACE INTERACTION, NAME=IFACE\n*FRICTION%s\n%g\n*GAP CONDUCTANCE, PRESSURE\n20., 0.\n*GAP HEAT GENERATION\n1., 0.5\n"
             % ("" if explicit else ", LAGRANGE", MU))
    text += "*CONTACT PAIR, INTERACTION=IFACE%s\nPADFACE, DISCRIM\n" % (", MECHANICAL CONSTRAINT=KINEMATIC" if explicit else "")
    omega = 2 * math.pi  # one revolution in unit time
    for n in range(nt):
        X, Y = nodes[did(0, n)]
        # u_x = X (cos wt - 1) - Y sin wt, u_y = Y (cos wt - 1) + X sin wt (displacement); their rates (velocity)
        if explicit:
            cx, sx, cy, sy, a0x, a0y, tt = -Y * omega, -X * omega, X * omega, -Y * omega, 0.0, 0.0, ", TIME=TOTAL TIME"
        else:
            cx, sx, cy, sy, a0x, a0y, tt = X, -Y, Y, X, -X, -Y, ""
        for ax, a0, c, sn in (("X", a0x, cx, sx), ("Y", a0y, cy, sy)):
            text += "*AMPLITUDE, NAME=H%s%d, DEFINITION=PERIODIC%s\n1, %.17g, 0., %.17g\n%.17g, %.17g\n" % (ax, n, tt, omega, a0, c, sn)
    text += "*INITIAL CONDITIONS, TYPE=TEMPERATURE\nNALL, 0.\n"
    hub = lambda typ: "".join("*BOUNDARY, %sAMPLITUDE=HX%d\n%d, 1, 1, 1.\n*BOUNDARY, %sAMPLITUDE=HY%d\n%d, 2, 2, 1.\n"
                              % (typ, n, did(0, n), typ, n, did(0, n)) for n in range(nt))
    out = "*NODE OUTPUT\nU, NT, RF, CPRESS\n*ELEMENT OUTPUT\nS\n"
    if explicit:
        text += "*INITIAL CONDITIONS, TYPE=VELOCITY\n"
        for i in range(DISC_NR + 1):
            for j in range(nt):
                X, Y = nodes[did(i, j)]
                text += "%d, 1, %.17g\n%d, 2, %.17g\n" % (did(i, j), -omega * Y, did(i, j), omega * X)
        text += "*AMPLITUDE, NAME=RAMP, DEFINITION=SMOOTH STEP\n0., 0., 0.2, 1.\n"
        text += "*STEP, NAME=PRESS\n*DYNAMIC TEMPERATURE-DISPLACEMENT, EXPLICIT\n, 0.25\n*FIXED MASS SCALING, DT=2e-5\n"
        text += "*BOUNDARY\nPADTOP, 1, 1\n" + hub("TYPE=VELOCITY, ") + "*DLOAD, AMPLITUDE=RAMP\nPADOUT, P2, %g\n" % Q_PAD
        text += "*OUTPUT, FIELD, NUMBER INTERVAL=1\n" + out + "*END STEP\n"
        text += "*STEP, NAME=SPIN\n*DYNAMIC TEMPERATURE-DISPLACEMENT, EXPLICIT\n, 1.\n*FIXED MASS SCALING, DT=2e-5\n"
        text += "*OUTPUT, FIELD, NUMBER INTERVAL=8\n"
    else:
        text += "*STEP, NAME=PRESS, NLGEOM, INC=100\n*COUPLED TEMPERATURE-DISPLACEMENT\n0.25, 1.\n"
        text += "*BOUNDARY\nHUB, 1, 2\nPADTOP, 1, 1\n*DLOAD\nPADOUT, P2, %g\n*END STEP\n" % Q_PAD
        text += "*STEP, NAME=SPIN, INC=1000\n*COUPLED TEMPERATURE-DISPLACEMENT\n%.17g, 1., 1e-6, %.17g\n*OUTPUT, FIELD, NUMBER INTERVAL=8\n" % (1 / 180, 1 / 180)
        text += hub("")
    text += out + "*END STEP\n"
    write("spin_disc_" + kind, text)

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
spin_disc("implicit")
spin_disc("explicit")
