#!/usr/bin/python3
"""Decks of the conventional shells (S8RT, SAX2T) with analytic answers (check_shell.py checks them).

usage: make_shell_decks.py OUTDIR

  plate_s8rt.inp        a 2 x 1 plate (thickness 0.5, normal +y): flux 100 in through SPOS, film h = 10 (sink 0) on
                        SNEG: the temperature through the thickness 10 (SNEG) .. 15 (SPOS), 12.5 on the deck's nodes
  plate_spos_s8rt.inp   the same with OFFSET=SPOS: the deck's nodes on the top face (15), the plate below them
  plate_labels_s8rt.inp the same loads by element labels (*DFLUX SPOS, *FILM FNEG), and a pressure of 1000 by *DLOAD P
                        on the shells (pushing against the normal): the reaction force 2000 along +y, no temperature change
  plate_nodal_s8rt.inp  plate_s8rt with the thickness 0.5 from *NODAL THICKNESS (the section's NODAL THICKNESS; its
                        data line's 9.0 not read): the same answer
  taper_s8rt.inp        the same plate with the nodal thickness 0.4 + 0.1 x (0.4 to 0.6): SPOS and SNEG are planes at
                        y = +-t / 2, so the heat in is 100 x their area 2.0025 (= the film's heat out)
  taper_parts_s8rt.inp  taper_s8rt the way Abaqus/CAE writes it: a *PART holding the plate, its section and its
                        *NODAL THICKNESS (a set's 9.0, then each node's own, which wins), placed twice (the second
                        instance moved by 3 along z): each plate the taper's answer, the heat in twice its
  plate_moved_s8rt.inp  the plate turned about (1, 2, 3) by 0.7 rad and moved by (1e5, -2e5, 3e5): the same temperatures
  cantilever_s8rt.inp   a 10 x 1 strip (thickness 0.5) clamped at x = 0 (free to bend and stretch across its width there,
                        so that it bends as a beam): step LOAD, a tip force of 100 (-y): tip
                        deflection P L^3 / (3 E I) + P L / (k G A); step HEAT, the force off, flux 100 in through the
                        top, film on the bottom: the through-thickness difference 5 bends it to a tip deflection
                        alpha dT L^2 / (2 t), downward
  cylinder_sax2t.inp    an open cylinder r = 1 (thickness 0.02, length 1) of SAX2T: step PRESSURE, 100 inside: Lame's
                        radial displacement; step HEAT, flux 100 in through the inside, film h = 10 outside: the
                        radial conduction's temperatures
"""
import math
import os
import sys

MAT = ("*MATERIAL, NAME=STEEL\n*ELASTIC\n 30.0E6, 0.3\n*CONDUCTIVITY\n 10.0\n*DENSITY\n 1000.0\n*SPECIFIC HEAT\n 0.001\n"
       "*EXPANSION\n 1.0E-5\n")


def quad8_strip(nx, nz, L, W, y=0.0):
    """S8RT elements of an nx x nz strip in the x-z plane (x in [0, L], z in [0, W]), right-hand normal +y.
    Returns nodes {id: (x, y, z)} and elements [(id, n1..n8)]."""
    NX, NZ = 2 * nx, 2 * nz
    nid = lambda i, k: 1 + i + k * (NX + 1)
    nodes, elems = {}, []
    for e_k in range(nz):
        for e_i in range(nx):
            I, K = 2 * e_i, 2 * e_k
            # corners (x, z): (I, K), (I, K+2), (I+2, K+2), (I+2, K): (z) x (x) = +y
            c = [nid(I, K), nid(I, K + 2), nid(I + 2, K + 2), nid(I + 2, K)]
            m = [nid(I, K + 1), nid(I + 1, K + 2), nid(I + 2, K + 1), nid(I + 1, K)]
            elems.append((len(elems) + 1,) + tuple(c + m))
    used = {n for e in elems for n in e[1:]}
    for k in range(NZ + 1):
        for i in range(NX + 1):
            if nid(i, k) in used:
                nodes[nid(i, k)] = (L * i / NX, y, W * k / NZ)
    return nodes, elems


def fmt_nodes(nodes, move=lambda p: p):
    return "*NODE, NSET=ALL\n" + "".join(" %d, %.15g, %.15g, %.15g\n" % ((n,) + tuple(move(nodes[n]))) for n in sorted(nodes))


def fmt_elems(elems, typ, elset):
    return "*ELEMENT, TYPE=%s, ELSET=%s\n" % (typ, elset) + "".join(" " + ", ".join(str(v) for v in e) + "\n" for e in elems)


def nset(name, ids):
    ids = sorted(ids)
    return "*NSET, NSET=%s\n" % name + "".join(" " + ", ".join(str(i) for i in ids[k:k + 8]) + "\n" for k in range(0, len(ids), 8))


