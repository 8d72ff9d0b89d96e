#!/usr/bin/python3
"""Writes the decks of tests/dload/decks/ (*DLOAD GRAV and CENTRIF; the checks in check_dload.py).

Steel in SI units, E = 2e11, rho = 7800, nu = 0 (so that the column's 1D stress state and the disc's plane
stress state are exact solutions of the continuum: the elements' nodal values are then exact for the
column, and second-order accurate for the disc).
usage: make_decks.py (writes beside itself)
"""
import math
import os

HERE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "decks")
MAT = """*MATERIAL, NAME=STEEL
*ELASTIC
2e11, 0.0
*CONDUCTIVITY
50.
*DENSITY
7800.
*SPECIFIC HEAT
450.
"""


def nodes_2d(xs, ys):
    ids, lines = {}, []
    for j, y in enumerate(ys):
        for i, x in enumerate(xs):
            ids[i, j] = len(ids) + 1
            lines.append("%d, %.17g, %.17g" % (ids[i, j], x, y))
    return ids, lines


def quads(ids, nx, ny):
    out = []
    for j in range(ny):
        for i in range(nx):
            out.append("%d, %d, %d, %d, %d" % (len(out) + 1, ids[i, j], ids[i + 1, j], ids[i + 1, j + 1], ids[i, j + 1]))
    return out


def write(name, text):
    with open(os.path.join(HERE, name), "w") as f:
        f.write(text)


def column_2d(typ, procedure, thickness, x0, width):
    """A column of height 1 along y, width `width` from x0, 2 x 10 elements, its own weight pulling in -y."""
    nx, ny = 2, 10
    xs = [x0 + width * i / nx for i in range(nx + 1)]
    ys = [i / ny for i in range(ny + 1)]
    ids, nl = nodes_2d(xs, ys)
    bottom = [ids[i, 0] for i in range(nx + 1)]
    top = [ids[i, ny] for i in range(nx + 1)]
    coupled = procedure.startswith("*COUPLED")
    text = "*HEADING\nColumn under its own weight, %s (tests/dload/check_dload.py column)\n" % typ
    text += "*NODE, NSET=NALL\n" + "\n".join(nl) + "\n"
    text += "*ELEMENT, TYPE=%s, ELSET=EALL\n" % typ + "\n".join(quads(ids, nx, ny)) + "\n"
    text += "*NSET, NSET=BOTTOM\n" + ", ".join(map(str, bottom)) + "\n"
    text += "*NSET, NSET=TOP\n" + ", ".join(map(str, top)) + "\n"
    text += "*NSET, NSET=PIN\n%d\n" % ids[0, 0]
    text += MAT + "*SOLID SECTION, ELSET=EALL, MATERIAL=STEEL\n%s\n" % (thickness if thickness else "")
    if coupled:
        text += "*INITIAL CONDITIONS, TYPE=TEMPERATURE\nNALL, 20.\n"
    text += "*STEP, NAME=WEIGHT\n%s\n" % procedure
    text += "*BOUNDARY\nBOTTOM, 2, 2\n"
    if typ.startswith("CPS") or typ.startswith("CPE"):
        text += "PIN, 1, 1\n"
    if coupled:
        text += "NALL, 11, 11, 20.\n"
    text += "*DLOAD\nEall, GRAV, 9.81, 0., -1., 0.\n*NODE PRINT, NSET=BOTTOM, TOTALS=ONLY\nRF\n*END STEP\n"
    # OP=NEW with no data lines removes the weight: the column springs back
    text += "*STEP, NAME=UNLOAD\n%s\n*DLOAD, OP=NEW\n*END STEP\n" % procedure
    return text


