#!/usr/bin/python3
"""Linear stability of the steady frictional slide of the spec's planar blocks (the explicit friction decks of
jobs/verification/make_decks.py: a 2 x 0.25 block of 4 x 2 cells on a 6 x 1.25 block of 12 x 2 cells fixed at its
bottom, plane strain, E = 3e7, nu = 0.3, rho = 1000, mu = 0.1; docs/explicit.md "Friction-induced flutter").

While the small block slides (its top face driven along x, the friction opposing the slip: -s mu p on each secondary
node, s the sliding direction), the friction force follows the contact reaction p, which depends on the blocks'
deformation: a non-symmetric stiffness, so the steady slide can be dynamically unstable (mode-coupling flutter)
whatever the sliding speed. Linearised about the steady state (small strain; the pressure's own stress does not
enter), the blocks' free dofs u obey

    M u'' + C u' + K u = (G^T + T) lambda,   T = -s mu F^T,

with M the lumped (row-sum) masses, K the elements' stiffness (CPE4T: 2 x 2 Gauss points; CPE3T: constant strain,
the cells cut as make_decks.mesh2d cuts them, symmetric about x = 3), C the explicit solver's linear bulk
viscosity (the pressure b1 (lambda + 2 mu) dt_e eps_vol' at each element's centre, dt_e = 2 / omega_max the
element's own stable increment; src/element/kernels.c TslElementBulkViscosity), G the gaps of the secondary nodes on
the main faces (g_s = y_s - sum_j N_j y_j, a flat interface) and F their tangential slips (x_s - sum_j N_j x_j).
Kinematic contact closes every gap: G u = 0 with the reactions lambda that keep it so (G u'' = 0), the stiff limit of
a penalty; penalty contact instead adds eps_n l_s g_s to each node's reaction (eps_n = 10 E / the main face length,
the solver's default; l_s the node's tributary length). The largest real part of the eigenvalues of the first-order
system is the growth rate of the least stable mode: positive, the slide chatters once the mode has grown (the nodes
leave the face and strike it again), and the friction falls short of mu N.

usage: sliding_flutter.py [--check]   (prints the table; --check computes and asserts what docs/explicit.md quotes)
"""
import os
import re
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "../../jobs/verification"))
from make_decks import EXPLICIT_SLIDE_BULK_VISCOSITY  # noqa: E402  the kinematic friction decks' slide damping

B1_SLIDE = float(re.search(r"\n\s*([0-9.eE+-]+),", EXPLICIT_SLIDE_BULK_VISCOSITY).group(1))

E, NU, RHO, MU = 30.0e6, 0.3, 1000.0, 0.1
LAM, G_SHEAR = E * NU / ((1 + NU) * (1 - 2 * NU)), E / (2 * (1 + NU))
WAVE = LAM + 2 * G_SHEAR  # lambda + 2 mu, the bulk viscosity's modulus
D = np.array([[WAVE, LAM, 0.0], [LAM, WAVE, 0.0], [0.0, 0.0, G_SHEAR]])  # plane strain, engineering shear


def strain_matrix(dN):
    """B (3 x 2n) from the shape functions' gradients dN (2 x n)."""
    n = dN.shape[1]
    B = np.zeros((3, 2 * n))
    B[0, 0::2], B[1, 1::2], B[2, 0::2], B[2, 1::2] = dN[0], dN[1], dN[1], dN[0]
    return B


def triangle(xy):
    """Constant-strain triangle: stiffness, area, B_vol at the centre."""
    (x1, y1), (x2, y2), (x3, y3) = xy
    area = 0.5 * ((x2 - x1) * (y3 - y1) - (x3 - x1) * (y2 - y1))
    dN = np.array([[y2 - y3, y3 - y1, y1 - y2], [x3 - x2, x1 - x3, x2 - x1]]) / (2 * area)
    B = strain_matrix(dN)
    return area * B.T @ D @ B, area, B.T @ np.array([1.0, 1.0, 0.0])


def quad(xy):
    """Bilinear quadrilateral, 2 x 2 Gauss points: stiffness, area, B_vol at the centre."""
    def gradients(xi, eta):
        dN = 0.25 * np.array([[-(1 - eta), 1 - eta, 1 + eta, -(1 + eta)], [-(1 - xi), -(1 + xi), 1 + xi, 1 - xi]])
        J = dN @ xy
        return np.linalg.solve(J, dN), np.linalg.det(J)
    K, area, g = np.zeros((8, 8)), 0.0, 1 / np.sqrt(3)
    for xi in (-g, g):
        for eta in (-g, g):
            dN, det = gradients(xi, eta)
            B = strain_matrix(dN)
            K += det * B.T @ D @ B
            area += det
    return K, area, strain_matrix(gradients(0.0, 0.0)[0]).T @ np.array([1.0, 1.0, 0.0])


