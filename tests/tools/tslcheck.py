"""Reading thermoslide results and printing verification checks (used by tests and the demo).

Each check prints one line `name: value (expected E, tolerance T) PASS|FAIL`; `finish()` exits non-zero
if any failed. Uses Debian's python3-h5py and python3-numpy only.
"""
import csv
import math
import sys

import h5py
import numpy as np

_failed = []


class Result:
    """The .h5 and .csv of one job."""

    def __init__(self, outdir, job):
        self.h5 = h5py.File("%s/%s.h5" % (outdir, job), "r")
        self.xyz = self.h5["/mesh/coordinates"][...]
        self.node_ids = self.h5["/mesh/node_ids"][...]
        self.frames = sorted(self.h5["/frames"].keys())
        with open("%s/%s.csv" % (outdir, job)) as f:
            rows = list(csv.DictReader(f))
        self.history = {k: np.array([float(r[k]) for r in rows]) for k in rows[0]} if rows else {}

    def frame(self, index=-1):
        return self.h5["/frames/" + self.frames[index]]

    def field(self, name, index=-1):
        return self.frame(index)[name][...]

    def frame_of_step(self, step, last=True):
        """Index of the last (or first) frame written in a step."""
        idx = [i for i, f in enumerate(self.frames) if int(self.h5["/frames/" + f].attrs["step"]) == step]
        return idx[-1] if last else idx[0]

    def elements(self):
        """Connectivity (natural node indices) of each element from the Mixed topology, in the dialect's node order
        (the file's is XDMF's, whose wedges run their base the other way round: the swaps undo it)."""
        topo, out, k = self.h5["/mesh/topology"][...], [], 0
        sizes = {4: 3, 5: 4, 6: 4, 8: 6, 9: 8, 36: 6, 37: 8, 38: 10, 40: 15, 48: 20}
        dialect = {8: [0, 2, 1, 3, 5, 4], 40: [0, 2, 1, 3, 5, 4, 8, 7, 6, 11, 10, 9, 12, 14, 13]}
        while k < len(topo):
            t = int(topo[k])
            if t == 2:  # Polyline (a link DC1D2): its node count follows
                k += 1
                sizes[2] = int(topo[k])
            n = sizes[t]
            cell = topo[k + 1:k + 1 + n]
            out.append(cell[dialect[t]] if t in dialect else cell)
            k += 1 + n
        return out


def face_shape(n, a, b):
    """Shape functions of a quad4 ((a, b) in [-1, 1]^2), tri3 or tri6 (the unit triangle) face and their
    derivatives, nodes in the catalogue's face order (corners, then the midsides 1-2, 2-3, 3-1)."""
    if n == 4:
        sa, sb = [-1, 1, 1, -1], [-1, -1, 1, 1]
        N = np.array([0.25 * (1 + sa[k] * a) * (1 + sb[k] * b) for k in range(4)])
        dN = np.array([[0.25 * sa[k] * (1 + sb[k] * b), 0.25 * sb[k] * (1 + sa[k] * a)] for k in range(4)])
        return N, dN
    L = [1 - a - b, a, b]
    dL = [[-1, -1], [1, 0], [0, 1]]
    if n == 3:
        return np.array(L), np.array(dL, dtype=float)
    N = [L[k] * (2 * L[k] - 1) for k in range(3)] + [4 * L[p] * L[q] for p, q in ((0, 1), (1, 2), (2, 0))]
    dN = [[(4 * L[k] - 1) * dL[k][c] for c in range(2)] for k in range(3)]
    dN += [[4 * (dL[p][c] * L[q] + L[p] * dL[q][c]) for c in range(2)] for p, q in ((0, 1), (1, 2), (2, 0))]
    return np.array(N), np.array(dN)


# edges of a hex20 (its nodes 9..20 are the midsides of these, in this order; XDMF's order is the same)
HEX20_EDGES = [(0, 1), (1, 2), (2, 3), (3, 0), (4, 5), (5, 6), (6, 7), (7, 4), (0, 4), (1, 5), (2, 6), (3, 7)]


