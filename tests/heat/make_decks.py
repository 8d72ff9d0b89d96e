"""The heat-transfer decks of tests/heat/decks (issue 45): written here so that the meshes are reproducible.

bar_<type>: a bar 0 <= x <= L = 1 of n elements along x, one across, T = 0 at the start, T = 1 held at x = 0 from
t = 0, insulated elsewhere: the transient 1D conduction whose Fourier series check_heat.py sums. alpha = k/(rho c)
= 1 (k = 1, rho = 0.5, c = 2). The DC3D8 bar and the C3D8T bar in *HEAT TRANSFER (read as DC3D8) must give the
same temperatures; the C3D8T bar in *COUPLED TEMPERATURE-DISPLACEMENT with every displacement held too.
"""
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))


def bar(etype, procedure, name, n=20, tdep=False, film=False, heat_load=False, data="0.0025, 0.2, 1e-6, 0.0025", freq=20):
    L, w = 1.0, 0.1
    lines = ["*HEADING", f" 1D transient conduction along a bar of {n} {etype} (tests/heat/make_decks.py)", "*NODE, NSET=NALL"]
    nid = 0
    ids = {}
    for k in range(2):
        for j in range(2):
            for i in range(n + 1):
                nid += 1
                ids[(i, j, k)] = nid
                lines.append(f"{nid}, {L * i / n:.12g}, {w * j:.12g}, {w * k:.12g}")
    lines.append(f"*ELEMENT, TYPE={etype}, ELSET=BAR")
    for i in range(n):
        c = [ids[(i, 0, 0)], ids[(i + 1, 0, 0)], ids[(i + 1, 1, 0)], ids[(i, 1, 0)],
             ids[(i, 0, 1)], ids[(i + 1, 0, 1)], ids[(i + 1, 1, 1)], ids[(i, 1, 1)]]
        lines.append(f"{i + 1}, " + ", ".join(str(x) for x in c))
    lines.append("*NSET, NSET=HOT")
    lines.append(", ".join(str(ids[(0, j, k)]) for j in range(2) for k in range(2)))
    lines.append("*NSET, NSET=COLD")
    lines.append(", ".join(str(ids[(n, j, k)]) for j in range(2) for k in range(2)))
    lines += ["*MATERIAL, NAME=M"]
    if procedure.startswith("*COUPLED"):
        lines += ["*ELASTIC", "1000., 0.3"]
    if tdep:
        lines += ["*CONDUCTIVITY", "1.5, 0.", "2.5, 1."]
    else:
        lines += ["*CONDUCTIVITY", "1."]
    lines += ["*DENSITY", "0.5", "*SPECIFIC HEAT"]
    lines += (["1.5, 0.", "2.5, 1."] if tdep else ["2."])
    lines += ["*SOLID SECTION, ELSET=BAR, MATERIAL=M", "*INITIAL CONDITIONS, TYPE=TEMPERATURE", "NALL, 0.", "*STEP, INC=1000", procedure]
    lines += [data]
    lines += ["*BOUNDARY", "HOT, 11, 11, 1."]
    if procedure.startswith("*COUPLED"):
        lines += ["NALL, 1, 3"]
    if film:
        lines += ["*FILM", f"{n}, F4, 0., 0.5"]
    if heat_load:
        lines += ["*CFLUX", "COLD, 11, 0.01", "*DFLUX", "BAR, BF, 0.3"]
    lines += [f"*OUTPUT, FIELD, FREQUENCY={freq}", "*NODE OUTPUT", "NT", "*EL FILE", "HFL", "*END STEP"]
    with open(os.path.join(HERE, "decks", name + ".inp"), "w") as f:
        f.write("\n".join(lines) + "\n")


def sequential(name):
    """The DC3D8 bar's mesh as C3D8 in a *STATIC step whose temperatures are the heat-transfer job's (*TEMPERATURE,
    FILE=bar_dc3d8: Abaqus's sequentially coupled thermal-stress analysis), at the heat job's frame times (DIRECT
    increments of 0.05 over 0.2), clamped at x = 0 (check_heat.py same)."""
    with open(os.path.join(HERE, "decks", "bar_dc3d8.inp")) as f:
        text = f.read()
    model = text[: text.index("*STEP")].replace("TYPE=DC3D8", "TYPE=C3D8").replace("*CONDUCTIVITY", "*ELASTIC\n1000., 0.3\n*EXPANSION\n1e-3\n*CONDUCTIVITY")
    model = model.replace("1D transient conduction along a bar of 20 DC3D8", "the DC3D8 bar's temperatures in a static step of C3D8")
    steps = ["*STEP", "*STATIC, DIRECT", "0.05, 0.2", "*BOUNDARY", "HOT, 1, 3", "*TEMPERATURE, FILE=bar_dc3d8", "*NODE OUTPUT", "U, NT", "*END STEP"]
    with open(os.path.join(HERE, "decks", name + ".inp"), "w") as f:
        f.write(model + "\n".join(steps) + "\n")


