#!/usr/bin/python3
"""Checks of the finite-strain decks (make_decks.py; St Venant-Kirchhoff, docs/elements.md "Finite strain"):

turn       at the end of each of the 8 steps (turned by 45 k degrees, heated by alpha dT = 0.2): every node at x = 1.2 Q X
           (1e-8 of the largest displacement: the Newton tolerance), no stress (1e-8 of E alpha dT), the logarithmic
           strain ln 1.2 in every normal direction and no shear (1e-9), the temperature 220; the ring: u = 0.2 X and the
           twist phi = 45 k degrees at every node
homog      simple shear to gamma = 1: the Cauchy stress F S F^T and LE from the eigenvalues (3 +- sqrt 5) / 2 of F F^T
           (1e-10); the body at F0 and at Q F0: S' = Q S Q^T and LE' = Q LE Q^T (1e-10)
compress   the same at 0.7 of its length (a cutback after an element turned inside out, read from the run's log)
uniaxial   the bar at twice its length: sigma_11 = lambda S_11 / lt^2 with S_11 = E (lambda^2 - 1) / 2 and the lateral
           stretch lt = sqrt(1 - nu (lambda^2 - 1)) in every element, the other components 0 (1e-8 of sigma_11), LE = (ln 2,
           ln lt, ln lt), the free lateral faces at lt - 1, the pulled end's reaction lambda S_11 A0 (1e-8)
pressure   the block pressed by the follower pressure p: Cauchy stress -p along the load in every element, the stresses
           across it 0 (plane strain: sigma_33 not) (1e-8 of p)
spin_disc  the disc turned once under the pressed pad (implicit, explicit): frictional dissipation mu N x 2 pi R (N from
           CPRESS over the pad face, 0.5 %), the heat absorbed, the hub torque (implicit), the disc away from the pad below
           5 % of the contact pressure, the stress field stationary in space (1e-8 implicit, 3e-2 explicit: its waves)
spin       the explicit block spinning through a quarter turn: at Q X (1e-3 of the displacement), its kinetic energy kept
           (1e-3), ETOTAL at round-off, stresses of the centrifugal size (below 1e-4 of E)
usage: check.py OUTDIR JOB turn|homog|uniaxial|pressure|spin [AXIS: the load's direction, 0 x, 1 y (the ring's z)]"""
import math
import sys

import numpy as np

sys.path.insert(0, sys.path[0] + "/../tools")
from tslcheck import Result, check, check_true, finish

outdir, job, case = sys.argv[1:4]
axis = int(sys.argv[4]) if len(sys.argv) > 4 else 0
r = Result(outdir, job)
E, NU, ALPHA, DT, THETA0 = 2.0e5, 0.3, 1.0e-3, 200.0, 20.0
AX = np.array([1.0, 2.0, 3.0]) / math.sqrt(14.0)
VI, VJ = [0, 1, 2, 0, 0, 1], [0, 1, 2, 1, 2, 2]


def rotation(angle, n):
    k = np.array([[0, -n[2], n[1]], [n[2], 0, -n[0]], [-n[1], n[0], 0]])
    return math.cos(angle) * np.eye(3) + math.sin(angle) * k + (1 - math.cos(angle)) * np.outer(n, n)


def tensor(v, shear_half=False):
    t = np.zeros((3, 3))
    for k in range(6):
        t[VI[k], VJ[k]] = t[VJ[k], VI[k]] = v[k] * (0.5 if shear_half and k >= 3 else 1.0)
    return t


def voigt(t, engineering=False):
    return np.array([t[VI[k], VJ[k]] * (2.0 if engineering and k >= 3 else 1.0) for k in range(6)])


X = r.xyz
if case == "turn":
    ring = "cgax" in job
    dim = 3 if "c3d" in job else 2
    s = 1 + ALPHA * DT
    for k in range(1, 9):
        i = r.frame_of_step(k)
        U, S, LE, NT = r.field("U", i), r.field("S", i), r.field("E", i), r.field("NT", i)
        if ring:
            expect = np.column_stack([(s - 1) * X[:, 0], (s - 1) * X[:, 1], np.full(len(X), math.radians(45 * k))])
        else:
            Q = rotation(math.radians(45 * k), AX if dim == 3 else np.array([0.0, 0.0, 1.0]))
            expect = s * X @ Q.T - X
            if dim == 2:
                expect[:, 2] = 0
        scale = np.abs(expect).max()
        check("step %d (turned by %d degrees): max|U - (1.2 Q - I) X| / max|U|" % (k, 45 * k), np.abs(U - expect).max() / scale, 0.0, 1e-8)
        check("step %d: max|S| / (E alpha dT)" % k, np.abs(S).max() / (E * ALPHA * DT), 0.0, 1e-8)
        le = np.zeros(6)
        le[:3] = math.log(s)
        check("step %d: max|LE - ln 1.2 (normal), 0 (shear)|" % k, np.abs(LE - le).max(), 0.0, 1e-9)
        check("step %d: temperature" % k, np.abs(NT - (THETA0 + DT)).max(), 0.0, 1e-9)