def plane_faces(r, which, y0, faces_3d, tet10_edges):
    """3D: the element faces on the plane y = y0 (reference) of the elements whose first node is in the mask
    `which`, as natural node indices in the catalogue's face order (corners, then midsides); faces_3d and
    tet10_edges are make_decks.py's tables."""
    out = []
    for conn in r.elements():
        conn = list(conn)
        if not which[conn[0]]:
            continue
        shape = {8: "hex", 20: "hex", 6: "wedge", 4: "tet", 10: "tet"}[len(conn)]
        for corners in faces_3d[shape]:
            if all(abs(r.xyz[conn[c], 1] - y0) < 1e-9 for c in corners):
                face = [conn[c] for c in corners]
                if len(conn) in (10, 20):  # tet10, hex20: the midside nodes of the face's edges
                    edges = tet10_edges if len(conn) == 10 else HEX20_EDGES
                    first = 4 if len(conn) == 10 else 8
                    edge = {frozenset(e): first + k for k, e in enumerate(edges)}
                    face += [conn[edge[frozenset((corners[k], corners[(k + 1) % len(corners)]))]] for k in range(len(corners))]
                out.append(face)
    return out


def contact_faces(faces):
    """A main surface's faces as contact sees them: a tri6 face (C3D10MT) is its four tri3 sub-faces, as its
    pressure loads are; a quad8 face (C3D20RT, the expanded S8RT) its four corner triangles and the quad of its
    midside nodes (docs/contact.md, "3D pairs", "Quad8 faces")."""
    def pieces(f):
        if len(f) == 6:
            return [[f[0], f[3], f[5]], [f[3], f[1], f[4]], [f[5], f[4], f[2]], [f[3], f[4], f[5]]]
        if len(f) == 8:
            return [[f[0], f[4], f[7]], [f[1], f[5], f[4]], [f[2], f[6], f[5]], [f[3], f[7], f[6]], [f[4], f[5], f[6], f[7]]]
        return [f]
    return [g for f in faces for g in pieces(f)]


def locate(faces, xz, p):
    """The face of `faces` (node lists) whose (x, z) positions xz[face] contain the point p = (x, z), and its
    shape functions there: (face, N), or (None, None)."""
    for f in faces:
        X = xz[f]
        if p[0] < X[:, 0].min() - 1e-9 or p[0] > X[:, 0].max() + 1e-9 or p[1] < X[:, 1].min() - 1e-9 or p[1] > X[:, 1].max() + 1e-9:
            continue
        a = np.array([0.0, 0.0]) if len(f) == 4 else np.array([1 / 3, 1 / 3])
        for _ in range(30):
            N, dN = face_shape(len(f), *a)
            a = a + np.linalg.solve(X.T @ dN, p - N @ X)
        N, _ = face_shape(len(f), *a)
        inside = (abs(a) <= 1 + 1e-9).all() if len(f) == 4 else (a.min() >= -1e-9 and a.sum() <= 1 + 1e-9)
        if inside:
            return f, N
    return None, None


def line_faces(xyz, nodes, quadratic):
    """2D: the faces along a line of interface nodes, sorted by reference x: pairs, or (corner, midside,
    corner) triples on quadratic meshes (line3)."""
    nodes = np.asarray(nodes)[np.argsort(xyz[nodes, 0])]
    k = 2 if quadratic else 1
    return [nodes[i:i + k + 1] for i in range(0, len(nodes) - 1, k)]


def line_shape(n, a):
    """Shape functions of a line2 or line3 face (a in [-1, 1]; nodes end, [midside,] end as line_faces
    orders them) and their derivatives."""
    if n == 2:
        return np.array([0.5 * (1 - a), 0.5 * (1 + a)]), np.array([-0.5, 0.5])
    return np.array([0.5 * a * (a - 1), 1 - a * a, 0.5 * a * (a + 1)]), np.array([a - 0.5, -2 * a, a + 0.5])