def block(nx, ny, x0, x1, y0, y1, shape, first):
    """Nodes (first, first + 1, ...) and elements of an nx x ny grid; triangles cut as make_decks.mesh2d cuts them
    (left of the block's centre along (n1, n3), right of it along (n2, n4))."""
    nid = lambda i, j: first + i + j * (nx + 1)
    xyz = [(x0 + (x1 - x0) * i / nx, y0 + (y1 - y0) * j / ny) for j in range(ny + 1) for i in range(nx + 1)]
    elems = []
    for j in range(ny):
        for i in range(nx):
            c1, c2, c3, c4 = nid(i, j), nid(i + 1, j), nid(i + 1, j + 1), nid(i, j + 1)
            if shape == "quad":
                elems.append((c1, c2, c3, c4))
            elif x0 + (x1 - x0) * (i + 0.5) / nx > 0.5 * (x0 + x1):
                elems += [(c1, c2, c4), (c2, c3, c4)]
            else:
                elems += [(c1, c2, c3), (c1, c3, c4)]
    return xyz, elems, nid


def growth(shape, contact="kinematic", b1=0.06, shift=0.0, s=1, small=(4, 2)):
    """Growth rate (1/s) and frequency (Hz) of the least stable mode of the steady slide; shift: the small block's
    position along x (0: its nodes on the main nodes, 0.25: midway on the 0.5 main faces); s: the sliding direction."""
    xl, el, nl = block(12, 2, 0.0, 6.0, 0.0, 1.25, shape, 0)
    xs, es, ns = block(small[0], small[1], 2.0 + shift, 4.0 + shift, 1.25, 1.5, shape, len(xl))
    X = np.array(xl + xs)
    n = 2 * len(X)
    K, C, m = np.zeros((n, n)), np.zeros((n, n)), np.zeros(n)
    for e in el + es:
        ke, area, bvol = (quad if len(e) == 4 else triangle)(X[list(e)])
        dofs = [2 * a + c for a in e for c in (0, 1)]
        me = np.full(2 * len(e), RHO * area / len(e))
        dt_e = 2 / np.sqrt(np.linalg.eigvalsh(ke / np.sqrt(np.outer(me, me))).max())
        K[np.ix_(dofs, dofs)] += ke
        C[np.ix_(dofs, dofs)] += b1 * WAVE * dt_e * area * np.outer(bvol, bvol)
        m[dofs] += me
    fixed = {2 * nl(i, 0) + c for i in range(13) for c in (0, 1)} | {2 * ns(i, small[1]) for i in range(small[0] + 1)}
    free = [k for k in range(n) if k not in fixed]
    # the secondary nodes' gaps (rows of Gm) and slips (rows of Fm) on the main faces of length 0.5
    h_main, h_sec = 0.5, 2.0 / small[0]
    Gm, Fm, lengths = [], [], []
    for i in range(small[0] + 1):
        a = ns(i, 0)
        x = X[a, 0]
        j = min(int(np.floor(x / h_main + 1e-9)), 11)
        w = x / h_main - j
        g, f = np.zeros(n), np.zeros(n)
        g[2 * a + 1], f[2 * a] = 1.0, 1.0
        for b, N in ((nl(j, 2), 1 - w), (nl(j + 1, 2), w)):
            g[2 * b + 1] -= N
            f[2 * b] -= N
        Gm.append(g), Fm.append(f), lengths.append(h_sec * (0.5 if i in (0, small[0]) else 1.0))
    Gm, Fm = np.array(Gm)[:, free], np.array(Fm)[:, free]
    K, C, m = K[np.ix_(free, free)], C[np.ix_(free, free)], m[free]
    T = -s * MU * Fm.T  # friction on the nodes per unit reaction
    if contact == "kinematic":
        # reactions lambda = S^-1 G M^-1 (C u' + K u) keep G u'' = 0; on the constraint's null space u = Z q
        S = Gm @ ((Gm.T + T) / m[:, None])
        R = (Gm.T + T) @ np.linalg.solve(S, Gm / m[None, :])  # u'' = -M^-1 (I - R) (K u + C u')
        Z = np.linalg.svd(Gm)[2][len(Gm):].T
        Mr = Z.T @ (m[:, None] * Z)
        P = Z.T @ (np.eye(len(m)) - R)
        Kr, Cr = np.linalg.solve(Mr, P @ K @ Z), np.linalg.solve(Mr, P @ C @ Z)
    else:
        eps = 10 * E / h_main
        for g, f, l in zip(Gm, Fm, lengths):
            K = K + eps * l * np.outer(g, g) - s * MU * eps * l * np.outer(f, g)  # reaction -eps l g, friction -s mu of it
        Kr, Cr = K / m[:, None], C / m[:, None]
    N = len(Kr)
    A = np.block([[np.zeros((N, N)), np.eye(N)], [-Kr, -Cr]])
    ev = np.linalg.eigvals(A)
    k = int(np.argmax(ev.real))
    return float(ev[k].real), float(abs(ev[k].imag) / (2 * np.pi))