def column_3d():
    """A column 0.1 x 0.1 x 1 along z, 2 x 2 x 10 C3D8T, gravity given as (0, 0, -2) (normalised by the reader)."""
    n, nz, a = 2, 10, 0.1
    ids, lines = {}, []
    for k in range(nz + 1):
        for j in range(n + 1):
            for i in range(n + 1):
                ids[i, j, k] = len(ids) + 1
                lines.append("%d, %.17g, %.17g, %.17g" % (ids[i, j, k], a * i / n, a * j / n, k / nz))
    el = []
    for k in range(nz):
        for j in range(n):
            for i in range(n):
                c = [ids[i, j, k], ids[i + 1, j, k], ids[i + 1, j + 1, k], ids[i, j + 1, k]]
                c += [ids[i, j, k + 1], ids[i + 1, j, k + 1], ids[i + 1, j + 1, k + 1], ids[i, j + 1, k + 1]]
                el.append("%d, " % (len(el) + 1) + ", ".join(map(str, c)))
    bottom = [ids[i, j, 0] for j in range(n + 1) for i in range(n + 1)]
    text = "*HEADING\nColumn under its own weight, C3D8T (tests/dload/check_dload.py column)\n"
    text += "*NODE, NSET=NALL\n" + "\n".join(lines) + "\n*ELEMENT, TYPE=C3D8T, ELSET=EALL\n" + "\n".join(el) + "\n"
    text += "*NSET, NSET=BOTTOM\n" + ", ".join(map(str, bottom)) + "\n"
    text += MAT + "*SOLID SECTION, ELSET=EALL, MATERIAL=STEEL\n"
    text += "*STEP, NAME=WEIGHT\n*STATIC\n*BOUNDARY\nBOTTOM, 3, 3\n%d, 1, 2\n%d, 2, 2\n" % (ids[0, 0, 0], ids[n, 0, 0])
    text += "*DLOAD\nEALL, GRAV, 9.81, 0., 0., -2.\n*END STEP\n"
    text += "*STEP, NAME=UNLOAD\n*STATIC\n*DLOAD, OP=NEW\n*END STEP\n"
    return text


def disc_cax4t(a, b, h, nr):
    """An annular disc a < r < b of height h spinning about its axis (CAX4T, nr x 1 elements), held at z = 0 in z."""
    xs = [a + (b - a) * i / nr for i in range(nr + 1)]
    ids, nl = nodes_2d(xs, [0.0, h])
    text = "*HEADING\nSpinning annular disc, CAX4T (tests/dload/check_dload.py disc)\n"
    text += "*NODE, NSET=NALL\n" + "\n".join(nl) + "\n*ELEMENT, TYPE=CAX4T, ELSET=EALL\n" + "\n".join(quads(ids, nr, 1)) + "\n"
    text += "*NSET, NSET=BOTTOM\n" + ", ".join(str(ids[i, 0]) for i in range(nr + 1)) + "\n"
    text += MAT + "*SOLID SECTION, ELSET=EALL, MATERIAL=STEEL\n"
    text += "*AMPLITUDE, NAME=SPIN\n0., 0., 1., 1.\n"
    text += "*STEP, NAME=SPIN\n*STATIC\n*BOUNDARY\nBOTTOM, 2, 2\n"
    text += "*DLOAD, AMPLITUDE=SPIN\nEALL, CENTRIF, 1e4, 0., 0., 0., 0., 1., 0.\n*END STEP\n"
    return text


def quarter_disc_cps4t(a, b, t, nr, nt):
    """A quarter of an annular plate a < r < b (CPS4T, thickness t) spinning about z through the origin; symmetry
    edges x = 0 (u1 = 0) and y = 0 (u2 = 0)."""
    ids, nl = {}, []
    for j in range(nt + 1):
        th = 0.5 * math.pi * j / nt
        for i in range(nr + 1):
            r = a + (b - a) * i / nr
            ids[i, j] = len(ids) + 1
            x, y = (r * math.cos(th), r * math.sin(th))
            if j == nt:
                x = 0.0
            nl.append("%d, %.17g, %.17g" % (ids[i, j], x, y))
    text = "*HEADING\nSpinning quarter plate, CPS4T (tests/dload/check_dload.py quarter)\n"
    text += "*NODE, NSET=NALL\n" + "\n".join(nl) + "\n*ELEMENT, TYPE=CPS4T, ELSET=EALL\n" + "\n".join(quads(ids, nr, nt)) + "\n"
    text += "*NSET, NSET=XAXIS\n" + ", ".join(str(ids[i, 0]) for i in range(nr + 1)) + "\n"
    text += "*NSET, NSET=YAXIS\n" + ", ".join(str(ids[i, nt]) for i in range(nr + 1)) + "\n"
    text += MAT + "*SOLID SECTION, ELSET=EALL, MATERIAL=STEEL\n%g\n" % t
    text += "*STEP, NAME=SPIN\n*COUPLED TEMPERATURE-DISPLACEMENT, STEADY STATE\n*BOUNDARY\nXAXIS, 2, 2\nYAXIS, 1, 1\nNALL, 11, 11, 20.\n"
    text += "*DLOAD\nEALL, CENTRIF, 1e4, 0., 0., 0.5, 0., 0., -3.\n*END STEP\n"
    return text