elif case == "homog":
    lam, mu = E * NU / ((1 + NU) * (1 - 2 * NU)), E / (2 * (1 + NU))
    F = np.array([[1.0, 1, 0], [0, 1, 0], [0, 0, 1]])
    Eg = 0.5 * (F.T @ F - np.eye(3))
    sig = F @ (lam * np.trace(Eg) * np.eye(3) + 2 * mu * Eg) @ F.T
    w, v = np.linalg.eigh(F @ F.T)
    le = v @ np.diag(0.5 * np.log(w)) @ v.T
    i = r.frame_of_step(1)
    S, LE = r.field("S", i)[0], r.field("E", i)[0]
    check("simple shear to 1: max|S - F S(E) F^T| / E", np.abs(S - voigt(sig)).max() / E, 0.0, 1e-10)
    check("simple shear to 1: max|LE - ln V| (engineering shear)", np.abs(LE - voigt(le, True)).max(), 0.0, 1e-10)
    check("simple shear to 1: S12 = mu gamma (1 + ...) > 0", float(S[3] > 0), 1.0, 0)
    Q = rotation(math.pi / 2, AX)
    S2, LE2 = r.field("S", r.frame_of_step(2))[0], r.field("E", r.frame_of_step(2))[0]
    S3, LE3 = r.field("S", r.frame_of_step(3))[0], r.field("E", r.frame_of_step(3))[0]
    check("turned by 90 degrees: max|S' - Q S Q^T| / max|S|", np.abs(S3 - voigt(Q @ tensor(S2) @ Q.T)).max() / np.abs(S2).max(), 0.0, 1e-10)
    check("turned by 90 degrees: max|LE' - Q LE Q^T|", np.abs(LE3 - voigt(Q @ tensor(LE2, True) @ Q.T, True)).max(), 0.0, 1e-10)
    check("LE on request: the E dataset's values", np.abs(r.field("LE", r.frame_of_step(3)) - r.field("E", r.frame_of_step(3))).max(), 0.0, 0.0)
elif case in ("uniaxial", "compress"):
    l = 2.0 if case == "uniaxial" else 0.7
    lt = math.sqrt(1 - NU * (l * l - 1))
    S11 = E * (l * l - 1) / 2
    S, LE, U, RF = r.field("S"), r.field("E"), r.field("U"), r.field("RF")
    check("Cauchy S11 = lambda S11 / lt^2 (worst element, relative)", np.abs(S[:, 0] / (l * S11 / lt ** 2) - 1).max(), 0.0, 1e-8)
    check("S22, S33, shear / S11", np.abs(S[:, 1:]).max() / abs(l * S11 / lt ** 2), 0.0, 1e-8)
    check("LE11 = ln lambda", np.abs(LE[:, 0] - math.log(l)).max(), 0.0, 1e-9)
    nz = 3 if "c3d" in job else 2
    check("LE22 = LE33 = ln lt", np.abs(LE[:, 1:nz] - math.log(lt)).max(), 0.0, 1e-9)
    side = np.abs(X[:, 1] - 1.0) < 1e-12
    check("free side y = 1 at lt - 1", np.abs(U[side, 1] - (lt - 1)).max(), 0.0, 1e-9)
    end = np.abs(X[:, 0] - 2.0) < 1e-12
    check("pulled end's reaction = lambda S11 A0 (relative)", RF[end, 0].sum() / (l * S11) - 1, 0.0, 1e-8)
    if case == "compress":
        log = open(outdir + ".log").read()
        check_true("the first iterate turned an element inside out and the increment was cut back",
                   "turned inside out (det F <= 0) at a Newton iterate" in log and "cutback" in log)
elif case == "pressure":
    p = 2.0e4
    S = r.field("S")
    plane_strain = "cpe" in job
    check("Cauchy stress along the load = -p (worst element, relative)", np.abs(S[:, axis] / -p - 1).max(), 0.0, 1e-8)
    others = [k for k in range(6) if k != axis and not (plane_strain and k == 2)]
    check("the other stress components / p", np.abs(S[:, others]).max() / p, 0.0, 1e-8)
    U = r.field("U")
    check_true("the block shortened along the load", U[:, axis].min() < -0.05 * X[:, axis].max() * p / E)