def cylinder(name, n=8, r1=1.0, r2=2.0):
    """A thick cylinder r1 <= r <= r2 of n CAX8 (CalculiX's name, read as DCAX8) along r, one along z: T = 100 at r1, a
    film h = 5 to a sink 20 at r2, steady; the closed form is check_heat.py's (cylinder)."""
    lines = ["*HEADING", f" Steady radial conduction in a thick cylinder of {n} CAX8 read as DCAX8 (tests/heat/make_decks.py)", "*NODE, NSET=NALL"]
    ids, nid = {}, 0
    for j in range(3):
        for i in range(2 * n + 1):
            if j == 1 and i % 2:
                continue
            nid += 1
            ids[(i, j)] = nid
            lines.append(f"{nid}, {r1 + (r2 - r1) * i / (2 * n):.12g}, {0.05 * j:.12g}")
    lines.append("*ELEMENT, TYPE=CAX8, ELSET=CYL")
    for e in range(n):
        i = 2 * e
        c = [ids[(i, 0)], ids[(i + 2, 0)], ids[(i + 2, 2)], ids[(i, 2)], ids[(i + 1, 0)], ids[(i + 2, 1)], ids[(i + 1, 2)], ids[(i, 1)]]
        lines.append(f"{e + 1}, " + ", ".join(str(x) for x in c))
    lines.append("*NSET, NSET=INNER")
    lines.append(", ".join(str(ids[(0, j)]) for j in range(3)))
    lines += ["*MATERIAL, NAME=M", "*CONDUCTIVITY", "3.", "*SOLID SECTION, ELSET=CYL, MATERIAL=M", "*STEP", "*HEAT TRANSFER, STEADY STATE",
              "*BOUNDARY", "INNER, 11, 11, 100.", "*FILM", f"{n}, F2, 20., 5.", "*NODE PRINT, NSET=INNER", "RFL", "*END STEP"]
    with open(os.path.join(HERE, "decks", name + ".inp"), "w") as f:
        f.write("\n".join(lines) + "\n")


def blocks(name, dim=2, gap=0.01, tilt=0.0, shift=0.0, s2s=False, n=4, radiation=False):
    """Two blocks (unit squares, DC2D4, thickness 1; or unit cubes, DC3D8) one above the other across a clearance
    gap + tilt x (the upper block's bottom rises along x), the upper one moved along x by shift: T = 0 held at the
    lower block's bottom, T = 1 at the upper block's top, k = 50, a *GAP CONDUCTANCE k(d) = 1000 (1 - d / 0.02)
    (Abaqus's clearance table), no displacement: a heat-transfer model (check_heat.py gap, gap_nodes, gap_off). With
    radiation: no conductance but *GAP RADIATION (eps 0.8 and 0.8, view factor 1), T = 300 K and 600 K held
    (check_heat.py gap_radiation)."""
    etype = "DC2D4" if dim == 2 else "DC3D8"
    nz = 1 if dim == 3 else 0
    L = ["*HEADING", f" two {etype} blocks across a clearance (tests/heat/make_decks.py)", "*NODE, NSET=NALL"]
    ids, nid = {}, 0
    for b in range(2):
        for k in range(nz + 1):
            for j in range(3):
                for i in range(n + 1):
                    nid += 1
                    ids[(b, i, j, k)] = nid
                    x = i / n + (shift if b else 0)
                    y = (1 + gap + tilt * i / n + j / 2) if b else j / 2
                    L.append(f"{nid}, {x:.12g}, {y:.12g}" + (f", {k:.12g}" if dim == 3 else ""))
    eid = 0
    for b in range(2):
        L.append(f"*ELEMENT, TYPE={etype}, ELSET={'UPPER' if b else 'LOWER'}")
        for j in range(2):
            for i in range(n):
                eid += 1
                q = [ids[(b, i, j, 0)], ids[(b, i + 1, j, 0)], ids[(b, i + 1, j + 1, 0)], ids[(b, i, j + 1, 0)]]
                if dim == 3:
                    q = [ids[(b, i, j, 0)], ids[(b, i, j, 1)], ids[(b, i + 1, j, 1)], ids[(b, i + 1, j, 0)],
                         ids[(b, i, j + 1, 0)], ids[(b, i, j + 1, 1)], ids[(b, i + 1, j + 1, 1)], ids[(b, i + 1, j + 1, 0)]]
                L.append(f"{eid}, " + ", ".join(str(x) for x in q))
    # 2D: S3 is the quad's top (nodes 3-4), S1 its bottom; 3D (nodes ordered y-up): S2 the top (5-8), S1 the bottom
    top, bottom = ("S3", "S1") if dim == 2 else ("S2", "S1")
    L += ["*ELSET, ELSET=ALL", "LOWER, UPPER", "*SURFACE, NAME=TOP"] + [f"{n + i + 1}, {top}" for i in range(n)]
    L += ["*SURFACE, NAME=BOTTOM"] + [f"{2 * n + i + 1}, {bottom}" for i in range(n)]
    L += ["*NSET, NSET=COLD", ", ".join(str(ids[(0, i, 0, k)]) for i in range(n + 1) for k in range(nz + 1))]
    L += ["*NSET, NSET=HOT", ", ".join(str(ids[(1, i, 2, k)]) for i in range(n + 1) for k in range(nz + 1))]
    L += ["*MATERIAL, NAME=M", "*CONDUCTIVITY", "50.", "*SOLID SECTION, ELSET=ALL, MATERIAL=M"] + (["1."] if dim == 2 else [])
    L += ["*SURFACE INTERACTION, NAME=INT", "*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=HARD"]
    if radiation:
        L += ["*GAP RADIATION", "0.8, 0.8", "1., 0.", "1., 0.1", "*PHYSICAL CONSTANTS, ABSOLUTE ZERO=0., STEFAN BOLTZMANN=5.67e-8"]
    else:
        L += ["*GAP CONDUCTANCE", "1000., 0.", "0., 0.02"]
    L += ["*CONTACT PAIR, INTERACTION=INT" + (", TYPE=SURFACE TO SURFACE" if s2s else ""), "BOTTOM, TOP"]
    cold, hot = (300, 600) if radiation else (0, 1)
    L += ["*STEP", "*HEAT TRANSFER, STEADY STATE", "*BOUNDARY", f"COLD, 11, 11, {cold}.", f"HOT, 11, 11, {hot}.",
          "*OUTPUT, FIELD", "*NODE OUTPUT", "NT, RFL, HFLA", "*END STEP"]
    with open(os.path.join(HERE, "decks", name + ".inp"), "w") as f:
        f.write("\n".join(L) + "\n")