def freefall():
    """An unsupported block 0.1 x 0.1 x 0.1 (2 x 2 x 2 C3D8T) falling under gravity in an explicit step."""
    n, a = 2, 0.1
    ids, lines = {}, []
    for k in range(n + 1):
        for j in range(n + 1):
            for i in range(n + 1):
                ids[i, j, k] = len(ids) + 1
                lines.append("%d, %.17g, %.17g, %.17g" % (ids[i, j, k], a * i / n, a * j / n, a * k / n))
    el = []
    for k in range(n):
        for j in range(n):
            for i in range(n):
                c = [ids[i, j, k], ids[i + 1, j, k], ids[i + 1, j + 1, k], ids[i, j + 1, k]]
                c += [ids[i, j, k + 1], ids[i + 1, j, k + 1], ids[i + 1, j + 1, k + 1], ids[i, j + 1, k + 1]]
                el.append("%d, " % (len(el) + 1) + ", ".join(map(str, c)))
    text = "*HEADING\nFree fall under gravity, explicit, C3D8T (tests/dload/check_dload.py freefall)\n"
    text += "*NODE, NSET=NALL\n" + "\n".join(lines) + "\n*ELEMENT, TYPE=C3D8T, ELSET=EALL\n" + "\n".join(el) + "\n"
    text += MAT + "*SOLID SECTION, ELSET=EALL, MATERIAL=STEEL\n*INITIAL CONDITIONS, TYPE=TEMPERATURE\nNALL, 20.\n"
    text += "*STEP, NAME=FALL\n*DYNAMIC TEMPERATURE-DISPLACEMENT, EXPLICIT\n, 2e-4\n"
    text += "*DLOAD\nEALL, GRAV, 9.81, 0., 0., -1.\n*OUTPUT, FIELD, NUMBER INTERVAL=4\n*NODE OUTPUT\nU\n*END STEP\n"
    return text


def plate_sc8rt():
    """A plate 1 x 1 x 0.02 of 4 x 4 SC8RT continuum shells lying on z = 0 (held there in z), its weight in -z."""
    n, h = 4, 0.02
    ids, lines = {}, []
    for k in range(2):
        for j in range(n + 1):
            for i in range(n + 1):
                ids[i, j, k] = len(ids) + 1
                lines.append("%d, %.17g, %.17g, %.17g" % (ids[i, j, k], i / n, j / n, h * k))
    el = []
    for j in range(n):
        for i in range(n):
            c = [ids[i, j, 0], ids[i + 1, j, 0], ids[i + 1, j + 1, 0], ids[i, j + 1, 0]]
            c += [ids[i, j, 1], ids[i + 1, j, 1], ids[i + 1, j + 1, 1], ids[i, j + 1, 1]]
            el.append("%d, " % (len(el) + 1) + ", ".join(map(str, c)))
    bottom = [ids[i, j, 0] for j in range(n + 1) for i in range(n + 1)]
    text = "*HEADING\nPlate of continuum shells under its own weight, SC8RT (tests/dload/check_dload.py weight)\n"
    text += "*NODE, NSET=NALL\n" + "\n".join(lines) + "\n*ELEMENT, TYPE=SC8RT, ELSET=EALL\n" + "\n".join(el) + "\n"
    text += "*NSET, NSET=BOTTOM\n" + ", ".join(map(str, bottom)) + "\n"
    text += MAT + "*SHELL SECTION, ELSET=EALL, MATERIAL=STEEL\n0.02\n"
    text += "*STEP, NAME=WEIGHT\n*STATIC\n*BOUNDARY\nBOTTOM, 3, 3\n%d, 1, 2\n%d, 2, 2\n" % (ids[0, 0, 0], ids[n, 0, 0])
    text += "*DLOAD\nEALL, GRAV, 9.81, 0., 0., -1.\n*END STEP\n"
    return text


