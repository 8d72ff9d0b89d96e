#!/usr/bin/python3
"""Writes the decks of contact on quadratic (line3) faces in this folder (run once; the decks are committed).

  contact_line3_uniform_{cpe8t,cax8t,cgax8t}.inp
      Two blocks of one material stacked with matched meshes (8-node elements, so the interface is made of
      line3 faces), a uniform pressure and a uniform heat flux on the top, steady state. The exact solution
      (uniform uniaxial stress, temperature linear through each block with a jump at the interface) lies in
      the element space, so with consistent contact weights (1/6, 2/3, 1/6 of a face) every secondary node,
      corner or midside, carries the applied pressure and flux. CGAX8T: the same with the twist rows
      (twist held), whose contact must revolve like CAX8T's; contact_twist_friction_cgax8t.inp adds
      *FRICTION: nothing slips, so the answer is the frictionless one.
  contact_twist_slide_{cgax4t,cgax8t}_{axial,twist,combined}.inp
      Frictional sliding with circumferential slip (twist rows): an inner ring (r 1 to 1.25, z 2 to 4) pressed
      outward (radial force 211.6 on its inner face, tied radially) on an outer ring (r 1.25 to 2.5, z 0 to 6)
      held on its outside, LAGRANGE friction mu = 0.1, frictional heating eta = 0.5; the inner face is then
      driven by a slide of magnitude 1 at the interface radius 1.25: axially (u_z = 1), circumferentially
      (phi = 1/1.25, the path 1.25 phi = 1) or both (u_z = 0.6, 1.25 phi = 0.8). check_twist_slide.py.
  contact_line3_jacobian_cpe8t.inp, contact_line3_friction_cpe8t.inp
      jobs/verification/contact_jacobian_cpe4t.inp and sliding_friction_cpe4t.inp with every CPE4T made a
      CPE8T (a midside node in the middle of each edge; node sets gain the midsides of their edges), so the
      same laws and checks run on line3 faces.
"""
import os
import re

HERE = os.path.dirname(os.path.abspath(__file__))
JOBS = os.path.join(HERE, "..", "..", "..", "jobs", "verification")


def quad8_block(nx, ny, x0, x1, y0, y1, first_node, first_elem):
    """A structured block of 8-node quadrilaterals: nodes on the (2nx+1) x (2ny+1) grid without the
    element centres, elements counter-clockwise with corners then midsides (bottom, right, top, left)."""
    nodes, grid = [], {}
    for j in range(2 * ny + 1):
        for i in range(2 * nx + 1):
            if i % 2 and j % 2:
                continue
            grid[i, j] = first_node + len(nodes)
            nodes.append((grid[i, j], x0 + (x1 - x0) * i / (2 * nx), y0 + (y1 - y0) * j / (2 * ny)))
    elems = []
    for j in range(ny):
        for i in range(nx):
            a, b = 2 * i, 2 * j
            c = [grid[a, b], grid[a + 2, b], grid[a + 2, b + 2], grid[a, b + 2]]
            m = [grid[a + 1, b], grid[a + 2, b + 1], grid[a + 1, b + 2], grid[a, b + 1]]
            elems.append((first_elem + i + j * nx, c + m))
    return nodes, elems, grid


def quad_block(order, nx, ny, x0, x1, y0, y1, first_node, first_elem):
    """quad8_block for order 2; for order 1 the 4-node quadrilaterals of the same grid of cells (the grid is
    indexed on the lattice (order nx + 1) x (order ny + 1) either way)."""
    if order == 2:
        return quad8_block(nx, ny, x0, x1, y0, y1, first_node, first_elem)
    nodes, grid = [], {}
    for j in range(ny + 1):
        for i in range(nx + 1):
            grid[i, j] = first_node + len(nodes)
            nodes.append((grid[i, j], x0 + (x1 - x0) * i / nx, y0 + (y1 - y0) * j / ny))
    elems = [(first_elem + i + j * nx, [grid[i, j], grid[i + 1, j], grid[i + 1, j + 1], grid[i, j + 1]]) for j in range(ny) for i in range(nx)]
    return nodes, elems, grid