POSITIONS = (0.0, 0.0625, 0.125, 0.1875)  # the small block's nodes at 0, 1/8, 1/4, 3/8 of a main face (0.5)


def worst(shape, contact, b1):
    """The least stable mode over the positions (the same by symmetry at 5/8, 3/4, 7/8 and for s = -1)."""
    return max(growth(shape, contact, b1, shift) for shift in POSITIONS)


# what docs/explicit.md quotes ("Friction-induced flutter"), and --check asserts: the decks' quads are stable; the
# triangles flutter at about 246 Hz under the kinematic tie undamped and with the default bulk viscosity, not with the
# default penalty, and not with the kinematic friction decks' slide damping (make_decks.py
# EXPLICIT_SLIDE_BULK_VISCOSITY, B1_SLIDE)
CASES = [("quad", "kinematic", 0.06), ("quad", "kinematic", B1_SLIDE), ("tri", "kinematic", 0.0), ("tri", "kinematic", 0.06),
         ("tri", "kinematic", B1_SLIDE), ("tri", "penalty", 0.0), ("tri", "penalty", 0.06)]
TABLE = [(shape, contact, b1) for shape in ("quad", "tri") for contact in ("kinematic", "penalty")
         for b1 in sorted({0.0, 0.06, 0.1, 0.2, B1_SLIDE, 0.5})]


if __name__ == "__main__":
    check_only = "--check" in sys.argv
    name = {"quad": "CPE4T", "tri": "CPE3T"}
    r = {}
    print("least stable mode of the steady slide, s = +1, the worst of the positions %s of a main face" % ", ".join("%g" % (p / 0.5) for p in POSITIONS))
    for case in (CASES if check_only else TABLE):
        r[case] = worst(*case)
        print("  %-5s %-9s b1 %.2f: %+9.4f /s at %6.1f Hz" % (name[case[0]], case[1], case[2], r[case][0], r[case][1]))
    if not check_only:
        for b1 in sorted({0.06, B1_SLIDE, 0.5}):
            g = growth("quad", "kinematic", b1, small=(8, 4))
            print("  CPE4T with the small block 8 x 4, kinematic b1 %.2f: %+9.4f /s at %6.1f Hz" % (b1, g[0], g[1]))
        sys.exit(0)
    sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "../tools"))
    from tslcheck import check, check_true, finish

    def stable(label, case):
        check_true("%s: no growing mode" % label, r[case][0] <= 1e-6, "%.4g /s" % r[case][0])

    def growing(label, case, rate):
        check_true("%s: flutter growing faster than %g /s" % (label, rate), r[case][0] > rate, "%.4g /s at %.1f Hz" % r[case])

    stable("CPE4T, kinematic, b1 0.06 (the default)", ("quad", "kinematic", 0.06))
    stable("CPE4T, kinematic, b1 %g (the decks' slide)" % B1_SLIDE, ("quad", "kinematic", B1_SLIDE))
    growing("CPE3T, kinematic, undamped", ("tri", "kinematic", 0.0), 10.0)
    check("CPE3T, kinematic, undamped: the flutter's frequency (Hz; the chatter measured 246 - 249 Hz)", r[("tri", "kinematic", 0.0)][1], 246.0, 0.02, relative=True)
    growing("CPE3T, kinematic, b1 0.06 (the default)", ("tri", "kinematic", 0.06), 1.0)
    stable("CPE3T, kinematic, b1 %g (the decks' slide)" % B1_SLIDE, ("tri", "kinematic", B1_SLIDE))
    growing("CPE3T, default penalty, undamped", ("tri", "penalty", 0.0), 0.5)
    stable("CPE3T, default penalty, b1 0.06 (the default)", ("tri", "penalty", 0.06))
    finish()