def freefall_cps4t():
    """freefall in 2D (CPS4T 2 x 2, gravity -y), its modulus given as a table in temperature, which keeps the
    elements off the explicit force records: the generic path of the body force in an explicit step."""
    n, a = 2, 0.1
    ids, nl = nodes_2d([a * i / n for i in range(n + 1)], [a * j / n for j in range(n + 1)])
    mat = MAT.replace("2e11, 0.0\n", "2e11, 0.0, 0.\n2e11, 0.0, 100.\n")
    text = "*HEADING\nFree fall under gravity, explicit, CPS4T off the force records (tests/dload/check_dload.py freefall)\n"
    text += "*NODE, NSET=NALL\n" + "\n".join(nl) + "\n*ELEMENT, TYPE=CPS4T, ELSET=EALL\n" + "\n".join(quads(ids, n, n)) + "\n"
    text += mat + "*SOLID SECTION, ELSET=EALL, MATERIAL=STEEL\n0.02\n*INITIAL CONDITIONS, TYPE=TEMPERATURE\nNALL, 20.\n"
    text += "*STEP, NAME=FALL\n*DYNAMIC TEMPERATURE-DISPLACEMENT, EXPLICIT\n, 2e-4\n"
    text += "*DLOAD\n1, GRAV, 9.81, 0., -1., 0.\n2, GRAV, 9.81, 0., -1., 0.\n3, GRAV, 9.81, 0., -1., 0.\n4, GRAV, 9.81, 0., -1., 0.\n"
    text += "*OUTPUT, FIELD, NUMBER INTERVAL=4\n*NODE OUTPUT\nU\n*END STEP\n"
    return text


def shell_s8rt(target):
    """Two S8RT conventional shells (1 x 0.5 each, thickness 0.1) held at their corners, under their own weight
    given by element ids (each shell's two expanded elements must both carry it) or by set."""
    xy = [(0, 0), (1, 0), (1, 1), (0, 1), (0.5, 0), (1, 0.5), (0.5, 1), (0, 0.5)]
    nodes = []
    for k, (x, y) in enumerate(xy):
        nodes.append("%d, %g, %g, 0." % (k + 1, x, 0.5 * y))
        nodes.append("%d, %g, %g, 0." % (k + 11, x, 0.5 + 0.5 * y))
    el = ["1, 1, 2, 3, 4, 5, 6, 7, 8", "2, 11, 12, 13, 14, 15, 16, 17, 18"]
    text = "*HEADING\nTwo conventional shells under their own weight, S8RT (tests/dload/check_dload.py weight)\n"
    text += "*NODE, NSET=NALL\n" + "\n".join(nodes) + "\n*NODE\n"
    text = text.replace("\n*NODE\n", "\n")
    text += "*ELEMENT, TYPE=S8RT, ELSET=EALL\n" + "\n".join(el) + "\n"
    text += "*NSET, NSET=CORNERS\n1, 2, 13, 14\n"
    text += MAT + "*SHELL SECTION, ELSET=EALL, MATERIAL=STEEL\n0.1\n"
    text += "*STEP, NAME=WEIGHT\n*STATIC\n*BOUNDARY\nCORNERS, 1, 3\n"
    text += "*DLOAD\n" + ("1, GRAV, 9.81, 0., 0., -1.\n2, GRAV, 9.81, 0., 0., -1.\n" if target == "ids" else "EALL, GRAV, 9.81, 0., 0., -1.\n")
    text += "*END STEP\n"
    return text


os.makedirs(HERE, exist_ok=True)
write("grav_shell_ids_s8rt.inp", shell_s8rt("ids"))
write("grav_freefall_cps4t.inp", freefall_cps4t())
write("grav_plate_sc8rt.inp", plate_sc8rt())
write("grav_column_c3d8t.inp", column_3d())
write("grav_column_cps4t.inp", column_2d("CPS4T", "*COUPLED TEMPERATURE-DISPLACEMENT, STEADY STATE", 0.05, 0.0, 0.1))
write("grav_column_transient_cps4t.inp", column_2d("CPS4T", "*COUPLED TEMPERATURE-DISPLACEMENT\n0.5, 1.", 0.05, 0.0, 0.1))
write("grav_column_cax4t.inp", column_2d("CAX4T", "*STATIC", None, 0.0, 0.1))
write("centrif_disc_cax4t.inp", disc_cax4t(0.1, 0.3, 0.01, 40))
write("centrif_quarter_cps4t.inp", quarter_disc_cps4t(0.1, 0.3, 0.01, 16, 32))
write("grav_freefall_c3d8t.inp", freefall())
