#!/usr/bin/python3
"""Writes the large-radius ring decks of this folder (issue 44, item 7; run once, the decks are committed).

  contact_ring_r1000_{type}[_rN]_t{rows}.inp
      The spec's friction section (jobs/verification/make_decks.py, sliding_blocks: a small block 2 x 0.25 on a
      large block 6 x 1.25, the spec's material, rho c = 1) as two rings of an axisymmetric model at r = 1000 + x,
      z = y: the large ring held at its base z = 0, the small ring above it, its top face tied by *EQUATION to a
      reference node (its first top node) that is pressed axially by F and driven radially (dof 1) through the
      friction series' slide 0 -> +1.5 -> -1.5 -> 0 (slip path 6) over 3 s, then left 20 s to equilibrate.
      F = 100 x 2 pi (1003) x 2, the planar series' interface pressure of 100; LAGRANGE friction mu = 0.2,
      conductance 20, heat generation eta = 0.5. The twist types hold the twist (dof 5) at the base and tie it
      on the top face to the held reference node.
      Expected (the load is axial, so the interface carries all of F whatever the rings' hoop stresses do):
        dissipation mu F 6 = 1 512 488.4, absorbed eta x that, and at the end a uniform temperature
        absorbed / (rho c V), V = 2 pi (1003) 8 (each ring's volume is 2 pi x its centroid radius 1003 x its
        section).
      At r = 1000 the radial slide is a hoop strain of 1.5e-3, a hoop stress of 45 000 against the contact
      pressure of 100: the small ring's section bends, and its contact pressure moves between its edges and
      its middle at every reversal (zero at the nodes in between). rows: cells through the small ring's
      thickness (the spec's 6; 1 is where the reduced types stopped or "completed" with the ring thrown away,
      docs/verification.md); _rN: every cell of both rings cut N x N (r2: where CAX4T "completed" with 31 % of
      the heat).
"""
import math
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "..", "jobs", "verification"))
from make_decks import MAT, deck_type, faces, family_of, mesh2d  # noqa: E402

R0 = 1000.0
MU = 0.2
PRESSURE = 100.0


def ring_deck(typ, rows, refine=1):
    typ = typ.upper()
    shape, order, kin = family_of(typ)
    c = 2 if order == 2 else 1
    bnodes, belems, brows = mesh2d(12 * refine // c, 2 * refine // c, 0.0, 6.0, 0.0, 1.25, shape, order, mirror=3.0)
    tnodes, telems, trows = mesh2d(4 * refine // c, rows * refine // c, 2.0, 4.0, 1.25, 1.5, shape, order, 1000, 1000, mirror=3.0)
    fb, ft = faces(shape)
    top = [n[0] for n in tnodes if abs(n[2] - 1.5) < 1e-12]
    base = [n[0] for n in bnodes if abs(n[2]) < 1e-12]
    ids = lambda v: "".join(" " + ", ".join(str(i) for i in v[k:k + 8]) + "\n" for k in range(0, len(v), 8))
    nodes = lambda v: "".join(" %d, %.12g, %.12g\n" % (n[0], R0 + n[1], n[2]) for n in v)
    elems = lambda v: "".join(" " + ", ".join(str(i) for i in e) + "\n" for e in v)
    force = PRESSURE * 2 * math.pi * (R0 + 3.0) * 2.0
    twist = kin == "GAX"
    dofs = (1, 2, 5) if twist else (1, 2)
    ref = top[0]
    text = ("*HEADING\n Rings at r = 1000 (the friction series' section), %s, %d cells through the small ring%s: pressed axially, slid radially\n"
            % (typ, rows, ", cells cut %d x %d" % (refine, refine) if refine > 1 else "") +
            "*NODE, NSET=ALL\n" + nodes(bnodes) + "*NODE, NSET=ALL\n" + nodes(tnodes) +
            "*ELEMENT, TYPE=%s, ELSET=LARGE\n" % deck_type(typ) + elems(belems) +
            "*ELEMENT, TYPE=%s, ELSET=SMALL\n" % deck_type(typ) + elems(telems) +
            "*NSET, NSET=BASE\n" + ids(base) + "*NSET, NSET=TOPFACE\n" + ids(top) +
            "*ELSET, ELSET=MAINE\n" + ids(brows[-1][1]) + "*ELSET, ELSET=SECE\n" + ids(trows[0][0]) +
            "*SURFACE, NAME=MAIN, TYPE=ELEMENT\n MAINE, S%s\n*SURFACE, NAME=SECONDARY, TYPE=ELEMENT\n SECE, S%s\n" % (ft, fb) + MAT +
            "*SOLID SECTION, ELSET=LARGE, MATERIAL=STEEL\n 1.0\n*SOLID SECTION, ELSET=SMALL, MATERIAL=STEEL\n 1.0\n"
            "*SURFACE INTERACTION, NAME=IFACE\n*FRICTION, LAGRANGE\n %g\n*GAP CONDUCTANCE, PRESSURE\n 20.0, 0.0\n"
            "*GAP HEAT GENERATION\n 0.5, 0.5\n*CONTACT PAIR, INTERACTION=IFACE, SMOOTH=0.05\n SECONDARY, MAIN\n" % MU +
            "*AMPLITUDE, NAME=SLIDE\n 0.0, 0.0, 1.0, 1.0, 2.0, -1.0, 3.0, 0.0\n*INITIAL CONDITIONS, TYPE=TEMPERATURE\n ALL, 0.0\n" +
            "".join("*EQUATION\n 2\n %d, %d, 1.0, %d, %d, -1.0\n" % (n, d, ref, d) for n in top[1:] for d in dofs) +
            "*STEP, NAME=PRESS, INC=100\n*COUPLED TEMPERATURE-DISPLACEMENT\n 0.5, 1.0\n*BOUNDARY\n BASE, 1, 2\n %d, 1, 1\n" % ref +
            (" BASE, 5, 5\n %d, 5, 5\n" % ref if twist else "") + "*CLOAD\n %d, 2, %.10g\n*END STEP\n" % (ref, -force) +
            "*STEP, NAME=SLIDE, INC=1000\n*COUPLED TEMPERATURE-DISPLACEMENT\n 0.025, 3.0, 1e-5, 0.025\n"
            "*BOUNDARY, AMPLITUDE=SLIDE\n %d, 1, 1, 1.5\n*END STEP\n" % ref +
            "*STEP, NAME=EQUILIBRATE, INC=1000\n*COUPLED TEMPERATURE-DISPLACEMENT\n 0.1, 20.0, 1e-5, 2.0\n*END STEP\n")
    name = "contact_ring_r1000_%s%s_t%d.inp" % (typ.lower(), "_r%d" % refine if refine > 1 else "", rows)
    with open(os.path.join(HERE, name), "w") as f:
        f.write(text)


if __name__ == "__main__":
    for t in ("CAX4T", "CAX4RT", "CAX4RHT", "CGAX4RT", "CGAX4RHT"):
        ring_deck(t, 1)
    ring_deck("CAX4T", 6, refine=2)
