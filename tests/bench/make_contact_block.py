#!/usr/bin/python3
"""A 3D two-block contact problem for the contact benchmark (issue 7, tests/bench/bench_contact3d.sh): a
thin block (N x 1 x N hexahedra over [0.02, 0.98] in x and z, 0.1 high in y) pressed on a base block
((N+1) x 2 x (N+1) hexahedra over [0, 1] in x and z, 0.5 high) that is fixed and held at temperature 0 at
its bottom (y = 0); the thin block's top face is held at temperature 100 and in x and z, and carries a
pressure of 100. The meshes do not match across the interface: (N+1)^2 secondary nodes (the thin block's
bottom) against (N+1)^2 main faces (the base's top). Gap conductance against the contact pressure. One
steady coupled increment.
usage: make_contact_block.py N deck.inp [thermoslide|s2s|calculix|explicit INCREMENTS [C3D8T|C3D8RT]]
  thermoslide: C3D8T, node-to-surface (the default pair type), penalty contact with the stiffness 0.1 E / h
               (h the main face size), *GAP CONDUCTANCE, PRESSURE;
  s2s:         the same with TYPE=SURFACE TO SURFACE (contact at the overlap's integration points, as
               CalculiX's face-to-face pair below);
  calculix:    the same mesh with C3D8 (CalculiX's coupled temperature-displacement brick), face-to-face
               (TYPE=SURFACE TO SURFACE) with a linear pressure-overclosure of the same stiffness, and its
               *GAP CONDUCTANCE (always by pressure);
  explicit:    the thermoslide deck as one *DYNAMIC TEMPERATURE-DISPLACEMENT, EXPLICIT step (penalty contact,
               the element-by-element stable increment with the penalty's share, default bulk viscosity) of
               about INCREMENTS increments (its period: INCREMENTS x 0.6 x the smallest cell side / (c_d sqrt 3)),
               one output frame (tests/bench/bench_explicit.sh).
Both codes: conductance 0 at zero pressure rising linearly to 2000 at 200 (continuous at lift-off, see below).
"""
import math
import sys

n, path = int(sys.argv[1]), sys.argv[2]
flavour = sys.argv[3] if len(sys.argv) > 3 else "thermoslide"
increments = int(sys.argv[4]) if flavour == "explicit" else 0
etype = sys.argv[5] if flavour == "explicit" and len(sys.argv) > 5 else "C3D8T"
nb = n + 1
E = 200.0e3


def block(nx, ny, nz, x0, x1, y0, y1, z0, z1, nid0, eid0):
    nid = lambda i, j, k: nid0 + 1 + i + k * (nx + 1) + j * (nx + 1) * (nz + 1)
    nodes = []
    for j in range(ny + 1):
        for k in range(nz + 1):
            for i in range(nx + 1):
                nodes.append((nid(i, j, k), x0 + (x1 - x0) * i / nx, y0 + (y1 - y0) * j / ny, z0 + (z1 - z0) * k / nz))
    elems, e = [], eid0
    for j in range(ny):
        for k in range(nz):
            for i in range(nx):
                # bottom (y_j) then top (y_j+1) quadrilaterals, counter-clockwise seen from +y... C3D8 wants
                # nodes 1-4 then 5-8 with a positive volume: (x, z) loops are clockwise seen from +y, so go
                # (i,k) -> (i,k+1) -> (i+1,k+1) -> (i+1,k)
                e += 1
                q = [(i, k), (i, k + 1), (i + 1, k + 1), (i + 1, k)]
                elems.append((e,) + tuple(nid(a, j, b) for a, b in q) + tuple(nid(a, j + 1, b) for a, b in q))
    return nodes, elems, nid


