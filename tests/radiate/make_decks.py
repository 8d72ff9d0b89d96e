"""Writes the radiation decks of tests/radiate/decks (committed; run again after a change here).

plate_c3d8t      a thin plate (1 x 1 x 0.01, 4 x 4 x 1 C3D8T, aluminium-like rho c = 2700 x 900, k = 1e6 so that it stays
                 isothermal) at 726.85 C radiating from its top face (*RADIATE, R2, emissivity 0.8) to an ambient of
                 26.85 C, on the Celsius scale (ABSOLUTE ZERO=-273.15): a transient step of 600 s in 30 fixed
                 increments; displacements held
plate_explicit_c3d8t  the same cooling in an explicit step (*DYNAMIC TEMPERATURE-DISPLACEMENT, EXPLICIT), on a plate
                 0.001 thick (2 x 2 x 1 elements) with rho c V = 2.43, so that it cools in 0.06 s
steady_cpe8t     a bar 2 x 0.5 (4 x 1 CPE8T, k = 20, thickness 1) heated by a flux q = 5000 on x = 0 (*DFLUX S4) and
                 radiating from x = 2 (*SRADIATE on a surface, emissivity 0.6) in kelvin (ABSOLUTE ZERO=0) to 300 K,
                 steady; step 2 the ambient under AMPLITUDE= (x 1.5: 450 K) and the emissivity under RADIATION
                 AMPLITUDE= (x 0.5: 0.3), step 3 *RADIATE, OP=NEW on the same surface with CalculiX's label R0 at 500 K, emissivity 1
jacobian_cpe4t   distorted CPE4T with a transient step, radiation on an element face (*RADIATE R3) and a surface
                 (*SRADIATE), an ambient under an amplitude, a flux and a film: for -snes_test_jacobian

usage: make_decks.py DIR
"""
import os
import sys

SIGMA = 5.670374419e-8


def grid3(nx, ny, lx, ly, lz):
    """Nodes of an nx x ny x 1 brick grid and its C3D8T elements (bottom z = 0, top z = lz)."""
    nodes, elems = [], []
    nid = lambda i, j, k: 1 + i + (nx + 1) * (j + (ny + 1) * k)
    for k in range(2):
        for j in range(ny + 1):
            for i in range(nx + 1):
                nodes.append((nid(i, j, k), i * lx / nx, j * ly / ny, k * lz))
    for j in range(ny):
        for i in range(nx):
            b = [nid(i, j, 0), nid(i + 1, j, 0), nid(i + 1, j + 1, 0), nid(i, j + 1, 0)]
            t = [nid(i, j, 1), nid(i + 1, j, 1), nid(i + 1, j + 1, 1), nid(i, j + 1, 1)]
            elems.append((len(elems) + 1, b + t))
    return nodes, elems


def node_lines(nodes):
    return ["%d, %.17g, %.17g, %.17g" % n for n in nodes]


def plate(explicit):
    if explicit:
        nodes, elems = grid3(2, 2, 1.0, 1.0, 0.001)
    else:
        nodes, elems = grid3(4, 4, 1.0, 1.0, 0.01)
    out = ["*HEADING",
           " A thin isothermal plate cooling by radiation from its top face (tests/radiate/make_decks.py)",
           "*NODE, NSET=NALL"] + node_lines(nodes)
    out += ["*ELEMENT, TYPE=C3D8T, ELSET=PLATE"] + ["%d, %s" % (e, ", ".join(map(str, c))) for e, c in elems]
    if explicit:
        # rho c = 2.43e3 per unit volume (V = 1e-3: rho c V = 2.43, the implicit plate's 24300 / 1e4): cooling from
        # 1000 K to about 620 K in 0.06 s; k = 50 keeps the Biot number h_r t / k = 4 sigma eps T^3 t / k at 3.6e-3
        # with a thermal stable increment of 2.2e-5 s (2700 increments), and E = 1e3 with rho = 2.7 keeps the
        # mechanical increment above it
        mat = ["*ELASTIC", "1000., 0.", "*CONDUCTIVITY", "50.", "*DENSITY", "2.7", "*SPECIFIC HEAT", "900."]
    else:
        mat = ["*ELASTIC", "7.0e10, 0.3", "*CONDUCTIVITY", "1.0e6", "*DENSITY", "2700.", "*SPECIFIC HEAT", "900."]
    out += ["*MATERIAL, NAME=ALU"] + mat
    out += ["*SOLID SECTION, ELSET=PLATE, MATERIAL=ALU",
            "*PHYSICAL CONSTANTS, ABSOLUTE ZERO=-273.15, STEFAN BOLTZMANN=%.10g" % SIGMA,
            "*INITIAL CONDITIONS, TYPE=TEMPERATURE", "NALL, 726.85",
            "*STEP, INC=1000"]
    if explicit:
        out += ["*DYNAMIC TEMPERATURE-DISPLACEMENT, EXPLICIT", ", 0.06"]
    else:
        out += ["*COUPLED TEMPERATURE-DISPLACEMENT, DELTMX=1e6", "20., 600., 20., 20."]
    out += ["*BOUNDARY", "NALL, 1, 3",
            "*RADIATE", "PLATE, R2, 26.85, 0.8",
            "*OUTPUT, FIELD, NUMBER INTERVAL=6" if explicit else "*OUTPUT, FIELD, FREQUENCY=10",
            "*NODE OUTPUT", "NT",
            "*END STEP"]
    return out


