#!/usr/bin/python3
"""Writes the structured-mesh verification decks of this folder (run once; the decks are committed).

Each deck is a plain Abaqus/CalculiX keyword file; this script only saves typing node and element lines.
"""
import math
import os
import re

HERE = os.path.dirname(os.path.abspath(__file__))

MAT = """*MATERIAL, NAME=STEEL
*ELASTIC
 30.0E6, 0.3
*CONDUCTIVITY
 10.0
*DENSITY
 1000.0
*SPECIFIC HEAT
 0.001
"""


def grid2d(nx, ny, x0, x1, y0, y1):
    nodes, elems = [], []
    for j in range(ny + 1):
        for i in range(nx + 1):
            nodes.append((1 + i + j * (nx + 1), x0 + (x1 - x0) * i / nx, y0 + (y1 - y0) * j / ny))
    for j in range(ny):
        for i in range(nx):
            n1 = 1 + i + j * (nx + 1)
            elems.append((1 + i + j * nx, n1, n1 + 1, n1 + nx + 2, n1 + nx + 1))
    return nodes, elems


def grid3d(nx, ny, nz, L, H, W):
    nodes, elems = [], []
    nid = lambda i, j, k: 1 + i + j * (nx + 1) + k * (nx + 1) * (ny + 1)
    for k in range(nz + 1):
        for j in range(ny + 1):
            for i in range(nx + 1):
                nodes.append((nid(i, j, k), L * i / nx, H * j / ny, W * k / nz))
    e = 1
    for k in range(nz):
        for j in range(ny):
            for i in range(nx):
                elems.append((e, nid(i, j, k), nid(i + 1, j, k), nid(i + 1, j + 1, k), nid(i, j + 1, k),
                              nid(i, j, k + 1), nid(i + 1, j, k + 1), nid(i + 1, j + 1, k + 1), nid(i, j + 1, k + 1)))
                e += 1
    return nodes, elems


def fmt_nodes(nodes):
    return "*NODE, NSET=ALL\n" + "".join(" " + ", ".join([str(n[0])] + ["%.10g" % c for c in n[1:]]) + "\n" for n in nodes)


def fmt_elems(elems, typ):
    return "*ELEMENT, TYPE=%s, ELSET=BODY\n" % typ + "".join(" " + ", ".join(str(v) for v in e) + "\n" for e in elems)


def nset(name, ids):
    ids = list(ids)
    return "*NSET, NSET=%s\n" % name + "".join(" " + ", ".join(str(i) for i in ids[k:k + 8]) + "\n" for k in range(0, len(ids), 8))


def elset(name, ids):
    ids = list(ids)
    return "*ELSET, ELSET=%s\n" % name + "".join(" " + ", ".join(str(i) for i in ids[k:k + 8]) + "\n" for k in range(0, len(ids), 8))


def write(name, text):
    with open(os.path.join(HERE, name), "w") as f:
        f.write(text)


def conduction_steady(typ):
    """Steady 1D conduction: theta = 100 on x = x0, film h = 50, sink 0 on x = x1 (face S2 of the last column)."""
    nx, ny = 10, 2
    if typ == "C3D8T":
        nodes, elems = grid3d(nx, ny, 1, 1.0, 0.2, 0.2)
        left = [n[0] for n in nodes if abs(n[1]) < 1e-12]
        right = [e[0] for e in elems if (e[0] - 1) % nx == nx - 1]
        face = "S4"
    else:
        x0, x1 = (1.0, 2.0) if typ == "CAX4T" else (0.0, 1.0)
        nodes, elems = grid2d(nx, ny, x0, x1, 0.0, 0.2)
        left = [n[0] for n in nodes if abs(n[1] - x0) < 1e-12]
        right = [e[0] for e in elems if (e[0] - 1) % nx == nx - 1]
        face = "S2"
    dofs = "1, 3" if typ == "C3D8T" else "1, 2"
    axis = "radial (r from 1 to 2), logarithmic profile" if typ == "CAX4T" else "along x, linear profile"
    write("conduction_steady_%s.inp" % typ.lower(),
          "*HEADING\n Steady conduction %s with %s: theta=100 at the inner face, film h=50 sink 0 at the outer face\n" % (axis, typ) +
          fmt_nodes(nodes) + fmt_elems(elems, typ) + nset("HOT", left) + elset("FILMED", right) + MAT +
          "*SOLID SECTION, ELSET=BODY, MATERIAL=STEEL\n 1.0\n"
          "*STEP\n*COUPLED TEMPERATURE-DISPLACEMENT, STEADY STATE\n 1.0, 1.0\n"
          "*BOUNDARY\n ALL, %s\n HOT, 11, 11, 100.0\n*FILM\n FILMED, F%s, 0.0, 50.0\n" % (dofs, face[1]) +
          "*NODE OUTPUT\n U, NT, RFL\n*ELEMENT OUTPUT\n HFL\n*END STEP\n")


def conduction_transient():
    """Transient 1D conduction into a slab: theta = 100 suddenly at x = 0, x = L insulated (series solution)."""
    nx = 40
    nodes, elems = grid2d(nx, 1, 0.0, 1.0, 0.0, 0.05)
    left = [n[0] for n in nodes if abs(n[1]) < 1e-12]
    write("conduction_transient_cpe4t.inp",
          "*HEADING\n Transient 1D conduction, CPE4T: slab 0<x<1 at 0, face x=0 held at 100 from t=0, x=1 insulated\n" +
          fmt_nodes(nodes) + fmt_elems(elems, "CPE4T") + nset("HOT", left) + MAT +
          "*SOLID SECTION, ELSET=BODY, MATERIAL=STEEL\n 1.0\n*INITIAL CONDITIONS, TYPE=TEMPERATURE\n ALL, 0.0\n"
          "*STEP, INC=1000\n*COUPLED TEMPERATURE-DISPLACEMENT, DELTMX=50.0\n 0.0005, 0.03, 1e-6, 0.0005\n"
          "*BOUNDARY\n ALL, 1, 2\n HOT, 11, 11, 100.0\n*NODE OUTPUT\n NT\n*END STEP\n")


def expansion(typ, constrained):
    """Uniform temperature rise 0 -> 100 of a block: free (statically determinate supports) or fully constrained."""
    if typ == "C3D8T":
        nodes, elems = grid3d(2, 2, 2, 1.0, 1.0, 1.0)
        corner = [n for n in nodes if abs(n[1]) + abs(n[2]) + abs(n[3]) < 1e-12][0][0]
        ynode = [n for n in nodes if abs(n[1]) < 1e-12 and abs(n[2] - 1) < 1e-12 and abs(n[3]) < 1e-12][0][0]
        znode = [n for n in nodes if abs(n[1]) < 1e-12 and abs(n[2]) < 1e-12 and abs(n[3] - 1) < 1e-12][0][0]
        supports = " %d, 1, 3\n %d, 1, 1\n %d, 3, 3\n %d, 1, 2\n" % (corner, ynode, ynode, znode)
        alldofs = "1, 3"
    else:
        x0 = 1.0 if typ == "CAX4T" else 0.0
        nodes, elems = grid2d(2, 2, x0, x0 + 1.0, 0.0, 1.0)
        corner = [n for n in nodes if abs(n[1] - x0) + abs(n[2]) < 1e-12][0][0]
        ynode = [n for n in nodes if abs(n[1] - x0) < 1e-12 and abs(n[2] - 1) < 1e-12][0][0]
        supports = " %d, 2, 2\n" % corner if typ == "CAX4T" else " %d, 1, 2\n %d, 1, 1\n" % (corner, ynode)
        alldofs = "1, 2"
    kind = "constrained" if constrained else "free"
    write("expansion_%s_%s.inp" % (kind, typ.lower()),
          "*HEADING\n Uniform heating 0 -> 100 of a %s block, %s; E=30e6 nu=0.3 alpha=1e-5\n" % (kind, typ) +
          fmt_nodes(nodes) + fmt_elems(elems, typ) + MAT + "*EXPANSION\n 1.0E-5\n" +
          "*SOLID SECTION, ELSET=BODY, MATERIAL=STEEL\n 1.0\n*INITIAL CONDITIONS, TYPE=TEMPERATURE\n ALL, 0.0\n"
          "*STEP\n*COUPLED TEMPERATURE-DISPLACEMENT, STEADY STATE\n 1.0, 1.0\n*BOUNDARY\n" +
          (" ALL, %s\n" % alldofs if constrained else supports) + " ALL, 11, 11, 100.0\n*END STEP\n")


def jacobian_case():
    """Small coupled transient case (expansion, film, flux, pressure) for -snes_test_jacobian."""
    nodes, elems = grid2d(2, 2, 0.0, 1.0, 0.0, 1.0)
    bottom = [n[0] for n in nodes if abs(n[2]) < 1e-12]
    nodes = [(n, x + 0.07 * y * x, y + 0.05 * x * x) for n, x, y in nodes]
    # material scaled so that the uu, u-theta and theta-theta blocks have entries of similar size: the
    # Frobenius-norm comparison would otherwise only see the stiffness
    mat = "*MATERIAL, NAME=SOFT\n*ELASTIC\n 1000.0, 0.3\n*CONDUCTIVITY\n 10.0\n*DENSITY\n 1.0\n*SPECIFIC HEAT\n 1.0\n*EXPANSION\n 0.01\n"
    write("jacobian_coupled_cpe4t.inp",
          "*HEADING\n Coupled transient on distorted CPE4T elements for -snes_test_jacobian\n" +
          fmt_nodes(nodes) + fmt_elems(elems, "CPE4T") + nset("BOTTOM", bottom) + elset("TOP", [3, 4]) + mat +
          "*SOLID SECTION, ELSET=BODY, MATERIAL=SOFT\n 1.0\n"
          "*INITIAL CONDITIONS, TYPE=TEMPERATURE\n ALL, 20.0\n"
          "*STEP\n*COUPLED TEMPERATURE-DISPLACEMENT\n 0.1, 0.1\n*BOUNDARY\n BOTTOM, 1, 2\n"
          "*DLOAD\n TOP, P3, 100.0\n*DFLUX\n TOP, S3, 50.0\n*FILM\n 1, F4, 0.0, 10.0\n*END STEP\n")