def rotation(axis, angle):
    a = [v / math.sqrt(sum(w * w for w in axis)) for v in axis]
    c, s = math.cos(angle), math.sin(angle)
    x, y, z = a
    return [[c + x * x * (1 - c), x * y * (1 - c) - z * s, x * z * (1 - c) + y * s],
            [y * x * (1 - c) + z * s, c + y * y * (1 - c), y * z * (1 - c) - x * s],
            [z * x * (1 - c) - y * s, z * y * (1 - c) + x * s, c + z * z * (1 - c)]]


def plate(out, offset=None, move=None, labels=False, nodal=None):
    nodes, elems = quad8_strip(2, 1, 2.0, 1.0)
    corner = [n for n, p in nodes.items() if p[0] == 0 and p[2] == 0][0]
    other = [n for n, p in nodes.items() if p[0] == 2.0 and p[2] == 0][0]
    if move:
        R, d = move
        mv = lambda p: [sum(R[i][j] * p[j] for j in range(3)) + d[i] for i in range(3)]
        # held along the plate's own normal and in-plane directions: the turned supports as *EQUATIONs would
        # need, so hold every direction at the plate's nodes instead (the temperatures are what is checked)
        supports = " ALL, 1, 3\n"
    else:
        mv = lambda p: p
        supports = " %d, 1, 3\n ALL, 2, 2\n %d, 3, 3\n" % (corner, other)
    return (("*HEADING\n S8RT plate: flux in through SPOS, film on SNEG%s\n" % (", OFFSET=SPOS" if offset else "")) +
            fmt_nodes(nodes, mv) + fmt_elems(elems, "S8RT", "PLATE") + MAT +
            ("*SHELL SECTION, ELSET=PLATE, MATERIAL=STEEL%s\n 0.5, 5\n" % (", OFFSET=SPOS" if offset else "") if not nodal else
             # the data line's thickness is not read with NODAL THICKNESS
             "*SHELL SECTION, ELSET=PLATE, MATERIAL=STEEL, NODAL THICKNESS\n 9.0, 5\n*NODAL THICKNESS\n" +
             ("".join(" %d, %.15g\n" % (n, nodal(nodes[n])) for n in sorted(nodes)) if callable(nodal) else " ALL, %g\n" % nodal)) +
            "*SURFACE, NAME=UP, TYPE=ELEMENT\n PLATE, SPOS\n*SURFACE, NAME=DOWN, TYPE=ELEMENT\n PLATE, SNEG\n"
            "*STEP, NAME=HEAT\n*COUPLED TEMPERATURE-DISPLACEMENT, STEADY STATE\n 1.0, 1.0\n*BOUNDARY\n" + supports +
            ("*DFLUX\n PLATE, SPOS, 100.0\n*FILM\n PLATE, FNEG, 0.0, 10.0\n*DLOAD\n PLATE, P, 1000.0\n" if labels else
             "*DSFLUX\n UP, S, 100.0\n*SFILM\n DOWN, F, 0.0, 10.0\n") + "*NODE PRINT, NSET=ALL\n NT\n*END STEP\n")


def taper_parts():
    nodes, elems = quad8_strip(2, 1, 2.0, 1.0)
    nt = "".join(" %d, %.15g\n" % (n, 0.4 + 0.1 * nodes[n][0]) for n in sorted(nodes))
    return ("*Heading\n S8RT tapered plate as a part placed twice\n*Part, name=Plate\n" + fmt_nodes(nodes) +
            fmt_elems(elems, "S8RT", "PLATE") +
            "*Shell Section, elset=PLATE, material=STEEL, nodal thickness\n 1.0, 5\n*Nodal Thickness\n ALL, 9.0\n" + nt +
            "*Surface, name=UP, type=ELEMENT\n PLATE, SPOS\n*Surface, name=DOWN, type=ELEMENT\n PLATE, SNEG\n*End Part\n"
            "*Assembly, name=Assembly\n*Instance, name=P-1, part=Plate\n*End Instance\n"
            "*Instance, name=P-2, part=Plate\n 0., 0., 3.\n*End Instance\n*Nset, nset=ALL\n P-1.ALL, P-2.ALL\n"
            "*End Assembly\n" + MAT +
            "*Step, name=HEAT\n*Coupled Temperature-Displacement, steady state\n 1.0, 1.0\n*Boundary\n ALL, 1, 3\n"
            "*Dsflux\n P-1.UP, S, 100.0\n P-2.UP, S, 100.0\n*Sfilm\n P-1.DOWN, F, 0.0, 10.0\n P-2.DOWN, F, 0.0, 10.0\n"
            "*Node Print, nset=ALL\n NT\n*End Step\n")


