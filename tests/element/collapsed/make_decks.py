#!/usr/bin/python3
"""Writes the collapsed-element decks of tests/element (run once; the decks are committed beside it).

A unit patch of 2 x 2 (x 2) cells on [0, 2]^d, its centre node moved off the middle, each cell cut into two
triangles (wedges), written twice: with the proper types (CPE3T, C3D6T) and as Abaqus/CAE writes them collapsed
(CPE4T a, b, c, c; C3D8T a, b, c, c, a', b', c', c'). Every boundary node is given a linear displacement and a
linear temperature, the centre node is free: the patch test (uniform strain, uniform heat flux) in a steady
coupled step, which both meshes must pass exactly, so their results agree to round-off.
The axisymmetric variant (CAX3T against CAX4T collapsed) puts the patch at the axis, r in [0, 2]: the
triangles CAE writes at a sweep's axis.
usage: make_decks.py   (writes collapsed_{2d,3d,ax}_{proper,collapsed}.inp here)
"""
import itertools
import os

HERE = os.path.dirname(os.path.abspath(__file__))
STRAIN = [[1e-3, 4e-4, -2e-4], [0.0, -5e-4, 3e-4], [0.0, 0.0, 6e-4]]  # u_i = sum_j STRAIN[i][j] x_j
GRAD = [5.0, 3.0, -2.0]  # theta = 10 + GRAD . x
# axisymmetric (r, z): the uniform strains u_r = c r, u_z = d z and a temperature linear in z, the states an
# axisymmetric patch holds exactly (u_r = h z would give a hoop strain h z / r, a uniform shear s_rz is out of
# equilibrium by s_rz / r; theta linear in r is no steady state)
STRAIN_AX = [[1e-3, 0.0], [0.0, -5e-4]]
GRAD_AX = [0.0, 3.0]


def fields(variant):
    """(STRAIN, GRAD) of a variant: 2d, 3d or ax."""
    return (STRAIN_AX, GRAD_AX) if variant == "ax" else (STRAIN, GRAD)


def deck(variant, collapsed):
    dim = 3 if variant == "3d" else 2
    strain, grad = fields(variant)
    n = 3
    ids, xyz = {}, []
    for p in itertools.product(range(n), repeat=dim):
        x = [float(c) for c in reversed(p)]  # x fastest
        if all(c == 1 for c in p):
            x = [1.1, 0.93, 1.04][:dim]
        ids[tuple(reversed(p))] = len(xyz) + 1
        xyz.append(x)
    elems = []
    cells = itertools.product(range(n - 1), repeat=dim)
    for c in cells:
        c = tuple(reversed(c))
        corner = lambda dx, dy, dz=0: ids[(c[0] + dx, c[1] + dy) + ((c[2] + dz,) if dim == 3 else ())]
        tris = [[(0, 0), (1, 0), (1, 1)], [(0, 0), (1, 1), (0, 1)]]
        for t in tris:
            if dim == 2:
                v = [corner(*q) for q in t]
                elems.append(v + [v[2]] if collapsed else v)
            else:
                lo, hi = [corner(*q, 0) for q in t], [corner(*q, 1) for q in t]
                elems.append(lo + [lo[2]] + hi + [hi[2]] if collapsed else lo + hi)
    typ = {("2d", False): "CPE3T", ("2d", True): "CPE4T", ("3d", False): "C3D6T", ("3d", True): "C3D8T", ("ax", False): "CAX3T",
           ("ax", True): "CAX4T"}[(variant, collapsed)]
    out = ["*HEADING", " Patch test of %s %s elements: linear displacement and temperature on the boundary, centre node free"
           % ("collapsed" if collapsed else "proper", typ), "*NODE, NSET=ALL"]
    out += ["%d, %s" % (i + 1, ", ".join("%.6f" % v for v in x)) for i, x in enumerate(xyz)]
    out.append("*ELEMENT, TYPE=%s, ELSET=BODY" % typ)
    out += ["%d, %s" % (e + 1, ", ".join(str(v) for v in conn)) for e, conn in enumerate(elems)]
    centre = ids[(1,) * dim]
    out.append("*NSET, NSET=EDGE")
    out += ["%d," % i for i in range(1, len(xyz) + 1) if i != centre]
    out += ["*MATERIAL, NAME=STEEL", "*ELASTIC", " 200000., 0.3", "*CONDUCTIVITY", " 50.", "*DENSITY", " 7.8e-9",
            "*SPECIFIC HEAT", " 4.6e8", "*SOLID SECTION, ELSET=BODY, MATERIAL=STEEL", "*STEP",
            "*COUPLED TEMPERATURE-DISPLACEMENT, STEADY STATE", " 1., 1.", "*BOUNDARY"]
    for i, x in enumerate(xyz):
        if i + 1 == centre:
            continue
        for k in range(dim):
            out.append(" %d, %d, %d, %.12e" % (i + 1, k + 1, k + 1, sum(strain[k][j] * x[j] for j in range(dim))))
        out.append(" %d, 11, 11, %.12e" % (i + 1, 10 + sum(grad[j] * x[j] for j in range(dim))))
    out += ["*NODE OUTPUT", " U, NT", "*ELEMENT OUTPUT", " S, E, HFL", "*END STEP", ""]
    return "\n".join(out)


if __name__ == "__main__":
    for variant in ("2d", "3d", "ax"):
        for collapsed in (False, True):
            with open(os.path.join(HERE, "collapsed_%s_%s.inp" % (variant, "collapsed" if collapsed else "proper")), "w") as f:
                f.write(deck(variant, collapsed))