def loads_multistep():
    """Two steps exercising *EQUATION, *CLOAD, OP=NEW, *DLOAD, *DFLUX, *CFLUX and a film coefficient
    that follows an amplitude. Plate 1 x 0.5, rollers at the bottom, top edge kept straight by equations."""
    nx, ny, W, H = 4, 2, 1.0, 0.5
    nodes, elems = grid2d(nx, ny, 0.0, W, 0.0, H)
    bottom = [n[0] for n in nodes if abs(n[2]) < 1e-12]
    top = [n[0] for n in nodes if abs(n[2] - H) < 1e-12]
    top_elems = [e[0] for e in elems if e[0] > nx * (ny - 1)]
    bottom_elems = [e[0] for e in elems if e[0] <= nx]
    eqs = "".join("*EQUATION\n 2\n %d, 2, 1.0, %d, 2, -1.0\n" % (n, top[0]) for n in top[1:])
    write("loads_multistep_cpe4t.inp",
          "*HEADING\n Loads across steps: equation-tied top edge under a point load, then pressure (OP=NEW), flux, film with amplitude\n" +
          fmt_nodes(nodes) + fmt_elems(elems, "CPE4T") + nset("BOTTOM", bottom) + nset("TOP", top) +
          elset("TOPE", top_elems) + elset("BOTE", bottom_elems) + MAT +
          "*SOLID SECTION, ELSET=BODY, MATERIAL=STEEL\n 1.0\n" + eqs +
          "*AMPLITUDE, NAME=HRAMP\n 0.0, 1.0, 0.1, 3.0\n"
          "*INITIAL CONDITIONS, TYPE=TEMPERATURE\n ALL, 0.0\n"
          "*STEP, NAME=POINT LOAD\n*COUPLED TEMPERATURE-DISPLACEMENT, STEADY STATE\n 1.0, 1.0\n"
          "*BOUNDARY\n BOTTOM, 2, 2\n %d, 1, 1\n*CLOAD\n %d, 2, -100.0\n" % (bottom[0], top[0]) +
          "*DFLUX\n TOPE, S3, 50.0\n*FILM\n BOTE, F1, 0.0, 10.0\n"
          "*NODE PRINT, NSET=TOP\n U, NT\n*EL PRINT, ELSET=TOPE\n S\n*END STEP\n"
          "*STEP, NAME=PRESSURE\n*COUPLED TEMPERATURE-DISPLACEMENT\n 0.01, 0.1\n"
          "*CLOAD, OP=NEW\n*DLOAD\n TOPE, P3, 200.0\n*CFLUX\n %d, 11, 5.0\n" % top[-1] +
          "*FILM, FILM AMPLITUDE=HRAMP\n BOTE, F1, 0.0, 10.0\n*END STEP\n")


# Element families of the 2D deck types (the digits of the type name) and what the generated meshes need:
# faces of the bottom and top edge of a grid cell. Triangles split each cell along a diagonal into A
# (bottom edge S1) and B (top edge S2): (n1, n2, n3) and (n1, n3, n4), or, mirrored, (n1, n2, n4) and
# (n2, n3, n4).
FAMILIES_2D = {"3": ("tri", 1), "4": ("quad", 1), "6": ("tri", 2), "8": ("quad", 2)}


# Catalogue rows the dialect has no coupled name for (src/element/catalogue.c, MechanicalOnly): a deck names
# them by CalculiX's mechanical name (CPE6), which a coupled step reads as the row (CPE6T).
MECHANICAL_ONLY = ("CPE6T", "CPS6T", "CAX6T", "C3D15T", "CPE4IT", "CPS4IT", "CAX4IT", "C3D8IT")


def deck_type(typ):
    """The *ELEMENT TYPE= a deck writes for catalogue row typ."""
    return typ[:-1] if typ.upper() in MECHANICAL_ONLY else typ


def family_of(typ):
    """(shape, order, kinematics) of a 2D type name: CPE4RT -> ("quad", 1, "PE")."""
    m = re.match(r"C(GAX|PEG|PE|PS|AX)(\d)", typ.upper())
    shape, order = FAMILIES_2D[m.group(2)]
    return shape, order, m.group(1)


def mesh2d(nx, ny, x0, x1, y0, y1, shape, order, nid0=0, eid0=0, mirror=None):
    """A structured nx x ny grid of cells as quads or triangles of order 1 or 2 (Abaqus node order).
    Triangles: cells left of x = mirror are cut along (n1, n3), cells right of it along (n2, n4), so that
    the mesh is symmetric about x = mirror.
    Returns nodes [(id, x, y)], elems [(id, n...)], and per cell row j the bottom and top elements:
    rows[j] = ([bottom-edge elements], [top-edge elements]) with the faces given by faces()."""
    step = order
    NX, NY = nx * step, ny * step
    nid = lambda i, j: nid0 + 1 + i + j * (NX + 1)
    used, elems, rows = set(), [], []
    e = eid0
    for j in range(ny):
        bottom, top = [], []
        for i in range(nx):
            I, J = i * step, j * step
            c1, c2, c3, c4 = nid(I, J), nid(I + step, J), nid(I + step, J + step), nid(I, J + step)
            if order == 1:
                mids = {}
            else:
                mids = {"b": nid(I + 1, J), "r": nid(I + 2, J + 1), "t": nid(I + 1, J + 2), "l": nid(I, J + 1), "c": nid(I + 1, J + 1)}
            if shape == "quad":
                conn = [c1, c2, c3, c4] + ([mids["b"], mids["r"], mids["t"], mids["l"]] if order == 2 else [])
                e += 1
                elems.append((e,) + tuple(conn))
                bottom.append(e), top.append(e)
            elif mirror is not None and x0 + (x1 - x0) * (i + 0.5) / nx > mirror:
                a = [c1, c2, c4] + ([mids["b"], mids["c"], mids["l"]] if order == 2 else [])   # bottom edge S1
                b = [c2, c3, c4] + ([mids["r"], mids["t"], mids["c"]] if order == 2 else [])   # top edge S2
            else:
                a = [c1, c2, c3] + ([mids["b"], mids["r"], mids["c"]] if order == 2 else [])
                b = [c1, c3, c4] + ([mids["c"], mids["t"], mids["l"]] if order == 2 else [])
            if shape == "tri":
                elems.append((e + 1,) + tuple(a))
                elems.append((e + 2,) + tuple(b))
                bottom.append(e + 1), top.append(e + 2)
                e += 2
        rows.append((bottom, top))
    for el in elems:
        used.update(el[1:])
    nodes = [(nid(i, j), x0 + (x1 - x0) * i / NX, y0 + (y1 - y0) * j / NY) for j in range(NY + 1) for i in range(NX + 1) if nid(i, j) in used]
    return nodes, elems, rows


def faces(shape):
    """Face numbers of the bottom and top edges of a cell's elements."""
    return ("1", "3") if shape == "quad" else ("1", "2")


# Axisymmetric variant: the planar picture turned by 90 degrees about the point (0, R_AXI): r = R_AXI - y,
# z = x (a proper rotation, so elements keep their orientation). The large block becomes an outer ring
# r in [1.25, 2.5] fixed on its outside, the small block an inner ring r in [1, 1.25] pressed outward
# and slid axially. Volume pi (16 R - 10.75) = 29.25 pi for R = 2.5 (docs/verification.md).
R_AXI = 2.5
RING_A, RING_B = 1.0, 1.25  # the small ring's pressed bore and its contact face


def ring_pressure(pc, main_length=None):
    """The pressure on the small ring's bore r = a that presses it with the uniform contact pressure pc onto
    the large ring's bore r = b, which the ring decks hold radially (MAINN), the small ring moved axially as
    a whole (every node, SMALLN) and free radially: a thick cylinder in plane strain, sigma_r(a) = -p,
    sigma_r(b) = -pc, and u(b) the interface's compliance pc / eps_n (main_length: the solver's default
    penalty eps_n = 10 E / mean main face length; None: kinematic contact, u(b) = 0). Lame's u = A r + B / r,
    sigma_r = c1 A - c2 B / r^2 with c1 / c2 = 1 / (1 - 2 nu) (plane strain) and c2 = E / (1 + nu), gives
        p / pc = (c1 / c2 + b^2 / a^2) / (c1 / c2 + 1) (1 - s / b) + s b / a^2,
    s = c2 / eps_n = main_length / (10 (1 + nu)) (E cancels): 1.1607143 for kinematic contact, 1.1730769 and
    1.1854396 for the penalty at main faces 0.5 and 1.0 long. The radius ratio b / a = 1.25 alone, which the
    decks used until 2026-12, is the thin ring free of hoop stress; a ring that cannot expand carries a
    compressive hoop stress (its radial compression, through Poisson's ratio), which adds to the force on
    the bore, and the penalty's small overlap lets it expand by pc / eps_n, which takes some away
    (docs/verification.md, "Axisymmetric decks")."""
    nu, a, b = 0.3, RING_A, RING_B
    s = 0.0 if main_length is None else main_length / (10.0 * (1.0 + nu))
    q = 1.0 / (1.0 - 2.0 * nu)
    return pc * ((q + b * b / (a * a)) / (q + 1.0) * (1.0 - s / b) + s * b / (a * a))


def series_interaction(series, auglagr=False, surf=False):
    """The spec's interface of each series (planar and 3D decks alike): pressure-dependent gap conductance,
    gap radiation, or Lagrange friction with heat generation; the contact pair (smoothing 0.05), the
    sliding amplitude and the initial temperature."""
    if series == "conductance":
        text = "*SURFACE INTERACTION, NAME=IFACE\n*GAP CONDUCTANCE, PRESSURE\n 20.0, 100.0\n 5.0, 200.0\n"
    elif series == "radiation":
        text = ("*PHYSICAL CONSTANTS, ABSOLUTE ZERO=-273.16, STEFAN BOLTZMANN=1.0\n"
                "*SURFACE INTERACTION, NAME=IFACE\n*GAP RADIATION\n 1.0, 1.0\n 1.0E-6, 0.0\n 1.0E-6, 1.0\n")
    else:
        text = ("*SURFACE INTERACTION, NAME=IFACE\n*FRICTION, LAGRANGE\n 0.1\n*GAP CONDUCTANCE, PRESSURE\n 20.0, 0.0\n"
                "*GAP HEAT GENERATION\n 0.5, 0.5\n")
    if auglagr:  # the spec's *_auglagr decks: every series (ei23tssc, ei23tssr, ei23tssf) with augmented Lagrange normal contact
        text += "*SURFACE BEHAVIOR, AUGMENTED LAGRANGE\n"
    return text + ("*CONTACT PAIR, INTERACTION=IFACE, SMOOTH=0.05%s\n SECONDARY, MAIN\n" % (", TYPE=SURFACE TO SURFACE" if surf else "") +
                   "*AMPLITUDE, NAME=SLIDE\n 0.0, 0.0, 1.0, 1.0, 2.0, -1.0, 3.0, 0.0\n"
                   "*INITIAL CONDITIONS, TYPE=TEMPERATURE\n ALL, 0.0\n")