def cantilever():
    L, W, t = 10.0, 1.0, 0.5
    nodes, elems = quad8_strip(10, 1, L, W)
    root = sorted((n for n, p in nodes.items() if p[0] == 0.0), key=lambda n: nodes[n][2])
    tip = sorted((n for n, p in nodes.items() if p[0] == L), key=lambda n: nodes[n][2])
    assert len(tip) == 3
    P = 100.0
    return ("*HEADING\n S8RT cantilever: tip force, then a through-thickness temperature difference\n" +
            fmt_nodes(nodes) + fmt_elems(elems, "S8RT", "STRIP") + nset("ROOT", root) + nset("TIP", tip) + MAT +
            "*SHELL SECTION, ELSET=STRIP, MATERIAL=STEEL\n %g\n" % t +
            "*SURFACE, NAME=TOP, TYPE=ELEMENT\n STRIP, SPOS\n"
            "*STEP, NAME=LOAD\n*COUPLED TEMPERATURE-DISPLACEMENT, STEADY STATE\n 1.0, 1.0\n*BOUNDARY\n ROOT, 1, 1\n %d, 2, 2\n %d, 2, 2\n %d, 3, 3\n"
            % (root[0], root[2], root[1]) +
            "*CLOAD\n %d, 2, %g\n %d, 2, %g\n %d, 2, %g\n" % (tip[0], -P / 6, tip[1], -4 * P / 6, tip[2], -P / 6) +
            "*FILM\n STRIP, FNEG, 0.0, 10.0\n*NODE PRINT, NSET=TIP\n U\n*END STEP\n"
            "*STEP, NAME=HEAT\n*COUPLED TEMPERATURE-DISPLACEMENT, STEADY STATE\n 1.0, 1.0\n*CLOAD, OP=NEW\n"
            "*DSFLUX\n TOP, S, 100.0\n*NODE PRINT, NSET=TIP\n U, NT\n*END STEP\n")


def cylinder():
    R, L, n = 1.0, 1.0, 4
    # SAX2T nodes along +z at r = R (end, middle, end): the normal (-t_z, t_r) = (-1, 0) points inwards, so
    # SPOS is the inside
    nodes = {1 + i: (R, L * i / (2 * n), 0.0) for i in range(2 * n + 1)}
    elems = [(e + 1, 1 + 2 * e, 2 + 2 * e, 3 + 2 * e) for e in range(n)]
    return ("*HEADING\n SAX2T open cylinder: inner pressure, then radial conduction\n" +
            "*NODE, NSET=ALL\n" + "".join(" %d, %.15g, %.15g\n" % (k, p[0], p[1]) for k, p in sorted(nodes.items())) +
            fmt_elems(elems, "SAX2T", "WALL") + MAT + "*SHELL SECTION, ELSET=WALL, MATERIAL=STEEL\n 0.02\n"
            "*SURFACE, NAME=INSIDE, TYPE=ELEMENT\n WALL, SPOS\n*SURFACE, NAME=OUTSIDE, TYPE=ELEMENT\n WALL, SNEG\n"
            "*STEP, NAME=PRESSURE\n*COUPLED TEMPERATURE-DISPLACEMENT, STEADY STATE\n 1.0, 1.0\n*BOUNDARY\n 1, 2, 2\n"
            "*DSLOAD\n INSIDE, P, 100.0\n*SFILM\n OUTSIDE, F, 0.0, 10.0\n*NODE PRINT, NSET=ALL\n U\n*END STEP\n"
            "*STEP, NAME=HEAT\n*COUPLED TEMPERATURE-DISPLACEMENT, STEADY STATE\n 1.0, 1.0\n*DSLOAD, OP=NEW\n"
            "*DSFLUX\n INSIDE, S, 100.0\n*NODE PRINT, NSET=ALL\n NT\n*END STEP\n")


def main():
    out = sys.argv[1]
    os.makedirs(out, exist_ok=True)
    decks = {"plate_s8rt": plate(out), "plate_spos_s8rt": plate(out, offset=True),
             "plate_moved_s8rt": plate(out, move=(rotation((1.0, 2.0, 3.0), 0.7), (1e5, -2e5, 3e5))),
             "plate_labels_s8rt": plate(out, labels=True), "plate_nodal_s8rt": plate(out, nodal=0.5),
             "taper_s8rt": plate(out, nodal=lambda p: 0.4 + 0.1 * p[0]), "taper_parts_s8rt": taper_parts(),
             "cantilever_s8rt": cantilever(), "cylinder_sax2t": cylinder()}
    for name, text in decks.items():
        with open(os.path.join(out, name + ".inp"), "w") as f:
            f.write(text)


if __name__ == "__main__":
    main()
