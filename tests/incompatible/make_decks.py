#!/usr/bin/python3
"""Decks of the incompatible-mode tests (CMakeLists.txt here; docs/elements.md "Incompatible modes"), in the
mechanical names a user's deck has (C3D8I, CPE4I, CPS4I, CAX4I: read with a temperature), *STATIC steps:

  cantilever_<type>.inp  a cantilever L = 10, height h = 1 (width 1), ONE element through the height, 10 along: step 1
                         an end couple M = 1 (forces +-M/h, split over the end face's nodes), step 2 a tip shear P = 1
                         added on the end face (spread by its consistent weights), E = 1000, nu = 0.3. The root x = 0:
                         u1 = 0 on the whole face, u2 (3D: u2 at the bottom corners too, u3 at one node) held at the
                         bottom edge only, so the section contracts freely (docs: check.py)
  patch_<type>.inp       a distorted patch (2 x 2 cells, 3D 2 x 2 x 2, the inner nodes moved by up to 30 % of a cell)
                         with every boundary node moved by the linear field u = A x and heated by 50 (free expansion
                         1.2e-5 x 50): the stress D (A_sym - eps_th I) uniform, exact in every element
  jacobian_<type>.inp    that mesh in a transient coupled step (E falling with temperature, expansion, a flux, a film):
                         the tangent against PETSc's finite differences
usage: make_decks.py [OUTDIR]"""
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
E, NU, ALPHA, DT = 1000.0, 0.3, 1.2e-5, 50.0
# the patch's linear displacement field (a general strain with rotation), 3D; 2D uses the upper-left 2 x 2
A = [[1.0e-3, 4.0e-4, -2.0e-4], [-1.0e-4, -5.0e-4, 3.0e-4], [2.5e-4, 1.5e-4, 7.0e-4]]
X0_AXI = 10.0  # the axisymmetric patch's inner radius


def material(expansion):
    return ("*MATERIAL, NAME=M\n*ELASTIC\n %g, %g\n" % (E, NU) + ("*EXPANSION\n %g\n" % ALPHA if expansion else "") +
            "*SOLID SECTION, ELSET=ALL, MATERIAL=M\n 1.0\n")


def cantilever(typ):
    three = typ.startswith("C3D")
    nx, L, h = 10, 10.0, 1.0
    nid = lambda i, j, k=0: 1 + i + (nx + 1) * (j + 2 * k)
    nodes, elems = [], []
    for k in range(2 if three else 1):
        for j in range(2):
            for i in range(nx + 1):
                nodes.append((nid(i, j, k), L * i / nx, h * j - 0.5, k - 0.5) if three else (nid(i, j), L * i / nx, h * j - 0.5))
    for i in range(nx):
        c = [nid(i, 0), nid(i + 1, 0), nid(i + 1, 1), nid(i, 1)]
        elems.append([i + 1] + (c + [nid(i, 0, 1), nid(i + 1, 0, 1), nid(i + 1, 1, 1), nid(i, 1, 1)] if three else c))
    ks = range(2) if three else [0]
    root = [nid(0, j, k) for j in range(2) for k in ks]
    bottom_root = [nid(0, 0, k) for k in ks]
    top_tip, bot_tip = [nid(nx, 1, k) for k in ks], [nid(nx, 0, k) for k in ks]
    f = 1.0 / h / len(top_tip)                 # the couple M = 1
    p = 1.0 / (len(top_tip) + len(bot_tip))    # the shear P = 1 (equal weights on a bilinear face)
    fmt = (lambda n: " %d, %.12g, %.12g, %.12g\n" % n) if three else (lambda n: " %d, %.12g, %.12g\n" % n)
    text = ("*HEADING\n Cantilever of one %s through its height: an end couple, then a tip shear\n" % typ +
            "*NODE\n" + "".join(fmt(n) for n in nodes) + "*ELEMENT, TYPE=%s, ELSET=ALL\n" % typ +
            "".join(" " + ", ".join(str(v) for v in e) + "\n" for e in elems) + material(False) +
            "*STEP, NAME=COUPLE\n*STATIC\n" + "*BOUNDARY\n" + "".join(" %d, 1, 1\n" % n for n in root) +
            "".join(" %d, 2, 2\n" % n for n in bottom_root) + (" %d, 3, 3\n" % root[0] if three else "") +
            "*CLOAD\n" + "".join(" %d, 1, %.12g\n" % (n, f) for n in top_tip) + "".join(" %d, 1, %.12g\n" % (n, -f) for n in bot_tip) +
            "*END STEP\n*STEP, NAME=SHEAR\n*STATIC\n*CLOAD, OP=NEW\n" + "".join(" %d, 2, %.12g\n" % (n, p) for n in top_tip + bot_tip) +
            "*END STEP\n")
    return text