JACOBIAN = """*HEADING
 Heat transfer on distorted DC2D4 elements for -snes_test_jacobian (tests/heat/make_decks.py): k(theta), c(theta), a film,
 radiation, a surface flux, a body flux and a concentrated flux
*NODE, NSET=ALL
 1, 0, 0
 2, 0.5, 0.0125
 3, 1, 0.05
 4, 0, 0.5
 5, 0.5175, 0.5125
 6, 1.035, 0.55
 7, 0, 1
 8, 0.535, 1.0125
 9, 1.07, 1.05
*ELEMENT, TYPE=DC2D4, ELSET=BODY
 1, 1, 2, 5, 4
 2, 2, 3, 6, 5
 3, 4, 5, 8, 7
 4, 5, 6, 9, 8
*NSET, NSET=BOTTOM
 1, 2, 3
*ELSET, ELSET=TOP
 3, 4
*SURFACE, NAME=RIGHT
 2, S2
 4, S2
*MATERIAL, NAME=M
*CONDUCTIVITY
 5.0, 300.
 15.0, 500.
*DENSITY
 1.0
*SPECIFIC HEAT
 1.0, 300.
 3.0, 500.
*SOLID SECTION, ELSET=BODY, MATERIAL=M
 1.0
*PHYSICAL CONSTANTS, ABSOLUTE ZERO=-273.15, STEFAN BOLTZMANN=5.670374419e-8
*INITIAL CONDITIONS, TYPE=TEMPERATURE
 ALL, 380.0
 9, 450.0
*STEP
*HEAT TRANSFER
 0.1, 0.1
*BOUNDARY
 1, 11, 11, 400.
*DFLUX
 TOP, S3, 50.0
 BODY, BF, 20.0
*CFLUX
 6, 11, 3.0
*FILM
 1, F4, 0.0, 10.0
 2, F1, 100.0, 4.0
*RADIATE
 TOP, R3, 20.0, 0.9
*SFILM
 RIGHT, F, 300.0, 2.0
*END STEP
"""


def main():
    bar("DC3D8", "*HEAT TRANSFER", "bar_dc3d8")
    bar("C3D8T", "*HEAT TRANSFER", "bar_c3d8t_heat")
    bar("C3D8T", "*COUPLED TEMPERATURE-DISPLACEMENT", "bar_c3d8t_coupled")
    bar("DC3D8", "*HEAT TRANSFER, END=SS", "endss_dc3d8", n=10, film=True, tdep=True, data="0.01, 50., 1e-6, 1., 1e-4", freq=1000)
    sequential("static_from_heat_c3d8")
    bar("DC3D8", "*HEAT TRANSFER, DELTMX=0.1", "deltmx_dc3d8", n=10, data="0.05, 0.2, 1e-6, 0.05", freq=1)
    cylinder("cylinder_cax8")
    blocks("gap_dc2d4")
    blocks("gap_s2s_dc3d8", dim=3, s2s=True)
    blocks("gap_nodes_dc2d4", tilt=0.01)
    blocks("gap_off_dc2d4", shift=1.5)
    blocks("gap_radiation_dc3d8", dim=3, radiation=True)
    with open(os.path.join(HERE, "decks", "jacobian_dc2d4.inp"), "w") as f:
        f.write(JACOBIAN)


if __name__ == "__main__":
    sys.exit(main())