def lines(ids, per=8):
    ids = list(ids)
    return "\n".join(" " + ", ".join(str(x) for x in ids[k:k + per]) for k in range(0, len(ids), per))


def uniform(etype, x0, friction=False):
    nx, W = 3, 2.0
    k = 1 if etype.endswith("4T") else 2  # nodes per cell side - 1: line2 or line3 faces on the interface
    low_n, low_e, low_g = quad_block(k, nx, 2, x0, x0 + W, 0.0, 1.0, 1, 1)
    up_n, up_e, up_g = quad_block(k, nx, 1, x0, x0 + W, 1.0, 1.5, 1001, 101)
    plane = etype.startswith("CP")
    twist = etype.startswith("CGAX")
    out = ["*HEADING",
           " Uniform pressure (100) and heat flux (10) through two stacked %s blocks: contact on line%d faces" % (etype, k + 1),
           "*NODE, NSET=ALL"]
    out += [" %d, %.17g, %.17g" % n for n in low_n + up_n]
    out.append("*ELEMENT, TYPE=%s, ELSET=LOWER" % etype)
    out += [" %d, %s" % (e, ", ".join(str(x) for x in c)) for e, c in low_e]
    out.append("*ELEMENT, TYPE=%s, ELSET=UPPER" % etype)
    out += [" %d, %s" % (e, ", ".join(str(x) for x in c)) for e, c in up_e]
    out += ["*NSET, NSET=BASE", lines(low_g[i, 0] for i in range(k * nx + 1))]
    if plane:  # symmetry plane x = 0: removes the rigid x motion of both blocks, leaves the Poisson expansion free
        out += ["*NSET, NSET=LEFT", lines([n for (i, j), n in sorted(low_g.items()) if i == 0] + [n for (i, j), n in sorted(up_g.items()) if i == 0])]
    if twist:  # the upper ring's rigid twist, which frictionless contact leaves free
        out += ["*NSET, NSET=UPTOP", lines(up_g[i, k] for i in range(k * nx + 1))]
    out += ["*ELSET, ELSET=LOWTOP", lines(e for e, c in low_e[nx:]),
            "*ELSET, ELSET=BODY", lines([e for e, c in low_e] + [e for e, c in up_e]),
            "*SURFACE, NAME=MAIN, TYPE=ELEMENT", " LOWTOP, S3",
            "*SURFACE, NAME=SECONDARY, TYPE=ELEMENT", " UPPER, S1",
            "*MATERIAL, NAME=STEEL", "*ELASTIC", " 200000.0, 0.3", "*CONDUCTIVITY", " 50.0", "*DENSITY", " 1.0",
            "*SPECIFIC HEAT", " 1.0",
            "*SOLID SECTION, ELSET=BODY, MATERIAL=STEEL", " 1.0",
            "*SURFACE INTERACTION, NAME=IFACE"] + (["*FRICTION", " 0.1"] if friction else []) + [
            "*GAP CONDUCTANCE, PRESSURE", " 20.0, 100.0", " 5.0, 200.0",
            "*CONTACT PAIR, INTERACTION=IFACE, SMOOTH=0.2", " SECONDARY, MAIN",
            "*INITIAL CONDITIONS, TYPE=TEMPERATURE", " ALL, 0.0",
            "*STEP, NAME=PRESS AND HEAT", "*COUPLED TEMPERATURE-DISPLACEMENT, STEADY STATE",
            "*BOUNDARY", " BASE, 2, 2", " BASE, 11, 11, 0.0"]
    if plane:
        out.append(" LEFT, 1, 1")
    if twist:
        out += [" BASE, 5, 5", " UPTOP, 5, 5"]
    out += ["*DLOAD", " UPPER, P3, 100.0", "*DFLUX", " UPPER, S3, 10.0", "*END STEP", ""]
    name = "contact_%s_%s.inp" % ("twist_friction" if friction else "line3_uniform" if k == 2 else "line2_uniform", etype.lower())
    open(os.path.join(HERE, name), "w").write("\n".join(out))