elif case == "spin":
    # a quarter turn at omega (make_decks.py OMEGA): x = Q X, the kinetic energy kept (the centrifugal stretch takes
    # 3e-5 of it, the bulk viscosity of its breathing 3e-4), ETOTAL at round-off, stresses of the order of the
    # centrifugal rho omega^2 L^2 (small strain moves the block along a straight line instead: 0.79 of the displacement)
    t = math.pi / 2
    Q = rotation(t, np.array([0.0, 0.0, 1.0]))
    expect = X @ Q.T - X
    if "cpe" in job:
        expect[:, 2] = 0
    U, S = r.field("U"), r.field("S")
    check("after a quarter turn: max|U - (Q - I) X| / max|U|", np.abs(U - expect).max() / np.abs(expect).max(), 0.0, 1e-3)
    ke, et = r.history["ALLKE"], r.history["ETOTAL"]
    check("kinetic energy kept: |ALLKE_end / ALLKE_0 - 1|", abs(ke[-1] / ke[0] - 1), 0.0, 1e-3)
    check("ETOTAL / ALLKE_0 (every row)", np.abs(et).max() / ke[0], 0.0, 1e-10)
    check("max|S| / E (the centrifugal stress, 25 x 0.25 / 2e5 = 3e-5)", np.abs(S).max() / E, 0.0, 1e-4)
elif case == "spin_disc":
    # the disc turned once under the pressed pad (make_decks.py spin_disc): its constants
    RO, HALF, MU_F = 1.0, math.radians(4.0), 0.1
    NT = int((r.node_ids <= 10000).sum()) // 5  # the disc's segments: 5 rings of nodes
    explicit = "explicit" in job
    eids, conn, h = r.h5["/mesh/element_ids"][...], r.elements(), r.history
    disc = np.where(eids < 5001)[0]
    pad_in = np.where((r.node_ids >= 10001) & (r.node_ids <= 10017))[0]
    L = np.zeros(len(pad_in))  # each pad node's share of the pad face (the reference lengths contact works on)
    for k in range(len(pad_in) - 1):
        d = np.linalg.norm(X[pad_in[k + 1], :2] - X[pad_in[k], :2])
        L[k:k + 2] += d / 2
    spin = [i for i in range(len(r.frames)) if int(r.frame(i).attrs["step"]) == 2]
    N = np.array([(r.field("CPRESS", i)[pad_in, 0] * L).sum() for i in spin])
    p_mean = N.mean() / (2 * HALF * RO)
    print("normal force N = sum CPRESS x length over the pad face: %.6g (spread over the turn %.2g), mean pressure %.6g" %
          (N.mean(), (N.max() - N.min()) / N.mean(), p_mean))
    rows = h["step"] == 2
    start = h["friction_dissipation_total"][h["step"] == 1][-1]
    dis = h["friction_dissipation_total"][rows][-1] - start
    check("frictional dissipation of the revolution = mu N x 2 pi R (sliding distance)", dis, MU_F * N.mean() * 2 * math.pi * RO, 5e-3, relative=True)
    check("frictional heat absorbed = dissipation (eta = 1)", h["friction_heat_total"][rows][-1] - h["friction_heat_total"][h["step"] == 1][-1],
          dis, 1e-9, relative=True)
    if not explicit:
        # the hub's torque about the axis (current positions) / R: the friction force mu N (the facets' tilted normals
        # add a moment that comes back with every facet: 0.4 %)
        hub = np.where(r.node_ids <= NT)[0]
        for i in spin[1::2]:
            x, RF = X[hub, :2] + r.field("U", i)[hub, :2], r.field("RF", i)[hub]
            check("frame %d: hub torque / R = mu N" % i, (x[:, 0] * RF[:, 1] - x[:, 1] * RF[:, 0]).sum() / RO, MU_F * N[spin.index(i)], 1e-2, relative=True)

    def mises(S):
        d = S[:, :3] - S[:, :3].mean(1)[:, None]
        return np.sqrt(1.5 * ((d**2).sum(1) + 2 * (S[:, 3:]**2).sum(1)))

    # away from the pad (the half of the disc below the axis, where it is at that frame) the disc carries only what
    # holds the pad's load and the torque: a few % of the contact pressure (small strain: a rigid turn by 90 degrees
    # alone would strain it by 1, a stress of the order of E, here 3e3 (implicit) and 3e2 (explicit) x p)
    worst = 0.0
    for i in spin:
        x = X[:, :2] + r.field("U", i)[:, :2]
        below = np.array([x[conn[e], 1].mean() < 0 for e in disc])
        worst = max(worst, mises(r.field("S", i)[disc][below]).max())
    check("largest Mises stress in the half away from the pad, any frame / mean contact pressure", worst / p_mean, 0.0, 5e-2)
    # the state is stationary in space: the stress where an element is at one frame is the stress of the element that is
    # there half a turn later (the mesh maps onto itself: frames 45 degrees apart, NT segments)
    S_end, S_half = r.field("S", spin[-1])[disc], r.field("S", spin[-5])[disc]
    j, layer = (eids[disc] - 1) % NT, (eids[disc] - 1) // NT
    index = {(a, b): n for n, (a, b) in enumerate(zip(j, layer))}
    there = np.array([index[((a + NT // 2) % NT, b)] for a, b in zip(j, layer)])
    peak = max(np.abs(r.field("S", i)[disc]).max() for i in spin)
    check("half a turn apart: the stress at the same place / largest stress", np.abs(S_end - S_half[there]).max() / peak, 0.0, 3e-2 if explicit else 1e-8)
else:
    sys.exit("unknown case " + case)
finish()