def sliding_blocks(series, auglagr=False, typ="CPE4T", outdir=None, surf=False, refine=1, top_rows=6, ring_sets=False,
                   film_amplitude=False):
    """The spec's finite-sliding problems: a block 2 x 0.25 (4 x 6 cells) pressed on a block 6 x 1.25
    (12 x 2 cells) fixed at its bottom; total area 8, rho c = 1. The thin upper block passes the applied
    pressure on nearly uniformly (a few % spread), and the blocks' nodes meet along the interface at the
    start; both have 24 cells, so slabs along y put them on different ranks.
    series: conductance (pressure-dependent gap conductance, 5 steps), radiation (gap radiation,
    5 steps), friction (Lagrange friction and frictional heating, 3 steps).
    typ: any 2D type of the catalogue (CPE*, CPEG*, CPS*, CAX*): triangles split each cell, second-order
    types get midside nodes, generalized plane strain types a reference node per block (9001, 9002:
    free, so each block expands out of plane freely; the in-plane problem is that of plane strain),
    types get midside nodes, axisymmetric types the rings described at R_AXI (slide along z, press
    along r). The rings' conductance and radiation series hold the large ring's bore radially (MAINN) and
    move the small ring axially as a whole (SMALLN), so that it is a thick cylinder in plane strain pressed
    onto a held bore, uniformly: the pressure on its face r = 1 is Lame's for 100 and 200 at the interface
    (ring_pressure, with the default penalty's compliance). With twist (CGAX) the sliding face also turns
    by 0.4 rad with the axial slide (circumferential motion, the spec's twist tests) and the twist (dof 5)
    is held on the base and the pressed face. The rings' friction series keeps the *EQUATION-tied face of
    the planar decks on a large ring free at its bore: a radial force 211.6, of which the inner ring's hoop
    stiffness takes about 5 %, so that the interface carries about 200 as in the planar decks (its
    explicit decks, sliding_explicit, press the held bore as the conductance series does).
    surf: TYPE=SURFACE TO SURFACE (job name *_surf_*); refine: cells per cell each way (job name *_rN_*);
    top_rows: cells across the small block (6; the explicit decks take 2); ring_sets: the rings' node sets
    SMALLN and MAINN in the friction series too (its explicit decks use them; the conductance and radiation
    series always have them).
    film_amplitude (the conductance series; job name *_filmamp_*): the film coefficient varies in
    time, as the spec's eia2tssc illustrates: *FILM, FILM AMPLITUDE=FILMH with the total-time amplitude
    FILM_AMPLITUDE below (h = 10 x 0.5 at the start, 10 at the end of step 1 and through step 3, 20 from the
    end of step 4 on), so that the steady steps' film faces sit at flux / (h A) with h = 10 and then 20.
    typ SAX2T (the spec's CAX8T, SAX2T decks): the large ring as the CAX8T deck has it, the small ring as a
    line of 4 SAX2T shells on its mid-surface r = 1.125 (thickness 0.25, along +z: the positive normal -r,
    so SNEG is the contact face r = 1.25 and SPOS the pressed face r = 1); TOPFACE is the shell nodes (a
    boundary condition holds each one's whole fiber through the thickness, the *EQUATIONs of the friction
    series tie the mid-surface nodes themselves); loads on the surface PRESSED (the SPOS side). The
    conductance and radiation series hold every shell node axially (SMALLN, the whole ring: plane strain on
    the held bore, as the solid rings; before the bore was held, the centre fibre alone was driven, since a
    ring held axially all through pressed a compliant bore like a rigid punch). The friction series' radial force is
    224.3: the ring's hoop stiffness takes more of it than the CAX8T ring's (about 11 %), and the interface
    force is again about 200."""
    typ = typ.upper()
    shell = typ == "SAX2T"
    if shell:
        typ = "CAX8T"
    shape, order, kin = family_of(typ)
    axi = kin in ("AX", "GAX")
    twist = kin == "GAX"
    # second-order types: half the cells each way (the same node spacing, a quarter of the elements)
    c = 2 if order == 2 else 1
    bnodes, belems, brows = mesh2d(12 * refine // c, 2 * refine // c, 0.0, 6.0, 0.0, 1.25, shape, order, mirror=3.0)
    fb, ft = faces(shape)
    if shell:
        # SAX2T: end, middle, end; 4 elements along x (z), nodes 1001.. on the mid-surface y = 1.375
        nel = 4 * refine
        tnodes = [(1001 + i, 2.0 + 2.0 * i / (2 * nel), 1.375) for i in range(2 * nel + 1)]
        telems = [(1001 + k, 1001 + 2 * k, 1002 + 2 * k, 1003 + 2 * k) for k in range(nel)]
        topface = [n[0] for n in tnodes]
        sec_elems = pressed = [e[0] for e in telems]
        drive = "SMALLN"  # every shell node's fibre: the ring moved axially as a whole (docstring)
        small_nodes = topface
    else:
        tnodes, telems, trows = mesh2d(4 * refine // c, top_rows * refine // c, 2.0, 4.0, 1.25, 1.5, shape, order, 1000, 1000, mirror=3.0)
        topface = [n[0] for n in tnodes if abs(n[2] - 1.5) < 1e-12]
        sec_elems = trows[0][0]     # bottom row of the small block
        pressed = trows[-1][1]      # top row of the small block
        # rings: every node of the small ring moved axially (SMALLN), so that it is pressed as a thick cylinder
        # in plane strain (ring_pressure); planar blocks: the top face
        drive = "SMALLN" if axi else "TOPFACE"
        small_nodes = [n[0] for n in tnodes]
    base = [n[0] for n in bnodes if abs(n[2]) < 1e-12]
    main_elems = brows[-1][1]   # top row of the large block
    mainn = [n[0] for n in bnodes if abs(n[2] - 1.25) < 1e-12]  # its top face (rings: the bore, held radially)
    main_length = 6.0 / len(main_elems)  # the main faces' length (the default penalty's 10 E / length)
    # centre of the large block's bottom, 2.5 <= x <= 3.5
    filmed = [brows[0][0][k] for k in (range(5 * refine // c, 7 * refine // c) if refine > 1 else (6 // c - 1, 6 // c))]
    place = (lambda x, y: (R_AXI - y, x)) if axi else (lambda x, y: (x, y))
    slide, press = ("2", "1") if axi else ("1", "2")
    fmt = lambda nodes: "".join(" %d, %.10g, %.10g\n" % ((n[0],) + place(n[1], n[2])) for n in nodes)
    text = ("*HEADING\n Finite sliding between coupled temperature-displacement %s blocks: %s series\n" % ("CAX8T and SAX2T" if shell else typ, series) +
            "*NODE, NSET=ALL\n" + fmt(bnodes) + "*NODE, NSET=ALL\n" + fmt(tnodes) +
            "*ELEMENT, TYPE=%s, ELSET=LARGE\n" % deck_type(typ) + "".join(" " + ", ".join(str(v) for v in e) + "\n" for e in belems) +
            "*ELEMENT, TYPE=%s, ELSET=SMALL\n" % ("SAX2T" if shell else deck_type(typ)) + "".join(" " + ", ".join(str(v) for v in e) + "\n" for e in telems) +
            nset("BASE", base) + nset("TOPFACE", topface) + (nset("SMALLN", small_nodes) + nset("MAINN", mainn) if axi and (series != "friction" or ring_sets) else "") +
            elset("MAINE", main_elems) + elset("SECE", sec_elems) +
            elset("PRESSEDE" if shell else "PRESSED", pressed) + elset("FILMED", filmed) +
            "*SURFACE, NAME=MAIN, TYPE=ELEMENT\n MAINE, S%s\n*SURFACE, NAME=SECONDARY, TYPE=ELEMENT\n SECE, S%s\n" % (ft, "NEG" if shell else fb) +
            ("*SURFACE, NAME=PRESSED, TYPE=ELEMENT\n PRESSEDE, SPOS\n" if shell else "") + MAT +
            (("*NODE, NSET=REFS\n 9001, 3.0, 0.0\n 9002, 3.0, 1.375\n"
              "*SOLID SECTION, ELSET=LARGE, MATERIAL=STEEL, REF NODE=9001\n 1.0\n*SOLID SECTION, ELSET=SMALL, MATERIAL=STEEL, REF NODE=9002\n 1.0\n")
             if kin == "PEG" else
             "*SOLID SECTION, ELSET=LARGE, MATERIAL=STEEL\n 1.0\n*SHELL SECTION, ELSET=SMALL, MATERIAL=STEEL\n 0.25\n" if shell else
             "*SOLID SECTION, ELSET=LARGE, MATERIAL=STEEL\n 1.0\n*SOLID SECTION, ELSET=SMALL, MATERIAL=STEEL\n 1.0\n"))
    # the pressed face's pressure and flux: element faces (PRESSED, P3 / S3, ...), or the shells' surface (P, S)
    pload = (lambda v: " PRESSED, P, %s\n" % v) if shell else (lambda v: " PRESSED, P%s, %s\n" % (ft, v))
    dflux = "*DSFLUX%s\n PRESSED, S, 100.0\n" if shell else "*DFLUX%s\n PRESSED, S" + ft + ", 100.0\n"
    text += series_interaction(series, auglagr, surf)
    if series == "friction":
        ref = topface[0]
        # twist rings: the sliding face also turns; the slide is 0.6 axial and 0.8 circumferential of the
        # planar slide (0.8 x 1.5 = 1.2 of arc at the interface r = 1.25: phi = 0.96), so that the slip path
        # and the heat are the planar ones
        dofs = (1, 2, 5) if twist else (1, 2)
        text += "".join("*EQUATION\n 2\n %d, %d, 1.0, %d, %d, -1.0\n" % (n, d, ref, d) for n in topface[1:] for d in dofs)
        hold = (" BASE, 5, 5\n %d, 5, 5\n" % ref) if twist else ""
        amount = "0.9" if twist else "1.5"
        turn = (" %d, 5, 5, 0.96\n" % ref) if twist else ""
        text += ("*STEP, NAME=PRESS, INC=100\n*COUPLED TEMPERATURE-DISPLACEMENT\n 0.5, 1.0\n"
                 "*BOUNDARY\n BASE, 1, 2\n %d, %s, %s\n%s*CLOAD\n %d, %s, %s\n*END STEP\n" % (ref, slide, slide, hold, ref, press, "224.3" if shell else "211.6" if axi else "-200.0") +
                 "*STEP, NAME=SLIDE, INC=1000\n*COUPLED TEMPERATURE-DISPLACEMENT\n 0.025, 3.0, 1e-5, 0.025\n"
                 "*BOUNDARY, AMPLITUDE=SLIDE\n %d, %s, %s, %s\n%s*END STEP\n" % (ref, slide, slide, amount, turn) +
                 "*STEP, NAME=EQUILIBRATE, INC=1000\n*COUPLED TEMPERATURE-DISPLACEMENT\n 0.1, 20.0, 1e-5, 2.0\n*END STEP\n")
    else:
        # rings: the large ring's bore held radially and the pressure of a thick cylinder pressed on it with 100
        # (ring_pressure, the default penalty's compliance included); planar blocks: 100 on the top face
        p1, p2 = ("%.10g" % ring_pressure(p, main_length) if axi else "%.10g" % p for p in (100.0, 200.0))
        if film_amplitude:
            text += "*AMPLITUDE, NAME=FILMH, TIME=TOTAL TIME\n" + "".join(" %g, %g\n" % p for p in FILM_AMPLITUDE)
        text += ("*AMPLITUDE, NAME=OFF\n 0.0, 0.0, 1.0, 1.0\n*AMPLITUDE, NAME=FLUXDOWN\n 0.0, 1.0, 0.1, 0.0\n"
                 "*STEP, NAME=HEAT, INC=100\n*COUPLED TEMPERATURE-DISPLACEMENT\n 0.1, 1.0, 1e-5, 0.1\n"
                 "*BOUNDARY\n BASE, 1, 2\n%s %s, %s, %s\n%s*DLOAD\n%s%s"
                 % (" MAINN, 1, 1\n" if axi else "", drive, slide, slide, " BASE, 5, 5\n TOPFACE, 5, 5\n" if twist else "", pload(p1), dflux % "") +
                 ("*FILM, FILM AMPLITUDE=FILMH\n" if film_amplitude else "*FILM\n") + " FILMED, F%s, 0.0, 10.0\n*END STEP\n" % fb +
                 "*STEP, NAME=SLIDE, INC=1000\n*COUPLED TEMPERATURE-DISPLACEMENT\n 0.05, 3.0, 1e-5, 0.05\n"
                 "*BOUNDARY, AMPLITUDE=SLIDE\n %s, %s, %s, 1.5\n%s*END STEP\n" % (drive, slide, slide, " TOPFACE, 5, 5, 0.4\n" if twist else "") +
                 "*STEP, NAME=STEADY\n*COUPLED TEMPERATURE-DISPLACEMENT, STEADY STATE\n 1.0, 1.0\n*END STEP\n"
                 "*STEP, NAME=DOUBLE PRESSURE\n*COUPLED TEMPERATURE-DISPLACEMENT, STEADY STATE\n 1.0, 1.0\n"
                 "*DLOAD\n%s*END STEP\n" % pload(p2) +
                 "*STEP, NAME=SLIDE OFF, INC=1000\n*COUPLED TEMPERATURE-DISPLACEMENT\n 0.05, 3.0, 1e-5, 0.1\n"
                 "*DLOAD, OP=NEW\n*BOUNDARY, FIXED\n TOPFACE, %s, %s\n%s*BOUNDARY, AMPLITUDE=OFF\n %s, %s, %s, 5.0\n"
                 % (press, press, " TOPFACE, 5, 5\n" if twist else "", drive, slide, slide) +
                 dflux % ", AMPLITUDE=FLUXDOWN" + "*END STEP\n")
    # the conductance series only: the radiation series' step 4 drop equals step 3's only at the same level
    assert not film_amplitude or series == "conductance", "--film-amplitude: the conductance series (the spec's eia2tssc)"
    name = "sliding_%s%s%s%s%s_%s.inp" % (series, "_auglagr" if auglagr else "", "_surf" if surf else "", "_r%d" % refine if refine > 1 else "",
                                           "_filmamp" if film_amplitude else "", "sax2t" if shell else typ.lower())
    with open(os.path.join(outdir or HERE, name), "w") as f:
        f.write(text)


# The film coefficient's factor over the total time for make_decks.py --sliding ... --film-amplitude (the spec's
# eia2tssc: "the procedure to specify a time-dependent variation of the film coefficient"); the conductance and
# radiation series' steps end at total times 1 (HEAT), 4 (SLIDE), 5 (STEADY), 6 (DOUBLE PRESSURE) and 9 (SLIDE OFF).
# A total-time amplitude keeps following its table across the steps and holds its last value beyond it.
FILM_AMPLITUDE = [(0.0, 0.5), (1.0, 1.0), (5.0, 1.0), (6.0, 2.0)]


# The 3D series (issue 7): the planar blocks extruded to the spec's "three-dimensional model with width
# 1.0" (the small block, z in [0, 1]); the large block is slightly wider (z in [-0.1, 1.1]) so that the
# small block's edge nodes land inside its faces; one cell across each width, so the meshes do not match
# in z either. Hexahedra (C3D8*), wedges (C3D6T: the planar triangles extruded, quad faces on the
# interface), tetrahedra (C3D4T: each hexahedron cut into six; C3D10MT: the same with midside nodes, tri6
# faces on the interface). Face numbers are found from the geometry (the face whose corners lie on the
# interface plane), so every family uses the catalogue's own numbering.
FACES_3D = {  # corner positions of each face S1..S6, as the dialect numbers them
    "hex": [(0, 1, 2, 3), (4, 7, 6, 5), (0, 4, 5, 1), (1, 5, 6, 2), (2, 6, 7, 3), (3, 7, 4, 0)],
    "wedge": [(0, 1, 2), (3, 5, 4), (0, 3, 4, 1), (1, 4, 5, 2), (2, 5, 3, 0)],
    "tet": [(0, 1, 2), (0, 3, 1), (1, 3, 2), (2, 3, 0)],
}
TET10_EDGES = [(0, 1), (1, 2), (2, 0), (0, 3), (1, 3), (2, 3)]
# six tetrahedra of a hexahedron (corners 0..7 as C3D8), all around the diagonal 0-6
HEX_TETS = [(0, 1, 2, 6), (0, 2, 3, 6), (0, 3, 7, 6), (0, 7, 4, 6), (0, 4, 5, 6), (0, 5, 1, 6)]


def amplitude(name, pts, smooth=False):
    """*AMPLITUDE lines; smooth: DEFINITION=SMOOTH STEP (a fifth-order step between the points, no velocity
    or acceleration jump anywhere: a tabulated smooth step jumps in velocity at every point)."""
    return ("*AMPLITUDE, NAME=%s%s\n" % (name, ", DEFINITION=SMOOTH STEP" if smooth else "") +
            "".join(" %.10g, %.10g\n" % p for p in pts))


# Explicit versions of the spec's series ("Simulation with Abaqus/Explicit"; docs/explicit.md, "Contact"),
# with the spec's material. The small block has 2 cells across its 0.25 instead of 6: the thermal stable
# increment goes as the square of the cell size (7e-4 instead of 9e-5), and with 2 cells it is about the
# mechanical one of density 1000 (4e-4 with the contact penalty). The slide is slow for a quasi-static
# response: its inertia M a (M = 500) stays below 310, half of what would lift an edge of the interface (the
# moment M a x 0.125 against N L / 6 = 67 about the interface), so the interface stays closed.
# Mass scaling would not shorten it: a heavier block must slide as much slower as its increment grows
# (both go as the square root of the mass), so mass scaling (to the thermal increment) is used only in the
# steps without motion, where it saves increments outright.
EXPLICIT_TARGET = 1.5e-3   # mass scaling target of the resting steps: the thermal stable increment (7.8e-4) then controls
EXPLICIT_SLIDE = 16.0      # period of the back-and-forth slide (slip path 6, legs of 5.3 s, peak acceleration 0.61 on the middle leg)
EXPLICIT_STEADY = 5.0      # the "steady" periods: 6 time constants C / (h A) = 8 / 10 of the assembly's film loss
EXPLICIT_EQUILIBRATE = 2.0 # friction series: 5.5 time constants L^2 / (pi^2 k / rho c) = 0.36 of the large block's length 6
# The resting steps damp the vibration the slide left (the default linear bulk viscosity, 0.06, barely touches it:
# kinetic energy 1e-8 at the end of a steady period, enough to make the contact pressure oscillate by 1 % and the
# pressure-dependent conductance with it; docs/explicit.md "What a quasi-static explicit solution reaches"): b1 = 0.5
# there, which the mass-scaled mechanical increment absorbs (the thermal increment still controls)
EXPLICIT_REST_BULK_VISCOSITY = "*BULK VISCOSITY\n 0.5, 1.2\n"
# The friction series' slide with KINEMATIC contact is damped too. A steady slide with Coulomb friction on a stiff
# normal constraint can be dynamically unstable (friction-induced flutter: the friction mu p couples the blocks'
# modes through the contact reaction p, a non-symmetric stiffness), and the kinematic tie is the stiff limit: on the
# planar triangles (CPE3T) the least stable mode grows at 22 /s (246 Hz) undamped, 6.8 /s with the default
# b1 = 0.06, and decays from b1 = 0.12 on (tests/explicit/sliding_flutter.py; the default penalty's compliance brings
# it to 1.4 /s undamped, which 0.06 damps). Grown, it makes the secondary nodes leave the face and strike it again,
# and the friction falls short of mu N (CPE3T, CPE6MT, C3D6T, C3D10MT: 0.08 - 0.4 %). b1 = 0.3 damps it on every mesh
# of the matrix but the continuum shell's (CPE6MT needs 0.12 - 0.2), stays clear of the shell's own limit (its slide
# blows up from b1 = 0.6 on, not understood: docs/explicit.md "Friction-induced flutter"), and costs the quasi-static
# slide nothing (ALLVD 3e-6 of its 120), only increments where the mechanical limit controls (x 0.74 against 0.94).
EXPLICIT_SLIDE_BULK_VISCOSITY = "*BULK VISCOSITY\n 0.3, 1.2\n"
# ... but not the continuum shells' (SC8RT): their flutter (97 Hz, omega = 609 /s, in a mode of the large block's soft
# thickness modulus 2G) is hardly volumetric, and grows at 2.8 - 4.3 /s whatever b1. Their material gets Rayleigh
# stiffness damping instead, *DAMPING, BETA=4e-5 (docs/explicit.md "Damping"): beta omega^2 / 2 = 7.4 /s of decay on
# that mode; the elements' highest modes get xi = beta omega_e / 2 = 0.07, their increment 5 % shorter (the slide
# 30 420 increments instead of 29 040). Measured: ALLFD 119.9929 instead of 119.928, the kinetic energy left 5e-12 of
# the slide's largest instead of 1.9e-6, the damping's work (ALLVD) 9.2e-6: the planar rows' bounds.
EXPLICIT_SHELL_DAMPING = "*DAMPING, BETA=4e-5\n"


def explicit_steps(series, hold, sd, pd, pressed, film, p100, drive="TOPFACE", constraint="PENALTY"):
    """The explicit steps of the spec's series (planar and 3D decks alike; see sliding_explicit): the
    amplitudes and the steps. hold: the *BOUNDARY lines of the first step (base fixed, the small block's top
    face held along the slide dof sd, and in 3D across z); pd: the pressing dof; pressed(kind, value): the
    load lines on the pressed face (kind P or S); film: the film lines; p100: the pressure giving 100 at the
    interface (friction: the interface force 200); drive: the node set whose motion along sd slides the small
    block (the rings: SMALLN, every node of the small ring); constraint: the pair's MECHANICAL CONSTRAINT (the
    friction series' slide with KINEMATIC contact is damped, EXPLICIT_SLIDE_BULK_VISCOSITY)."""
    T = EXPLICIT_SLIDE
    # 0 -> 1.5 -> -1.5 -> 0 as the implicit decks, each leg a smooth step: at rest at the reversals and the ends
    slide = [(0, 0), (T / 3, 1.5), (2 * T / 3, -1.5), (T, 0)]
    mass = "*FIXED MASS SCALING, DT=%g, TYPE=BELOW MIN\n" % EXPLICIT_TARGET
    dyn = lambda period, scaled=False: "*DYNAMIC TEMPERATURE-DISPLACEMENT, EXPLICIT\n , %g\n" % period + (mass + EXPLICIT_REST_BULK_VISCOSITY if scaled else "")
    text = amplitude("SLIDE", slide, True) + amplitude("RAMP", [(0.0, 0.0), (0.25, 1.0)], True)
    move = "*BOUNDARY, AMPLITUDE=SLIDE\n %s, %s, %s, 1.0\n*END STEP\n" % (drive, sd, sd)
    if series == "friction":
        return text + ("*STEP, NAME=PRESS\n" + dyn(0.25) + "*BOUNDARY\n" + hold + "*DLOAD, AMPLITUDE=RAMP\n" + pressed("P", p100) +
                       "*END STEP\n*STEP, NAME=SLIDE\n" + dyn(T) + (EXPLICIT_SLIDE_BULK_VISCOSITY if constraint == "KINEMATIC" else "") + move +
                       "*STEP, NAME=EQUILIBRATE\n" + dyn(EXPLICIT_EQUILIBRATE, True) + "*END STEP\n")
    S = EXPLICIT_STEADY
    return text + (amplitude("OFF", [(0.0, 0.0), (4.0, 1.0)], True) + amplitude("FLUXDOWN", [(0.0, 1.0), (0.1, 0.0)]) +
                   amplitude("DOUBLE", [(0.0, 1.0), (0.5, 2.0)], True) +
                   "*STEP, NAME=HEAT\n" + dyn(1.0) + "*BOUNDARY\n" + hold + "*DLOAD, AMPLITUDE=RAMP\n" + pressed("P", p100) +
                   "*DFLUX\n" + pressed("S", "100.0") + "*FILM\n" + film + "*END STEP\n" +
                   "*STEP, NAME=SLIDE\n" + dyn(T) + move +
                   "*STEP, NAME=STEADY\n" + dyn(S, True) + "*END STEP\n"
                   "*STEP, NAME=DOUBLE PRESSURE\n" + dyn(S, True) + "*DLOAD, AMPLITUDE=DOUBLE, OP=NEW\n" + pressed("P", p100) + "*END STEP\n"
                   "*STEP, NAME=SLIDE OFF\n" + dyn(4.0) + "*DLOAD, OP=NEW\n*BOUNDARY, FIXED\n TOPFACE, %s, %s\n"
                   "*BOUNDARY, AMPLITUDE=OFF\n %s, %s, %s, 5.0\n*DFLUX, AMPLITUDE=FLUXDOWN\n" % (pd, pd, drive, sd, sd) +
                   pressed("S", "100.0") + "*END STEP\n")


def sliding_explicit(series, constraint="PENALTY", typ="CPE4T", outdir=None, surf=False):
    """The three series of sliding_blocks as explicit steps (any planar or axisymmetric type): the same blocks,
    interaction and loads, with MECHANICAL CONSTRAINT=constraint (PENALTY or KINEMATIC) and these
    changes, each needed by explicit steps: no *EQUATION (the friction series' straight, non-rotating top
    face becomes a prescribed horizontal motion of the top face with the force 200 as a pressure of 100
    on it; the rings as sliding_blocks' conductance series has them in every series: the large ring's bore
    held radially, the small ring moved axially as a whole, pressed with the thick cylinder's pressure
    (ring_pressure: no compliance with kinematic contact, the default penalty's with penalty contact) for
    100 at the interface, or in the friction series for the planar blocks' interface force 200, pc = 200 /
    (2 pi b x 2) = 12.73); the slide 0 -> 1.5 -> -1.5 -> 0 as three SMOOTH STEP legs (the same slip path 6, but no
    velocity or acceleration jumps, which would send waves through the undamped blocks: the 16-point
    tables used before rang them up to ALLIE ~ 10); loads ramped in by smooth steps; steady-state steps as transient
    steps of EXPLICIT_STEADY; density / specific heat as above (the steps: explicit_steps). surf: TYPE=SURFACE
    TO SURFACE (PENALTY only; job name *_surf_*)."""
    import tempfile
    with tempfile.TemporaryDirectory() as tmp:  # the implicit deck of the same name must not be overwritten
        sliding_blocks(series, typ=typ, outdir=tmp, top_rows=2, ring_sets=True)
        with open(os.path.join(tmp, "sliding_%s_%s.inp" % (series, typ.lower()))) as f:
            text = f.read()
    head = text[:text.index("*CONTACT PAIR")]
    head = head.replace("%s series\n" % series, "%s series, explicit, %s contact\n" % (series, constraint.lower()))
    shape, order, kin = family_of(typ)
    fb, ft = faces(shape)
    # axisymmetric rings (CAX*): slide along z (dof 2), press along r (dof 1), the pressure on the inner face
    # (r = 1) the thick cylinder's (ring_pressure) for a contact pressure of 100 on the held bore (r = 1.25), or
    # for the interface force 200 in the friction series (docstring)
    axi = kin in ("AX", "GAX")
    sd, pd = ("2", "1") if axi else ("1", "2")
    if axi:
        pc = 200.0 / (2.0 * math.pi * RING_B * 2.0) if series == "friction" else 100.0
        p100 = "%.10g" % ring_pressure(pc, 0.5 * (2 if order == 2 else 1) if constraint == "PENALTY" else None)  # the main faces' length
    else:
        p100 = "100.0"
    hold = " BASE, 1, 2\n MAINN, 1, 1\n SMALLN, %s, %s\n" % (sd, sd) if axi else " BASE, 1, 2\n TOPFACE, %s, %s\n" % (sd, sd)
    text = head + ("*CONTACT PAIR, INTERACTION=IFACE, SMOOTH=0.05, MECHANICAL CONSTRAINT=%s%s\n SECONDARY, MAIN\n"
                   % (constraint, ", TYPE=SURFACE TO SURFACE" if surf else "") + "*INITIAL CONDITIONS, TYPE=TEMPERATURE\n ALL, 0.0\n")
    text += explicit_steps(series, hold, sd, pd, lambda kind, value: " PRESSED, %s%s, %s\n" % (kind, ft, value),
                           " FILMED, F%s, 0.0, 10.0\n" % fb, p100, "SMALLN" if axi else "TOPFACE", constraint)
    name = "sliding_%s_explicit_%s%s_%s.inp" % (series, constraint.lower(), "_surf" if surf else "", typ.lower())
    with open(os.path.join(outdir or HERE, name), "w") as f:
        f.write(text)


def family_3d(typ):
    m = re.match(r"(?:C3D|SC)(\d+)", typ.upper())
    return {"8": "hex", "6": "wedge", "4": "tet", "10": "tet"}[m.group(1)], 2 if m.group(1) == "10" else 1


# SC8RT decks with the solids' numbering (the elements' second direction along y) and STACK DIRECTION=2
# instead of the default (third direction along y): make_decks.py --sliding SC8RT SERIES OUTDIR --stack2
SHELL_STACK2 = False


def is_shell(typ):
    """A continuum shell (SC8RT, SC6RT): its elements are numbered with the stack direction, their third, along
    y (the blocks' height), and its section is *SHELL SECTION."""
    return typ.upper().startswith("SC")


def section(typ, elset):
    if is_shell(typ):
        return "*SHELL SECTION, ELSET=%s, MATERIAL=STEEL%s\n 1.0, 5\n" % (elset, ", STACK DIRECTION=2" if SHELL_STACK2 else "")
    return "*SOLID SECTION, ELSET=%s, MATERIAL=STEEL\n" % elset


def mesh3d(nx, ny, nz, x0, x1, y0, y1, z0, z1, typ, nid0=0, eid0=0, mirror=None):
    """Block of nx x ny x nz cells as the family of typ; returns nodes {id: (x, y, z)} and elements
    [(id, conn...)] with positive volumes. Wedges and tetrahedra: cells right of x = mirror are cut as the
    mirror images of those left of it, so that the mesh is symmetric about x = mirror."""
    shape, order = family_3d(typ)
    nid = lambda i, j, k: nid0 + 1 + i + j * (nx + 1) + k * (nx + 1) * (ny + 1)
    nodes = {nid(i, j, k): (x0 + (x1 - x0) * i / nx, y0 + (y1 - y0) * j / ny, z0 + (z1 - z0) * k / nz)
             for k in range(nz + 1) for j in range(ny + 1) for i in range(nx + 1)}
    elems, e, mids = [], eid0, {}
    nextid = [nid0 + (nx + 1) * (ny + 1) * (nz + 1)]

    def mid(a, b):
        key = (min(a, b), max(a, b))
        if key not in mids:
            nextid[0] += 1
            mids[key] = nextid[0]
            nodes[nextid[0]] = tuple(0.5 * (nodes[a][d] + nodes[b][d]) for d in range(3))
        return mids[key]

    def volume(c):
        a, b, cc, d = (nodes[n] for n in c[:4])
        u = [b[i] - a[i] for i in range(3)]
        v = [cc[i] - a[i] for i in range(3)]
        w = [d[i] - a[i] for i in range(3)]
        return (u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0]) + u[2] * (v[0] * w[1] - v[1] * w[0]))

    for k in range(nz):
        for j in range(ny):
            for i in range(nx):
                if is_shell(typ) and not SHELL_STACK2:  # the third direction (faces 1-2-3-4 to 5-6-7-8) along y, the stack direction
                    h = [nid(i, j, k), nid(i, j, k + 1), nid(i + 1, j, k + 1), nid(i + 1, j, k),
                         nid(i, j + 1, k), nid(i, j + 1, k + 1), nid(i + 1, j + 1, k + 1), nid(i + 1, j + 1, k)]
                    mirrored = [h[3], h[2], h[1], h[0], h[7], h[6], h[5], h[4]]
                else:
                    h = [nid(i, j, k), nid(i + 1, j, k), nid(i + 1, j + 1, k), nid(i, j + 1, k),
                         nid(i, j, k + 1), nid(i + 1, j, k + 1), nid(i + 1, j + 1, k + 1), nid(i, j + 1, k + 1)]
                    mirrored = [h[1], h[0], h[3], h[2], h[5], h[4], h[7], h[6]]
                if shape != "hex" and mirror is not None and x0 + (x1 - x0) * (i + 0.5) / nx > mirror:
                    h = mirrored  # the cut of the mirror image (left-handed)
                if shape == "hex":
                    cells = [h]
                elif shape == "wedge":  # the planar triangles (c1, c2, c3), (c1, c3, c4) extruded along z
                    cells = [[h[0], h[1], h[2], h[4], h[5], h[6]], [h[0], h[2], h[3], h[4], h[6], h[7]]]
                    for c in cells:
                        if volume([c[0], c[1], c[2], c[3]]) < 0:  # a mirrored cell: reverse each triangle
                            c[1], c[2], c[4], c[5] = c[2], c[1], c[5], c[4]
                else:
                    cells = []
                    for t in HEX_TETS:
                        c = [h[q] for q in t]
                        if volume(c) < 0:
                            c[1], c[2] = c[2], c[1]
                        if order == 2:
                            c = c + [mid(c[a], c[b]) for a, b in TET10_EDGES]
                        cells.append(c)
                for c in cells:
                    e += 1
                    elems.append((e,) + tuple(c))
    return nodes, elems, shape


def faces_on(nodes, elems, shape, y):
    """(element, S-number) of every face whose corners lie on the plane y."""
    out = []
    for el in elems:
        conn = el[1:]
        for f, corners in enumerate(FACES_3D[shape]):
            if all(abs(nodes[conn[c]][1] - y) < 1e-12 for c in corners):
                out.append((el[0], f + 1))
    return out


def shell_plate(nx, nz, x0, x1, z0, z1, y, nid0=0, eid0=0):
    """A plate of nx x nz S8RT elements on the plane y (its mid-surface): nodes {id: (x, y, z)}, elements
    [(id, 4 corners, 4 midsides)] with the corners (x, z), (x, z + dz), (x + dx, z + dz), (x + dx, z), so that
    the right-hand normal (x2 - x1) x (x4 - x1) is +y: SPOS is the upper face, SNEG the lower one."""
    NX, NZ = 2 * nx, 2 * nz
    nid = lambda i, k: nid0 + 1 + i + k * (NX + 1)
    nodes = {nid(i, k): (x0 + (x1 - x0) * i / NX, y, z0 + (z1 - z0) * k / NZ)
             for k in range(NZ + 1) for i in range(NX + 1) if not (i % 2 and k % 2)}
    elems = []
    for k in range(nz):
        for i in range(nx):
            I, K = 2 * i, 2 * k
            elems.append((eid0 + 1 + i + k * nx, nid(I, K), nid(I, K + 2), nid(I + 2, K + 2), nid(I + 2, K),
                          nid(I, K + 1), nid(I + 1, K + 2), nid(I + 2, K + 1), nid(I + 1, K)))
    return nodes, elems


def sliding_blocks_3d(series, typ, outdir=None, surf=False, explicit=None):
    """The spec's three series on 3D blocks (see above): the planar decks' loads and steps on faces of
    width 1 (small block) and 1.2 (large block), sliding along x, pressing along -y, z held on the small
    block's top face. Volume 6 x 1.25 x 1.2 + 2 x 0.25 x 1 = 9.5 (rho c = 1): the friction series ends at
    60 / 9.5. surf: TYPE=SURFACE TO SURFACE (job name *_surf_*). explicit: PENALTY or KINEMATIC, the
    series as explicit steps the way sliding_explicit writes the planar ones (2 cells across the small block;
    its top face moved along x and held in z, the friction series' force 200 as a pressure of 100 on it; job
    name sliding_<series>_explicit_<constraint>_<type>).
    typ S8RT (the spec's ei38tssr decks): each block a plate of S8RT shells on its mid-surface (normal +y;
    large: y = 0.625, thickness 1.25, 12 x 1 elements; small: y = 1.375, thickness 0.25, 4 x 3), which the
    reader expands into the blocks' volumes (two C3D20RT through each thickness: 24 elements in each block, so
    that slabs along y put them on different ranks). MAIN is the large plate's
    SPOS side, SECONDARY the small plate's SNEG side, the loads on the surfaces PRESSED (the small plate's
    SPOS) and FILMED (the large plate's SNEG under x in [2.5, 3.5]); BASE and TOPFACE are the plates' shell
    nodes, and a boundary condition on a shell node holds its whole fiber: BASE holds the large block
    entirely, TOPFACE moves the small block as a whole along x and z (the *EQUATIONs of the friction series
    tie the mid-surface nodes themselves)."""
    typ = typ.upper()
    shell = typ == "S8RT"
    if shell:
        assert not explicit
        bnodes, belems = shell_plate(12, 1, 0.0, 6.0, -0.1, 1.1, 0.625)
        tnodes, telems = shell_plate(4, 3, 2.0, 4.0, 0.0, 1.0, 1.375, 1000, 1000)
        base, topface = sorted(bnodes), sorted(tnodes)
        filmede = [e[0] for e in belems if all(2.5 - 1e-12 <= bnodes[n][0] <= 3.5 + 1e-12 for n in e[1:])]
        pressed, filmed = "PRESSED", "FILMED"  # the surfaces below
    else:
        bnodes, belems, shape = mesh3d(12, 2, 1, 0.0, 6.0, 0.0, 1.25, -0.1, 1.1, typ, mirror=3.0)
        tnodes, telems, _ = mesh3d(4, 2 if explicit else 6, 1, 2.0, 4.0, 1.25, 1.5, 0.0, 1.0, typ, 1000, 1000, mirror=3.0)
        main = faces_on(bnodes, belems, shape, 1.25)
        sec = faces_on(tnodes, telems, shape, 1.25)
        pressed = faces_on(tnodes, telems, shape, 1.5)
        base = sorted(n for n, c in bnodes.items() if abs(c[1]) < 1e-12)
        topface = sorted(n for n, c in tnodes.items() if abs(c[1] - 1.5) < 1e-12)
        # film on the large block's bottom under the small block (x in [2.5, 3.5]), all across the width
        filmed = [(e, f) for e, f in faces_on(bnodes, belems, shape, 0.0)
                  if all(2.5 - 1e-12 <= bnodes[n][0] <= 3.5 + 1e-12 for n in [dict((el[0], el[1:]) for el in belems)[e][c] for c in FACES_3D[shape][f - 1]])]

    def surface(name, faces):
        return "*SURFACE, NAME=%s, TYPE=ELEMENT\n" % name + "".join(" %d, S%d\n" % f for f in faces)

    def load_lines(faces, kind, value):
        if shell:  # a surface: PRESSED, P, 100.0
            return " %s, %s, %s\n" % (faces, kind, value)
        return "".join(" %d, %s%d, %s\n" % (e, kind, f, value) for e, f in faces)

    fmt = lambda nodes: "".join(" %d, %.10g, %.10g, %.10g\n" % ((n,) + nodes[n]) for n in sorted(nodes))
    text = ("*HEADING\n Finite sliding between coupled temperature-displacement %s blocks (3D): %s series\n" % (typ, series) +
            "*NODE, NSET=ALL\n" + fmt(bnodes) + "*NODE, NSET=ALL\n" + fmt(tnodes) +
            "*ELEMENT, TYPE=%s, ELSET=LARGE\n" % deck_type(typ) + "".join(" " + ", ".join(str(v) for v in e) + "\n" for e in belems) +
            "*ELEMENT, TYPE=%s, ELSET=SMALL\n" % deck_type(typ) + "".join(" " + ", ".join(str(v) for v in e) + "\n" for e in telems) +
            nset("BASE", base) + nset("TOPFACE", topface))
    if shell:
        text += (elset("FILMEDE", filmede) + "*SURFACE, NAME=MAIN, TYPE=ELEMENT\n LARGE, SPOS\n*SURFACE, NAME=SECONDARY, TYPE=ELEMENT\n SMALL, SNEG\n"
                 "*SURFACE, NAME=PRESSED, TYPE=ELEMENT\n SMALL, SPOS\n*SURFACE, NAME=FILMED, TYPE=ELEMENT\n FILMEDE, SNEG\n" + MAT +
                 "*SHELL SECTION, ELSET=LARGE, MATERIAL=STEEL\n 1.25\n*SHELL SECTION, ELSET=SMALL, MATERIAL=STEEL\n 0.25\n")
    else:
        damp = EXPLICIT_SHELL_DAMPING if explicit == "KINEMATIC" and series == "friction" and is_shell(typ) else ""
        text += surface("MAIN", main) + surface("SECONDARY", sec) + MAT + damp + section(typ, "LARGE") + section(typ, "SMALL")
    # the flux and film keywords of element faces (S3, F1, ...) or of surfaces
    dflux, film = ("*DSFLUX", "*SFILM") if shell else ("*DFLUX", "*FILM")
    if explicit:
        assert not surf
        text = text.replace("%s series\n" % series, "%s series, explicit, %s contact\n" % (series, explicit.lower()), 1)
        text += (series_interaction(series).replace("SMOOTH=0.05", "SMOOTH=0.05, MECHANICAL CONSTRAINT=%s" % explicit)
                 .replace("*AMPLITUDE, NAME=SLIDE\n 0.0, 0.0, 1.0, 1.0, 2.0, -1.0, 3.0, 0.0\n", ""))  # the smooth legs below
        text += explicit_steps(series, " BASE, 1, 3\n TOPFACE, 1, 1\n TOPFACE, 3, 3\n", "1", "2",
                               lambda kind, value: load_lines(pressed, kind, value), load_lines(filmed, "F", "0.0, 10.0"), "100.0",
                               constraint=explicit)
        if damp:  # *DAMPING, BETA= has the small-strain damping stress: these steps keep small strain (NLGEOM, the explicit default, refuses it)
            text = text.replace("*STEP, NAME=", "*STEP, NLGEOM=NO, NAME=")
        name = "sliding_%s_explicit_%s_%s.inp" % (series, explicit.lower(), typ.lower())
        with open(os.path.join(outdir or HERE, name), "w") as f:
            f.write(text)
        return
    text += series_interaction(series, surf=surf)
    if series == "friction":
        ref = topface[0]
        text += "".join("*EQUATION\n 2\n %d, %d, 1.0, %d, %d, -1.0\n" % (n, d, ref, d) for n in topface[1:] for d in (1, 2, 3))
        text += ("*STEP, NAME=PRESS, INC=100\n*COUPLED TEMPERATURE-DISPLACEMENT\n 0.5, 1.0\n"
                 "*BOUNDARY\n BASE, 1, 3\n %d, 1, 1\n %d, 3, 3\n*CLOAD\n %d, 2, -200.0\n*END STEP\n" % (ref, ref, ref) +
                 "*STEP, NAME=SLIDE, INC=1000\n*COUPLED TEMPERATURE-DISPLACEMENT\n 0.025, 3.0, 1e-5, 0.025\n"
                 "*BOUNDARY, AMPLITUDE=SLIDE\n %d, 1, 1, 1.5\n*END STEP\n" % ref +
                 "*STEP, NAME=EQUILIBRATE, INC=1000\n*COUPLED TEMPERATURE-DISPLACEMENT\n 0.1, 20.0, 1e-5, 2.0\n*END STEP\n")
    else:
        text += ("*AMPLITUDE, NAME=OFF\n 0.0, 0.0, 1.0, 1.0\n*AMPLITUDE, NAME=FLUXDOWN\n 0.0, 1.0, 0.1, 0.0\n"
                 "*STEP, NAME=HEAT, INC=100\n*COUPLED TEMPERATURE-DISPLACEMENT\n 0.1, 1.0, 1e-5, 0.1\n"
                 "*BOUNDARY\n BASE, 1, 3\n TOPFACE, 1, 1\n TOPFACE, 3, 3\n*DLOAD\n" + load_lines(pressed, "P", "100.0") +
                 dflux + "\n" + load_lines(pressed, "S", "100.0") + film + "\n" + load_lines(filmed, "F", "0.0, 10.0") + "*END STEP\n"
                 "*STEP, NAME=SLIDE, INC=1000\n*COUPLED TEMPERATURE-DISPLACEMENT\n 0.05, 3.0, 1e-5, 0.05\n"
                 "*BOUNDARY, AMPLITUDE=SLIDE\n TOPFACE, 1, 1, 1.5\n*END STEP\n"
                 "*STEP, NAME=STEADY\n*COUPLED TEMPERATURE-DISPLACEMENT, STEADY STATE\n 1.0, 1.0\n*END STEP\n"
                 "*STEP, NAME=DOUBLE PRESSURE\n*COUPLED TEMPERATURE-DISPLACEMENT, STEADY STATE\n 1.0, 1.0\n"
                 "*DLOAD\n" + load_lines(pressed, "P", "200.0") + "*END STEP\n"
                 "*STEP, NAME=SLIDE OFF, INC=1000\n*COUPLED TEMPERATURE-DISPLACEMENT\n 0.05, 3.0, 1e-5, 0.1\n"
                 "*DLOAD, OP=NEW\n*BOUNDARY, FIXED\n TOPFACE, 2, 2\n*BOUNDARY, AMPLITUDE=OFF\n TOPFACE, 1, 1, 5.0\n" +
                 dflux + ", AMPLITUDE=FLUXDOWN\n" + load_lines(pressed, "S", "100.0") + "*END STEP\n")
    name = "sliding_%s%s_%s.inp" % (series, "_surf" if surf else "", typ.lower())
    with open(os.path.join(outdir or HERE, name), "w") as f:
        f.write(text)


def friction_cycle(law):
    """Issue 8, items 7 and 8: the friction series' two blocks (sliding_blocks) with a pressure of 75 on
    the top of the small block, mu = 0.2, slid +1.25, -2.5, +1.25 over 4 s (slip path 5): dissipation
    mu p A path = 0.2 * 75 * 2 * 5 = 150, half of it (eta = 0.5) heats the blocks to 75 / (rho c area 8)
    = 9.375 after the equilibration step. law: "lagrange" (*FRICTION, LAGRANGE) or "penalty" (plain
    *FRICTION: the default penalty stick, whose elastic slip withholds a little heat)."""
    sliding_blocks("friction")
    with open(os.path.join(HERE, "sliding_friction_cpe4t.inp")) as f:
        text = f.read()
    head = text[:text.index("*STEP")]
    head = head.replace("friction series", "friction cycle, %s friction, pressure 75, slip path 5" % law)
    head = head.replace("*FRICTION, LAGRANGE\n 0.1\n", "*FRICTION%s\n 0.2\n" % (", LAGRANGE" if law == "lagrange" else ""))
    head = head.replace("*AMPLITUDE, NAME=SLIDE\n 0.0, 0.0, 1.0, 1.0, 2.0, -1.0, 3.0, 0.0\n",
                        "*AMPLITUDE, NAME=SLIDE\n 0.0, 0.0, 1.0, 1.0, 3.0, -1.0, 4.0, 0.0\n")
    # the top face is driven in x node by node and free in y (no constraint equations): the block may
    # tilt, which is what made Newton's first iterate of each increment open the contact (item 7)
    head = re.sub(r"\*EQUATION\n 2\n[^\n]*\n", "", head)
    head += ("*STEP, NAME=PRESS, INC=100\n*COUPLED TEMPERATURE-DISPLACEMENT\n 0.5, 1.0\n"
             "*BOUNDARY\n BASE, 1, 2\n TOPFACE, 1, 1\n*DLOAD\n PRESSED, P3, 75.0\n*END STEP\n"
             "*STEP, NAME=SLIDE, INC=1000\n*COUPLED TEMPERATURE-DISPLACEMENT\n 0.02, 4.0, 1e-5, 0.05\n"
             "*BOUNDARY, AMPLITUDE=SLIDE\n TOPFACE, 1, 1, 1.25\n*END STEP\n" +
             "*STEP, NAME=EQUILIBRATE, INC=1000\n*COUPLED TEMPERATURE-DISPLACEMENT\n 0.1, 20.0, 1e-5, 2.0\n*END STEP\n")
    write("sliding_friction_cycle_%s_cpe4t.inp" % law, head)


def steady_touching():
    """Issue 8, item 2: the conductance series' blocks, exactly touching (shared interface coordinate), in
    a steady first step: pressure 100 and flux 100 on the top of the small block, film h = 10 (sink 0) on
    the centre of the large block's bottom, pressure-dependent conductance (20 at p <= 100, 5 at 200).
    At steady state the flux in (100 * area 2 = 200) crosses the interface and leaves through the film.
    A second steady step doubles the pressure."""
    sliding_blocks("conductance")
    with open(os.path.join(HERE, "sliding_conductance_cpe4t.inp")) as f:
        text = f.read()
    head = text[:text.index("*STEP")]
    head = head.replace("conductance series", "conductance series, steady first step from exact touching")
    head = head[:head.index("*AMPLITUDE")] + "*INITIAL CONDITIONS, TYPE=TEMPERATURE\n ALL, 0.0\n"
    head += ("*STEP, NAME=STEADY\n*COUPLED TEMPERATURE-DISPLACEMENT, STEADY STATE\n 1.0, 1.0\n"
             "*BOUNDARY\n BASE, 1, 2\n TOPFACE, 1, 1\n*DLOAD\n PRESSED, P3, 100.0\n*DFLUX\n PRESSED, S3, 100.0\n"
             "*FILM\n FILMED, F1, 0.0, 10.0\n*END STEP\n"
             "*STEP, NAME=DOUBLE PRESSURE\n*COUPLED TEMPERATURE-DISPLACEMENT, STEADY STATE\n 1.0, 1.0\n"
             "*DLOAD\n PRESSED, P3, 200.0\n*END STEP\n")
    write("contact_steady_touching_cpe4t.inp", head)


def contact_jacobian():
    """A block (1 element) on a block (2 x 1 elements) with every interface law active, in three steps
    that put the contact in stick, slip and open states: for -snes_test_jacobian. Materials scaled so
    that the mechanical, coupling and thermal blocks of the Jacobian have entries of similar size."""
    bnodes, belems = grid2d(2, 1, 0.0, 2.0, 0.0, 1.0)
    tnodes, telems = grid2d(1, 1, 0.5, 1.5, 1.0 - 1e-4, 2.0)  # slightly overclosed: no kink at the start
    tnodes = [(n + 100, x, y) for n, x, y in tnodes]
    telems = [(e[0] + 100,) + tuple(v + 100 for v in e[1:]) for e in telems]
    write("contact_jacobian_cpe4t.inp",
          "*HEADING\n Contact Jacobian check: stick, slip and open states with conductance, radiation, frictional heat\n" +
          fmt_nodes(bnodes) + "*NODE, NSET=ALL\n" + "".join(" %d, %.10g, %.10g\n" % n for n in tnodes) +
          "*ELEMENT, TYPE=CPE4T, ELSET=LOWER\n" + "".join(" " + ", ".join(str(v) for v in e) + "\n" for e in belems) +
          "*ELEMENT, TYPE=CPE4T, ELSET=UPPER\n" + "".join(" " + ", ".join(str(v) for v in e) + "\n" for e in telems) +
          nset("BASE", [1, 2, 3]) + nset("TOP", [103, 104]) + elset("BODY", [1, 2, 101]) +
          "*SURFACE, NAME=MAIN\n LOWER, S3\n*SURFACE, NAME=SECONDARY\n 101, S1\n"
          "*MATERIAL, NAME=SOFT\n*ELASTIC\n 1000.0, 0.3\n*CONDUCTIVITY\n 10.0\n*DENSITY\n 1.0\n*SPECIFIC HEAT\n 1.0\n"
          "*SOLID SECTION, ELSET=BODY, MATERIAL=SOFT\n 1.0\n"
          "*PHYSICAL CONSTANTS, ABSOLUTE ZERO=-273.16, STEFAN BOLTZMANN=1.0\n"
          "*SURFACE INTERACTION, NAME=ALL LAWS\n*FRICTION\n 0.2\n*GAP CONDUCTANCE, PRESSURE\n 20.0, 0.0\n 5.0, 20.0\n"
          "*GAP RADIATION\n 1.0, 1.0\n 1.0E-6, 0.0\n 1.0E-6, 0.5\n*GAP HEAT GENERATION\n 0.5, 0.5\n"
          "*CONTACT PAIR, INTERACTION=ALL LAWS, SMOOTH=0.05\n SECONDARY, MAIN\n"
          "*INITIAL CONDITIONS, TYPE=TEMPERATURE\n ALL, 20.0\n"
          "*STEP, NAME=STICK\n*COUPLED TEMPERATURE-DISPLACEMENT, DIRECT\n 0.1, 0.1\n"
          # the top of the upper block is driven: pressed (about 10 of contact pressure), then moved
          # sideways a little (stick) and a lot (slip), then lifted (open, radiation across the gap)
          "*BOUNDARY\n BASE, 1, 2\n BASE, 11, 11, 20.0\n TOP, 1, 1, 1.0E-5\n TOP, 2, 2, -0.011\n*DFLUX\n 101, S3, 50.0\n*END STEP\n"
          "*STEP, NAME=SLIP\n*COUPLED TEMPERATURE-DISPLACEMENT, DIRECT\n 0.1, 0.1\n*BOUNDARY\n TOP, 1, 1, 0.1\n*END STEP\n"
          "*STEP, NAME=OPEN\n*COUPLED TEMPERATURE-DISPLACEMENT, DIRECT\n 0.1, 0.1\n"
          "*BOUNDARY\n TOP, 2, 2, 0.05\n*END STEP\n")


def temperature_tables():
    """Temperature-dependent conductivity and specific heat (issue 6): a bar 1 x 0.1 (40 x 1 CPE4T).
    Step 1, steady: theta = 0 at x = 0 and 100 at x = 1 with k = 10 at 0 and 30 at 100 (linear):
    the heat flux q = -k(theta) theta' is uniform, and the Kirchhoff transform K(theta) = int_0^theta k
    = 10 theta + 0.1 theta^2 is linear in x:
    10 theta + 0.1 theta^2 = 2000 x; q = 2000 (per unit area, thickness 1 and height 0.1: RFL = 200 total).
    Step 2, transient: both ends insulated (the temperatures released), a flux of 500 per area into the
    face x = 0 for 1 s: the heat stored, sum over nodes of rho V_a (e(theta_a) - e(theta_a, start)) with
    e(theta) = int_0^theta c = theta + theta^2 / 400 (c = 1 at 0, 2 at 200; rho = 1), equals 500 x 0.1."""
    nodes, elems = grid2d(40, 1, 0.0, 1.0, 0.0, 0.1)
    left = [n[0] for n in nodes if abs(n[1]) < 1e-12]
    right = [n[0] for n in nodes if abs(n[1] - 1.0) < 1e-12]
    write("conduction_tables_cpe4t.inp",
          "*HEADING\n Temperature-dependent conductivity and specific heat: Kirchhoff profile and stored heat\n" +
          fmt_nodes(nodes) + fmt_elems(elems, "CPE4T") + nset("LEFT", left) + nset("RIGHT", right) + elset("FIRST", [1]) +
          "*MATERIAL, NAME=TABLES\n*ELASTIC\n 1000.0, 0.3\n*CONDUCTIVITY\n 10.0, 0.0\n 30.0, 100.0\n*DENSITY\n 1.0\n"
          "*SPECIFIC HEAT\n 1.0, 0.0\n 2.0, 200.0\n*SOLID SECTION, ELSET=BODY, MATERIAL=TABLES\n 1.0\n"
          "*INITIAL CONDITIONS, TYPE=TEMPERATURE\n ALL, 0.0\n"
          "*STEP, NAME=KIRCHHOFF\n*COUPLED TEMPERATURE-DISPLACEMENT, STEADY STATE\n 1.0, 1.0\n"
          "*BOUNDARY\n ALL, 1, 2\n LEFT, 11, 11, 0.0\n RIGHT, 11, 11, 100.0\n*END STEP\n"
          "*STEP, NAME=HEAT UP, INC=100\n*COUPLED TEMPERATURE-DISPLACEMENT\n 0.05, 1.0\n"
          "*BOUNDARY, OP=NEW\n ALL, 1, 2\n*DFLUX\n FIRST, S4, 500.0\n*END STEP\n")


if __name__ == "__main__":
    import sys
    if len(sys.argv) >= 5 and sys.argv[1] == "--sliding":
        # the suite's per-type decks: make_decks.py --sliding TYPE SERIES OUTDIR [--auglagr] [--surf] [--refine=N] [--stack2] [--film-amplitude]
        # (TYPE S8RT: the blocks as shell plates, sliding_blocks_3d; SAX2T: the small ring as shells on a CAX8T ring, sliding_blocks)
        flags = sys.argv[5:]
        if "--stack2" in flags:
            assert sys.argv[2].upper() == "SC8RT", "--stack2: SC8RT only (a wedge stacks along its third direction)"
            SHELL_STACK2 = True
        refine = [int(f.split("=")[1]) for f in flags if f.startswith("--refine=")]
        if sys.argv[2].upper().startswith(("C3D", "SC", "S8")):
            sliding_blocks_3d(sys.argv[3], typ=sys.argv[2], outdir=sys.argv[4], surf="--surf" in flags)
        else:
            sliding_blocks(sys.argv[3], typ=sys.argv[2], outdir=sys.argv[4], auglagr="--auglagr" in flags, surf="--surf" in flags,
                           refine=refine[0] if refine else 1, film_amplitude="--film-amplitude" in flags)
        sys.exit(0)
    if len(sys.argv) == 6 and sys.argv[1] == "--explicit-series":
        # the spec's explicit decks per type: make_decks.py --explicit-series TYPE SERIES PENALTY|KINEMATIC OUTDIR
        typ, series, constraint, outdir = sys.argv[2].upper(), sys.argv[3], sys.argv[4].upper(), sys.argv[5]
        if typ.startswith(("C3D", "SC")):
            sliding_blocks_3d(series, typ, outdir=outdir, explicit=constraint)
        else:
            sliding_explicit(series, constraint, typ=typ, outdir=outdir)
        sys.exit(0)
    if len(sys.argv) >= 2 and sys.argv[1] == "--explicit":
        for series in ("friction", "conductance"):
            for constraint in ("PENALTY", "KINEMATIC"):
                sliding_explicit(series, constraint)
        sliding_explicit("radiation", "KINEMATIC")
        for series in ("friction", "conductance"):  # the axisymmetric rings
            sliding_explicit(series, "KINEMATIC", typ="CAX4T")
        for series in ("friction", "conductance"):  # surface-to-surface, penalty
            sliding_explicit(series, "PENALTY", surf=True)
        # the 3D friction series (the spec's coupledtemplgslcont_f_c3d8t, _fpc3d8rt and _f_c3d10mt)
        sliding_blocks_3d("friction", "C3D8T", explicit="KINEMATIC")
        sliding_blocks_3d("friction", "C3D8RT", explicit="PENALTY")
        sliding_blocks_3d("friction", "C3D10MT", explicit="KINEMATIC")
        sys.exit(0)
    contact_jacobian()
    temperature_tables()
    for series in ("conductance", "radiation", "friction"):
        sliding_blocks(series)
    sliding_blocks("conductance", auglagr=True)
    friction_cycle("lagrange")
    friction_cycle("penalty")
    steady_touching()
    loads_multistep()
    for t in ("CPE4T", "CPS4T", "CAX4T", "C3D8T"):
        conduction_steady(t)
        expansion(t, False)
        expansion(t, True)
    conduction_transient()
    jacobian_case()