def twist_slide(etype, motion):
    """The ring pair of contact_twist_slide_*: x = r, y = z; motion axial, twist or combined (docstring above)."""
    order = 2 if etype.endswith("8T") else 1
    out_n, out_e, out_g = quad_block(order, 2, 12, 1.25, 2.5, 0.0, 6.0, 1, 1)
    in_n, in_e, in_g = quad_block(order, 2, 4, 1.0, 1.25, 2.0, 4.0, 1001, 101)
    base = [n for (i, j), n in sorted(out_g.items()) if i == 2 * order]
    driven = [n for (i, j), n in sorted(in_g.items()) if i == 0]
    ref = driven[0]
    uz, path = {"axial": (1.0, 0.0), "twist": (0.0, 1.0), "combined": (0.6, 0.8)}[motion]
    out = ["*HEADING",
           " Inner %s ring pressed on an outer ring and slid with friction at the interface radius 1.25: %s (u_z %g, 1.25 phi %g)" %
           (etype, motion, uz, path),
           "*NODE, NSET=ALL"]
    out += [" %d, %.17g, %.17g" % n for n in out_n + in_n]
    out.append("*ELEMENT, TYPE=%s, ELSET=OUTER" % etype)
    out += [" %d, %s" % (e, ", ".join(str(x) for x in c)) for e, c in out_e]
    out.append("*ELEMENT, TYPE=%s, ELSET=INNER" % etype)
    out += [" %d, %s" % (e, ", ".join(str(x) for x in c)) for e, c in in_e]
    out += ["*NSET, NSET=BASE", lines(base), "*NSET, NSET=DRIVEN", lines(driven),
            "*ELSET, ELSET=MAINE", lines(e for k, (e, c) in enumerate(out_e) if k % 2 == 0),
            "*ELSET, ELSET=SECE", lines(e for k, (e, c) in enumerate(in_e) if k % 2 == 1),
            "*SURFACE, NAME=MAIN, TYPE=ELEMENT", " MAINE, S4",
            "*SURFACE, NAME=SECONDARY, TYPE=ELEMENT", " SECE, S2",
            "*MATERIAL, NAME=STEEL", "*ELASTIC", " 30.0E6, 0.3", "*CONDUCTIVITY", " 10.0", "*DENSITY", " 1000.0",
            "*SPECIFIC HEAT", " 0.001",
            "*SOLID SECTION, ELSET=OUTER, MATERIAL=STEEL", " 1.0", "*SOLID SECTION, ELSET=INNER, MATERIAL=STEEL", " 1.0",
            "*SURFACE INTERACTION, NAME=IFACE", "*FRICTION, LAGRANGE", " 0.1", "*GAP CONDUCTANCE, PRESSURE", " 20.0, 0.0",
            "*GAP HEAT GENERATION", " 0.5, 0.5",
            "*CONTACT PAIR, INTERACTION=IFACE, SMOOTH=0.05", " SECONDARY, MAIN",
            "*AMPLITUDE, NAME=SLIDE", " 0.0, 0.0, 1.0, 1.0",
            "*INITIAL CONDITIONS, TYPE=TEMPERATURE", " ALL, 0.0"]
    for n in driven[1:]:
        out += ["*EQUATION", " 2", " %d, 1, 1.0, %d, 1, -1.0" % (n, ref)]
    out += ["*STEP, NAME=PRESS, INC=100", "*COUPLED TEMPERATURE-DISPLACEMENT", " 0.5, 1.0",
            "*BOUNDARY", " BASE, 1, 2", " BASE, 5, 5", " DRIVEN, 2, 2", " DRIVEN, 5, 5",
            "*CLOAD", " %d, 1, 211.6" % ref, "*END STEP",
            "*STEP, NAME=SLIDE, INC=1000", "*COUPLED TEMPERATURE-DISPLACEMENT", " 0.05, 1.0, 1e-5, 0.05",
            "*BOUNDARY, AMPLITUDE=SLIDE", " DRIVEN, 2, 2, %.17g" % uz, " DRIVEN, 5, 5, %.17g" % (path / 1.25), "*END STEP", ""]
    name = "contact_twist_slide_%s_%s.inp" % (etype.lower(), motion)
    open(os.path.join(HERE, name), "w").write("\n".join(out))