def steady():
    # 4 x 1 CPE8T on [0, 2] x [0, 0.5]: corner and midside nodes
    nx, lx, ly = 4, 2.0, 0.5
    nodes, ids = [], {}
    for j in range(3):
        for i in range(2 * nx + 1):
            if j == 1 and i % 2:
                continue
            ids[(i, j)] = len(nodes) + 1
            nodes.append((len(nodes) + 1, i * lx / (2 * nx), j * ly / 2, 0.0))
    elems = []
    for e in range(nx):
        i = 2 * e
        c = [ids[(i, 0)], ids[(i + 2, 0)], ids[(i + 2, 2)], ids[(i, 2)], ids[(i + 1, 0)], ids[(i + 2, 1)], ids[(i + 1, 2)], ids[(i, 1)]]
        elems.append((e + 1, c))
    out = ["*HEADING", " Steady conduction: a flux in on x = 0, radiation out on x = 2 (tests/radiate/make_decks.py)",
           "*NODE, NSET=NALL"] + ["%d, %.17g, %.17g" % n[:3] for n in nodes]
    out += ["*ELEMENT, TYPE=CPE8T, ELSET=BAR"] + ["%d, %s" % (e, ", ".join(map(str, c))) for e, c in elems]
    out += ["*SURFACE, NAME=HOT", "%d, S2" % nx,
            "*MATERIAL, NAME=M", "*ELASTIC", "2.0e5, 0.3", "*CONDUCTIVITY", "20.", "*DENSITY", "1.", "*SPECIFIC HEAT", "1.",
            "*SOLID SECTION, ELSET=BAR, MATERIAL=M", "1.",
            "*PHYSICAL CONSTANTS, ABSOLUTE ZERO=0, STEFAN BOLTZMANN=%.10g" % SIGMA,
            "*AMPLITUDE, NAME=AMB", "0., 1., 1., 1.5",
            "*AMPLITUDE, NAME=EMI", "0., 1., 1., 0.5",
            "*INITIAL CONDITIONS, TYPE=TEMPERATURE", "NALL, 600.",
            "*STEP", "*COUPLED TEMPERATURE-DISPLACEMENT, STEADY STATE", "1., 1.",
            "*BOUNDARY", "NALL, 1, 2",
            "*DFLUX", "1, S4, 5000.",
            "*SRADIATE", "HOT, R, 300., 0.6",
            "*END STEP",
            "*STEP", "*COUPLED TEMPERATURE-DISPLACEMENT, STEADY STATE", "1., 1.",
            "*SRADIATE, AMPLITUDE=AMB, RADIATION AMPLITUDE=EMI", "HOT, R, 300., 0.6",
            "*END STEP",
            "*STEP", "*COUPLED TEMPERATURE-DISPLACEMENT, STEADY STATE", "1., 1.",
            "*RADIATE, OP=NEW", "HOT, R0, 500., 1.",
            "*END STEP"]
    return out


def jacobian():
    out = ["*HEADING", " Radiation on distorted CPE4T elements for -snes_test_jacobian (tests/radiate/make_decks.py)",
           "*NODE, NSET=ALL",
           " 1, 0, 0", " 2, 0.5, 0.0125", " 3, 1, 0.05", " 4, 0, 0.5", " 5, 0.5175, 0.5125", " 6, 1.035, 0.55",
           " 7, 0, 1", " 8, 0.535, 1.0125", " 9, 1.07, 1.05",
           "*ELEMENT, TYPE=CPE4T, ELSET=BODY", " 1, 1, 2, 5, 4", " 2, 2, 3, 6, 5", " 3, 4, 5, 8, 7", " 4, 5, 6, 9, 8",
           "*NSET, NSET=BOTTOM", " 1, 2, 3",
           "*ELSET, ELSET=TOP", " 3, 4",
           "*SURFACE, NAME=RIGHT", " 2, S2", " 4, S2",
           "*MATERIAL, NAME=SOFT", "*ELASTIC", " 1000.0, 0.3", "*CONDUCTIVITY", " 10.0", "*DENSITY", " 1.0",
           "*SPECIFIC HEAT", " 1.0", "*EXPANSION", " 0.01",
           "*SOLID SECTION, ELSET=BODY, MATERIAL=SOFT", " 1.0",
           "*PHYSICAL CONSTANTS, ABSOLUTE ZERO=-273.15, STEFAN BOLTZMANN=5.670374419e-8",
           "*AMPLITUDE, NAME=WARM", " 0., 1., 0.1, 2.",
           "*INITIAL CONDITIONS, TYPE=TEMPERATURE", " ALL, 400.0",
           "*STEP", "*COUPLED TEMPERATURE-DISPLACEMENT", " 0.1, 0.1",
           "*BOUNDARY", " BOTTOM, 1, 2",
           "*DFLUX", " TOP, S3, 50.0",
           "*FILM", " 1, F4, 0.0, 10.0",
           "*RADIATE", " TOP, R3, 20.0, 0.9",
           "*SRADIATE, AMPLITUDE=WARM", " RIGHT, R, 50.0, 0.5",
           "*END STEP"]
    return out


if __name__ == "__main__":
    d = sys.argv[1]
    for name, lines in (("plate_c3d8t", plate(False)), ("plate_explicit_c3d8t", plate(True)), ("steady_cpe8t", steady()),
                        ("jacobian_cpe4t", jacobian())):
        with open(os.path.join(d, name + ".inp"), "w") as f:
            f.write("\n".join(lines) + "\n")