bn, be, bid = block(nb, 2, nb, 0.0, 1.0, 0.0, 0.5, 0.0, 1.0, 0, 0)
off = 10 ** len(str(len(bn)))
tn, te, tid = block(n, 1, n, 0.02, 0.98, 0.5, 0.6, 0.02, 0.98, off, off)
with open(path, "w") as f:
    w = f.write
    w("*HEADING\n 3D contact benchmark: %d secondary nodes\n*NODE, NSET=ALL\n" % ((n + 1) ** 2))
    for nd in bn + tn:
        w("%d, %.9g, %.9g, %.9g\n" % nd)
    typ = "C3D8" if flavour == "calculix" else etype
    w("*ELEMENT, TYPE=%s, ELSET=BASE\n" % typ)
    for el in be:
        w(", ".join(str(v) for v in el) + "\n")
    w("*ELEMENT, TYPE=%s, ELSET=TOP\n" % typ)
    for el in te:
        w(", ".join(str(v) for v in el) + "\n")
    # faces: the base's top (y = 0.5: nodes 5-8 face S2) and the thin block's bottom (nodes 1-4: S1)
    w("*ELSET, ELSET=BASETOP\n")
    ids = [el[0] for el in be if el[0] > nb * nb]
    for k in range(0, len(ids), 16):
        w(", ".join(str(i) for i in ids[k:k + 16]) + "\n")
    w("*SURFACE, NAME=MAIN, TYPE=ELEMENT\n BASETOP, S2\n*SURFACE, NAME=SECONDARY, TYPE=ELEMENT\n TOP, S1\n")
    w("*NSET, NSET=FIXED\n")
    ids = [nd[0] for nd in bn if nd[2] == 0.0]
    for k in range(0, len(ids), 16):
        w(", ".join(str(i) for i in ids[k:k + 16]) + "\n")
    w("*NSET, NSET=HOT\n")
    ids = [nd[0] for nd in tn if abs(nd[2] - 0.6) < 1e-12]
    for k in range(0, len(ids), 16):
        w(", ".join(str(i) for i in ids[k:k + 16]) + "\n")
    w("*MATERIAL, NAME=STEEL\n*ELASTIC\n %g, 0.3\n*CONDUCTIVITY\n 50.0\n*EXPANSION\n 1.2E-5\n*DENSITY\n 7.8E-9\n*SPECIFIC HEAT\n 4.6E8\n" % E)
    w("*SOLID SECTION, ELSET=BASE, MATERIAL=STEEL\n*SOLID SECTION, ELSET=TOP, MATERIAL=STEEL\n")
    w("*SURFACE INTERACTION, NAME=IFACE\n")
    # the same linear penalty in both codes, 0.1 E / main face size (a hundredth of thermoslide's default
    # 10 E / h): CalculiX's face-to-face contact with 10 E / h did not converge at N = 8 (the residual
    # dropped to 1e-5 and jumped back on a contact status change, cutback after cutback), with 0.1 E / h it
    # takes 5 iterations. The penetration under the pressure of 100 is 0.5 % of the main face size.
    if flavour == "calculix":
        w("*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR\n %g\n" % (0.1 * E * nb))
    else:
        w("*SURFACE BEHAVIOR, PENALTY\n %g\n" % (0.1 * E * nb))
    # conductance against the contact pressure: thermoslide's dialect says so with PRESSURE (without it the
    # abscissa is the clearance, as in Abaqus); CalculiX's *GAP CONDUCTANCE is always by pressure and ignores the
    # parameter with a warning, so both flavours carry it and the CalculiX deck runs unchanged in thermoslide
    # (tests/contact/check_calculix_deck.sh: C3D8 read as C3D8T, the LINEAR slope as the penalty).
    # The conductance is 0 at zero pressure, so it is continuous where a node lifts off: the hot thin block
    # bows and its edge rows lift off, and with 1000 at zero pressure (as before) the heat flow of a node
    # jumped from 1000 A dT to 0 on opening; Newton then cycled between two states (thermoslide at N = 16:
    # residual 141 / 335 alternately, cutbacks down to the minimum increment; CalculiX likewise at N = 8).
    w("*GAP CONDUCTANCE, PRESSURE\n 0.0, 0.0\n 2000.0, 200.0\n")
    w("*CONTACT PAIR, INTERACTION=IFACE%s\n SECONDARY, MAIN\n" % (", TYPE=SURFACE TO SURFACE" if flavour in ("calculix", "s2s") else ""))
    w("*INITIAL CONDITIONS, TYPE=TEMPERATURE\n ALL, 0.0\n")
    if increments:
        nu, rho = 0.3, 7.8e-9
        cd = math.sqrt(E * (1 - nu) / ((1 + nu) * (1 - 2 * nu)) / rho)
        w("*STEP\n*DYNAMIC TEMPERATURE-DISPLACEMENT, EXPLICIT\n , %.6e\n" % (increments * 0.6 * min(0.1, 0.96 / n) / (cd * math.sqrt(3))))
        w("*OUTPUT, FIELD, NUMBER INTERVAL=1\n")
    else:
        w("*STEP\n*COUPLED TEMPERATURE-DISPLACEMENT, STEADY STATE\n 1.0, 1.0\n")
    w("*BOUNDARY\n FIXED, 1, 3\n FIXED, 11, 11, 0.0\n HOT, 1, 1\n HOT, 3, 3\n HOT, 11, 11, 100.0\n")
    w("*DLOAD\n TOP, P2, 100.0\n")
    w("*NODE FILE\n U, NT\n")
    if flavour == "calculix":
        # the heat entering at the hot face, which in the steady state all crosses the interface (compare
        # with thermoslide's history column interface_heat)
        w("*NODE PRINT, NSET=HOT, TOTALS=ONLY\n RFL\n")
    w("*END STEP\n")