def line_locate(faces, x, p):
    """The face of `faces` whose current x positions x[face] hold p and its shape functions there (x(a) = p
    by Newton, as contact projects): (face, N), or (None, None)."""
    for f in faces:
        X = x[f]
        if p < X.min() - 1e-12 or p > X.max() + 1e-12:
            continue
        a = 0.0
        for _ in range(30):
            N, dN = line_shape(len(f), a)
            a += (p - N @ X) / (dN @ X)
        return f, line_shape(len(f), a)[0]
    return None, None


def line_weights(xyz, faces):
    """Nodal lengths int N_a ds of the faces, by node (reference lengths: line2 1/2, 1/2; line3 1/6, 4/6,
    1/6 of the face)."""
    w = {}
    for f in faces:
        L = abs(xyz[f[-1], 0] - xyz[f[0], 0])
        for n, c in zip(f, [0.5, 0.5] if len(f) == 2 else [1 / 6, 4 / 6, 1 / 6]):
            w[n] = w.get(n, 0.0) + c * L
    return w


def check(name, value, expected, tol, relative=False):
    """|value - expected| <= tol (absolute) or <= tol*|expected| (relative)."""
    err = abs(value - expected)
    bound = tol * abs(expected) if relative else tol
    ok = bool(err <= bound) and np.isfinite(value)
    kind = "relative " if relative else ""
    print("%s: %.10g (expected %.10g, %stolerance %.3g) %s" % (name, value, expected, kind, tol, "PASS" if ok else "FAIL"))
    if not ok:
        _failed.append(name)
    return ok


def check_true(name, ok, detail=""):
    print("%s: %s %s" % (name, detail, "PASS" if ok else "FAIL"))
    if not ok:
        _failed.append(name)


def check_contact_jacobian_log(log):
    """The ||J - Jfd||/||J|| ratios of -snes_test_jacobian in a job log, step by step: every one below 1e-6
    in steps 1, 2, 3 (stick, slip, open), except the first evaluation of step 3, which starts exactly on
    the Coulomb yield surface (a kink where a finite-difference Jacobian means nothing)."""
    import re
    step, seen = 0, {}
    for line in open(log):
        m = re.match(r"step (\d+) \(", line)
        if m:
            step = int(m.group(1))
        m = re.search(r"\|\|J - Jfd\|\|_F/\|\|J\|\|_F = ([0-9.eE+-]+)", line)
        if m:
            seen.setdefault(step, []).append(float(m.group(1)))
    check_true("Jacobian comparisons in all three steps", sorted(seen) == [1, 2, 3], "%s" % {k: len(v) for k, v in seen.items()})
    for s, ratios in sorted(seen.items()):
        for k, x in enumerate(ratios):
            if s == 3 and k == 0:
                print("step 3 evaluation 1: %.3g (on the yield surface, not checked)" % x)
                continue
            check("step %d evaluation %d ||J - Jfd||/||J||" % (s, k + 1), x, 0.0, 1e-6)


def finish():
    if _failed:
        print("FAILED checks: %s" % ", ".join(_failed))
        sys.exit(1)
    print("all checks passed")
    sys.exit(0)


def slab_series(x, t, kappa, L=1.0, theta=100.0):
    """Slab 0 < x < L initially at 0, face x = 0 held at theta from t = 0, x = L insulated:
    theta [1 - sum_n 4/((2n+1) pi) sin((2n+1) pi x / 2L) exp(-(2n+1)^2 pi^2 kappa t / 4L^2)]."""
    s = 0.0
    for n in range(200):
        m = (2 * n + 1) * math.pi / (2 * L)
        s += 4.0 / ((2 * n + 1) * math.pi) * math.sin(m * x) * math.exp(-m * m * kappa * t)
    return theta * (1.0 - s)