def is_mesh(sec, kw):
    """A *NODE / *ELEMENT data block (not *NODE OUTPUT, *NODE PRINT, *ELEMENT OUTPUT)."""
    return sec is not None and sec.startswith(kw) and not re.match(r"\*(NODE|ELEMENT) (OUTPUT|PRINT)", sec)


def to_quad8(src, dst, heading):
    """CPE4T deck -> CPE8T deck: a midside node in the middle of every edge (ids from 2001 for edges of
    nodes above 1000, from 501 otherwise), node sets completed with the midsides of their edges."""
    text = open(os.path.join(JOBS, src)).read().split("\n")
    nodes, elems, sec = {}, [], None
    for ln in text:
        if ln.startswith("*"):
            sec = ln.upper()
        elif is_mesh(sec, "*NODE") and ln.strip():
            f = [x.strip() for x in ln.split(",")]
            nodes[int(f[0])] = (float(f[1]), float(f[2]))
        elif is_mesh(sec, "*ELEMENT") and ln.strip():
            elems.append([int(x) for x in ln.split(",")])
    edge, count = {}, {"low": 500, "high": 2000}

    def mid(a, b):
        k = (min(a, b), max(a, b))
        if k not in edge:
            side = "high" if a > 1000 and b > 1000 else "low"
            count[side] += 1
            edge[k] = count[side]
            nodes[edge[k]] = tuple(0.5 * (nodes[a][d] + nodes[b][d]) for d in range(2))
        return edge[k]

    conn = {}
    for f in elems:
        c = f[1:5]
        conn[f[0]] = c + [mid(c[0], c[1]), mid(c[1], c[2]), mid(c[2], c[3]), mid(c[3], c[0])]
    out, sec, members, wrote_nodes = [], None, None, False

    def close_set():
        if members is not None:
            s = set(members)
            out.append(lines(members + sorted(m for k, m in edge.items() if k[0] in s and k[1] in s)))

    for ln in text:
        if ln.startswith("*"):
            close_set()
            members, sec = None, ln.upper()
            if is_mesh(sec, "*NODE"):
                if not wrote_nodes:
                    out.append("*NODE, NSET=ALL")
                    out += [" %d, %.17g, %.17g" % (n, nodes[n][0], nodes[n][1]) for n in sorted(nodes)]
                    wrote_nodes = True
                continue
            if sec.startswith("*NSET"):
                members = []
            out.append(ln.replace("CPE4T", "CPE8T"))
        elif sec.startswith("*HEADING"):
            out.append(" " + heading)
        elif is_mesh(sec, "*NODE"):
            continue
        elif is_mesh(sec, "*ELEMENT") and ln.strip():
            e = int(ln.split(",")[0])
            out.append(" %d, %s" % (e, ", ".join(str(x) for x in conn[e])))
        elif members is not None and ln.strip():
            members += [int(x) for x in ln.split(",") if x.strip()]
        else:
            out.append(ln)
    close_set()
    open(os.path.join(HERE, dst), "w").write("\n".join(out))


uniform("CPE8T", 0.0)
uniform("CAX8T", 0.5)
uniform("CGAX8T", 0.5)  # twist rows: contact acts in the r-z plane, the same answer as CAX8T
uniform("CGAX8T", 0.5, friction=True)  # with *FRICTION: nothing slips, the frictionless answer
uniform("CAX4T", 0.5)  # line2 faces: the consistent axisymmetric weights int N_a 2 pi r ds (src/mesh/distribute.c)
for etype in ("CGAX4T", "CGAX8T"):
    for motion in ("axial", "twist", "combined"):
        twist_slide(etype, motion)
to_quad8("contact_jacobian_cpe4t.inp", "contact_line3_jacobian_cpe8t.inp",
         "Contact Jacobian check on line3 faces (jobs/verification/contact_jacobian_cpe4t.inp with CPE8T): stick, slip, open")
to_quad8("sliding_friction_cpe4t.inp", "contact_line3_friction_cpe8t.inp",
         "Finite sliding with Lagrange friction and frictional heating on line3 faces (sliding_friction_cpe4t.inp with CPE8T)")
