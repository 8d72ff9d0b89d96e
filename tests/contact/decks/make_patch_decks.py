#!/usr/bin/python3
"""Writes the contact patch test decks (tests/contact/decks/contact_patch_*_cpe4t.inp): two CPE4T blocks of
one material with non-matching meshes across a flat interface at y = 0.5: the lower (main) block 1 x 0.5
with NL elements across and 2 high, the upper (secondary) 1 x 0.5 with NU across and 2 high. Pressure 100 on
top, bottom held in y, the symmetry edge x = 0 held in x (both blocks expand freely sideways alike, so the
interface does not slide), temperature 100 on top and 0 at the bottom, gap conductance k(100) = 20: the
exact state is uniform (S22 = -100, CPRESS = 100, heat flux q = 100 / (0.5/50 + 1/20 + 0.5/50) = 1428.57).
usage: make_patch_decks.py OUTDIR [NL NU]   (defaults 5 3; writes contact_patch_s2s_cpe4t.inp and _n2s_)
"""
import sys

out = sys.argv[1]
NL, NU = (int(sys.argv[2]), int(sys.argv[3])) if len(sys.argv) > 3 else (5, 3)


def block(first_node, first_elem, nx, y0):
    nodes, elems = [], []
    for j in range(3):
        for i in range(nx + 1):
            nodes.append((first_node + j * (nx + 1) + i, i / nx, y0 + 0.25 * j))
    for j in range(2):
        for i in range(nx):
            a = first_node + j * (nx + 1) + i
            elems.append((first_elem + j * nx + i, a, a + 1, a + nx + 2, a + nx + 1))
    return nodes, elems


def lines(ids, per=8):
    return "\n".join(" " + ", ".join(str(v) for v in ids[k:k + per]) for k in range(0, len(ids), per))


ln, le = block(1, 1, NL, 0.0)
un, ue = block(1001, 101, NU, 0.5)
for kind, param in (("s2s", ", TYPE=SURFACE TO SURFACE"), ("n2s", "")):
    d = ["*HEADING", " Contact patch test (%s): uniform pressure and heat flux through a non-matching interface, %d vs %d CPE4T"
         % (kind, NL, NU), "*NODE, NSET=ALL"]
    d += [" %d, %.17g, %.17g" % n for n in ln + un]
    d += ["*ELEMENT, TYPE=CPE4T, ELSET=LOWER"] + [" %d, %d, %d, %d, %d" % e for e in le]
    d += ["*ELEMENT, TYPE=CPE4T, ELSET=UPPER"] + [" %d, %d, %d, %d, %d" % e for e in ue]
    d += ["*NSET, NSET=BASE", lines([n[0] for n in ln if n[2] == 0.0])]
    d += ["*NSET, NSET=TOP", lines([n[0] for n in un if n[2] == 1.0])]
    d += ["*NSET, NSET=LEFT", lines([n[0] for n in ln + un if n[1] == 0.0])]
    d += ["*ELSET, ELSET=LOWTOP", lines([e[0] for e in le[NL:]])]
    d += ["*ELSET, ELSET=UPBOT", lines([e[0] for e in ue[:NU]])]
    d += ["*ELSET, ELSET=UPTOP", lines([e[0] for e in ue[NU:]])]
    d += ["*ELSET, ELSET=BODY", lines([e[0] for e in le + ue])]
    d += ["*SURFACE, NAME=MAIN, TYPE=ELEMENT", " LOWTOP, S3", "*SURFACE, NAME=SECONDARY, TYPE=ELEMENT", " UPBOT, S1"]
    d += ["*MATERIAL, NAME=STEEL", "*ELASTIC", " 200000.0, 0.3", "*CONDUCTIVITY", " 50.0", "*DENSITY", " 1.0", "*SPECIFIC HEAT", " 1.0"]
    d += ["*SOLID SECTION, ELSET=BODY, MATERIAL=STEEL", " 1.0"]
    d += ["*SURFACE INTERACTION, NAME=IFACE", "*GAP CONDUCTANCE, PRESSURE", " 20.0, 100.0", " 5.0, 200.0"]
    d += ["*CONTACT PAIR, INTERACTION=IFACE, SMOOTH=0.2" + param, " SECONDARY, MAIN"]
    d += ["*INITIAL CONDITIONS, TYPE=TEMPERATURE", " ALL, 0.0"]
    d += ["*STEP, NAME=PRESS AND HEAT", "*COUPLED TEMPERATURE-DISPLACEMENT, STEADY STATE", "*BOUNDARY", " BASE, 2, 2", " BASE, 11, 11, 0.0",
          " TOP, 11, 11, 100.0", " LEFT, 1, 1", "*DLOAD", " UPTOP, P3, 100.0", "*END STEP"]
    open("%s/contact_patch_%s_cpe4t.inp" % (out, kind), "w").write("\n".join(d) + "\n")