def patch(typ):
    three = typ.startswith("C3D")
    axi = typ.startswith("CAX")
    n = 2
    nid = lambda i, j, k=0: 1 + i + (n + 1) * (j + (n + 1) * k)
    move = {(1, 1, 1): (0.3, -0.2, 0.25)} if three else {(1, 1, 0): (0.3, -0.2, 0.0)}
    nodes, bnd = [], []
    for k in range(n + 1 if three else 1):
        for j in range(n + 1):
            for i in range(n + 1):
                d = move.get((i, j, k), (0.0, 0.0, 0.0))
                # a distorted outer shape too: the corner (2, 2) pulled out, straight edges kept linear
                x = [0.5 * (i + d[0]), 0.5 * (j + d[1]) + 0.1 * i * j / 4, 0.5 * (k + d[2])]
                if axi:
                    x[0] += X0_AXI
                nodes.append((nid(i, j, k), x))
                if i in (0, n) or j in (0, n) or (three and k in (0, n)):
                    bnd.append((nid(i, j, k), x))
    elems = []
    for k in range(n if three else 1):
        for j in range(n):
            for i in range(n):
                c = [nid(i, j, k), nid(i + 1, j, k), nid(i + 1, j + 1, k), nid(i, j + 1, k)]
                if three:
                    c += [nid(i, j, k + 1), nid(i + 1, j, k + 1), nid(i + 1, j + 1, k + 1), nid(i, j + 1, k + 1)]
                elems.append([len(elems) + 1] + c)
    dim = 3 if three else 2
    fmt = lambda nd: " %d, " % nd[0] + ", ".join("%.12g" % v for v in nd[1][:dim]) + "\n"
    # axisymmetric: u_r = A00 r, u_z = A11 z (uniform strain with equal radial and hoop strains; a shear sigma_rz
    # would not be in equilibrium: d sigma_rz / dr + sigma_rz / r = sigma_rz / r)
    field = (lambda x: [A[0][0] * x[0], A[1][1] * x[1]]) if axi else \
            (lambda x: [sum(A[a][b] * x[b] for b in range(dim)) for a in range(dim)])
    bc = "".join(" %d, %d, %d, %.15g\n" % (nd, a + 1, a + 1, field(x)[a]) for nd, x in bnd for a in range(dim))
    return ("*HEADING\n Distorted patch of %s: a linear displacement on its boundary and a uniform heating\n" % typ +
            "*NODE, NSET=NALL\n" + "".join(fmt(nd) for nd in nodes) + "*ELEMENT, TYPE=%s, ELSET=ALL\n" % typ +
            "".join(" " + ", ".join(str(v) for v in e) + "\n" for e in elems) + material(True) +
            "*INITIAL CONDITIONS, TYPE=TEMPERATURE\n NALL, 0.0\n"
            "*STEP, NAME=PATCH\n*STATIC\n*BOUNDARY\n" + bc + "*TEMPERATURE\n NALL, %g\n*END STEP\n" % DT)


def jacobian(typ):
    """The patch's mesh in a transient coupled step with a temperature-dependent modulus, expansion, a flux and a
    film, the bottom held: the exact tangent of the condensed bubbles (u and theta columns) by -snes_test_jacobian."""
    text = patch(typ)
    head, _, _ = text.partition("*MATERIAL")
    three = typ.startswith("C3D")
    node_lines = head.partition("*NODE, NSET=NALL\n")[2].partition("*ELEMENT")[0].splitlines()
    bottom = [int(l.split(",")[0]) for l in node_lines if abs(float(l.split(",")[-1])) < 1e-12]  # z = 0 (2D: y = 0)
    return (head.replace("uniform heating", "uniform heating: the Jacobian test") +
            "*NSET, NSET=BOTTOM\n" + "".join(" %d,\n" % n for n in bottom) +
            "*MATERIAL, NAME=M\n*ELASTIC\n %g, %g, 0.0\n %g, %g, 100.0\n*EXPANSION\n 1.0E-3\n*CONDUCTIVITY\n 10.0\n*DENSITY\n 1.0\n"
            "*SPECIFIC HEAT\n 1.0\n*SOLID SECTION, ELSET=ALL, MATERIAL=M\n 1.0\n" % (E, NU, 0.5 * E, NU) +
            "*INITIAL CONDITIONS, TYPE=TEMPERATURE\n NALL, 20.0\n"
            "*STEP\n*COUPLED TEMPERATURE-DISPLACEMENT\n 0.1, 0.1\n*BOUNDARY\n BOTTOM, 1, %d\n*DFLUX\n 1, S%d, 500.0\n*FILM\n %d, F%d, 0.0, 10.0\n"
            "*END STEP\n" % (3 if three else 2, 2 if three else 3, 4 if three else 2, 4 if three else 2))


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else os.path.join(HERE, "decks")
    for typ in ("C3D8I", "C3D8", "CPE4I", "CPS4I"):
        open(os.path.join(out, "cantilever_%s.inp" % typ.lower()), "w").write(cantilever(typ))
    for typ in ("C3D8I", "CPE4I", "CPS4I", "CAX4I"):
        open(os.path.join(out, "patch_%s.inp" % typ.lower()), "w").write(patch(typ))
    for typ in ("C3D8I", "CAX4I"):
        open(os.path.join(out, "jacobian_%s.inp" % typ.lower()), "w").write(jacobian(typ))


if __name__ == "__main__":
    main()
