#!/usr/bin/python3
"""Writes the contact patch test decks (tests/contact/decks/contact_patch_*_cpe4t.inp): two CPE4T blocks of
one material with non-matching meshes across a flat interface at y = 0.5: the lower (main) block 1 x 0.5
with NL elements across and 2 high, the upper (secondary) 1 x 0.5 with NU across and 2 high. Pressure 100 on
top, bottom held in y, the symmetry edge x = 0 held in x (both blocks expand freely sideways alike, so the
interface does not slide), temperature 100 on top and 0 at the bottom, gap conductance k(100) = 20: the
exact state is uniform (S22 = -100, CPRESS = 100, heat flux q = 100 / (0.5/50 + 1/20 + 0.5/50) = 1428.57).
usage: make_patch_decks.py OUTDIR [NL NU]   (defaults 5 3; writes contact_patch_s2s_cpe4t.inp and _n2s_)

With --3d: the same test with two C3D8T blocks 1 x 0.5 x 1 (y up), the lower (main) 3 x 3 elements across
the interface, the upper (secondary) 4 x 5, both 2 high; x = 0 held in x and z = 0 in z (symmetry planes),
writes contact_patch_s2s_c3d8t.inp and _n2s_. Same exact state (the heat flux over an interface of area 1).
usage: make_patch_decks.py OUTDIR --3d

With --axi: the 2D decks as CAX4T rings, the radius r = x + 1 (1 to 2), no edge held in r (the uniform state has
u_r = -nu S22 r / E, which CAX4T represents exactly); the heat across the interface is q x pi (2^2 - 1^2).
Writes contact_patch_s2s_cax4t.inp and _n2s_.
usage: make_patch_decks.py OUTDIR --axi
"""
import os
import sys

out = sys.argv[1]
if "--3d" in sys.argv:
    sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "../../../jobs/verification"))
    from make_decks import faces_on, mesh3d

    ln, le, shape = mesh3d(3, 2, 3, 0.0, 1.0, 0.0, 0.5, 0.0, 1.0, "C3D8T")
    un, ue, _ = mesh3d(4, 2, 5, 0.0, 1.0, 0.5, 1.0, 0.0, 1.0, "C3D8T", 1000, 100)
    nodes = dict(ln)
    nodes.update(un)
    surf = lambda name, faces: ["*SURFACE, NAME=%s, TYPE=ELEMENT" % name] + [" %d, S%d" % f for f in faces]
    sel = lambda pred: sorted(n for n, c in nodes.items() if pred(c))
    nl = lambda ids: "\n".join(" " + ", ".join(str(v) for v in ids[k:k + 8]) for k in range(0, len(ids), 8))
    for kind, param in (("s2s", ", TYPE=SURFACE TO SURFACE"), ("n2s", "")):
        d = ["*HEADING", " Contact patch test (%s, 3D): uniform pressure and heat flux through a non-matching interface, 3 x 3 vs 4 x 5 C3D8T"
             % kind, "*NODE, NSET=ALL"]
        d += [" %d, %.17g, %.17g, %.17g" % ((n,) + nodes[n]) for n in sorted(nodes)]
        d += ["*ELEMENT, TYPE=C3D8T, ELSET=LOWER"] + [" " + ", ".join(str(v) for v in e) for e in le]
        d += ["*ELEMENT, TYPE=C3D8T, ELSET=UPPER"] + [" " + ", ".join(str(v) for v in e) for e in ue]
        d += ["*NSET, NSET=BASE", nl(sel(lambda c: c[1] == 0.0))]
        d += ["*NSET, NSET=TOP", nl(sel(lambda c: c[1] == 1.0))]
        d += ["*NSET, NSET=XSYM", nl(sel(lambda c: c[0] == 0.0))]
        d += ["*NSET, NSET=ZSYM", nl(sel(lambda c: c[2] == 0.0))]
        d += ["*ELSET, ELSET=BODY", nl([e[0] for e in le + ue])]
        d += surf("MAIN", faces_on(ln, le, shape, 0.5)) + surf("SECONDARY", faces_on(un, ue, shape, 0.5))
        d += ["*MATERIAL, NAME=STEEL", "*ELASTIC", " 200000.0, 0.3", "*CONDUCTIVITY", " 50.0", "*DENSITY", " 1.0", "*SPECIFIC HEAT", " 1.0"]
        d += ["*SOLID SECTION, ELSET=BODY, MATERIAL=STEEL"]
        d += ["*SURFACE INTERACTION, NAME=IFACE", "*GAP CONDUCTANCE, PRESSURE", " 20.0, 100.0", " 5.0, 200.0"]
        d += ["*CONTACT PAIR, INTERACTION=IFACE, SMOOTH=0.2" + param, " SECONDARY, MAIN"]
        d += ["*INITIAL CONDITIONS, TYPE=TEMPERATURE", " ALL, 0.0"]
        d += ["*STEP, NAME=PRESS AND HEAT", "*COUPLED TEMPERATURE-DISPLACEMENT, STEADY STATE", "*BOUNDARY", " BASE, 2, 2", " BASE, 11, 11, 0.0",
              " TOP, 11, 11, 100.0", " XSYM, 1, 1", " ZSYM, 3, 3", "*DLOAD"]
        d += [" %d, P%d, 100.0" % f for f in faces_on(un, ue, shape, 1.0)] + ["*END STEP"]
        open("%s/contact_patch_%s_c3d8t.inp" % (out, kind), "w").write("\n".join(d) + "\n")
    sys.exit(0)
axi = "--axi" in sys.argv
args = [a for a in sys.argv[2:] if not a.startswith("--")]
NL, NU = (int(args[0]), int(args[1])) if len(args) > 1 else (5, 3)
etype, r0 = ("CAX4T", 1.0) if axi else ("CPE4T", 0.0)


def block(first_node, first_elem, nx, y0):
    nodes, elems = [], []
    for j in range(3):
        for i in range(nx + 1):
            nodes.append((first_node + j * (nx + 1) + i, r0 + i / nx, y0 + 0.25 * j))
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
    d = ["*HEADING", " Contact patch test (%s): uniform pressure and heat flux through a non-matching interface, %d vs %d %s"
         % (kind, NL, NU, etype), "*NODE, NSET=ALL"]
    d += [" %d, %.17g, %.17g" % n for n in ln + un]
    d += ["*ELEMENT, TYPE=%s, ELSET=LOWER" % etype] + [" %d, %d, %d, %d, %d" % e for e in le]
    d += ["*ELEMENT, TYPE=%s, ELSET=UPPER" % etype] + [" %d, %d, %d, %d, %d" % e for e in ue]
    d += ["*NSET, NSET=BASE", lines([n[0] for n in ln if n[2] == 0.0])]
    d += ["*NSET, NSET=TOP", lines([n[0] for n in un if n[2] == 1.0])]
    if not axi:
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
          " TOP, 11, 11, 100.0"] + ([] if axi else [" LEFT, 1, 1"]) + ["*DLOAD", " UPTOP, P3, 100.0", "*END STEP"]
    open("%s/contact_patch_%s_%s.inp" % (out, kind, etype.lower()), "w").write("\n".join(d) + "\n")
