#!/usr/bin/python3
"""Checks of the tie decks (tests/tie/decks, written by make_decks.py).

patch   two blocks meshed differently across x = 1 and tied there (docs/design.md "Ties": dual-mortar weights), every
        outer boundary node given the linear fields of make_decks.py, u = A x and theta = t0 + g . x: the exact
        solution is those fields everywhere, with the uniform stress sigma = C : sym(A) (plane strain, E = 2e5,
        nu = 0.3, no expansion; axisymmetric (CAX4T): u_r = a r, u_z = d z, theta = t0 + g z, which equilibrium
        and conduction about the axis allow with a uniform stress; C3D4T: uniaxial stress along x, theta = t0 + g x, the
        secondary nodes on the outer faces, which carry no traction then, left to the tie). Checks: U at every node against A x within 1e-8 of max |u|, NT within 1e-8 of the
        temperature's range, every integration point's S against C : sym(A) within 1e-8 of max |sigma|, and the
        heat balance of the increment within 1e-8 of the heat crossing the body.
bar     the explicit bar cut at x = 1 and tied (OTHER names the untied bar's output directory): U and NT at every
        frame and node equal the untied bar's (matched by position; the tied bar's second node at x = 1 has the
        same position) within 1e-9 of the fields' largest value: the tie moves the secondary nodes' mass, heat
        capacity and forces to the main nodes and recovers their motion, which is the untied bar's lumped system.
fall    the blocks of the CPE4T patch (4 elements tied to 3) falling under gravity in an explicit step: u = g t^2 / 2 at
        every node within 1e-9 (the secondary mass moves with its force; masses alone or forces alone would not do), and
        heated by a uniform body flux: theta = 20 + q t / (rho c) within 1e-9 of the rise (the capacity with the heat).
heat    patch_heat_cpe4t (a *HEAT TRANSFER step, the temperature alone): NT against the linear field within 1e-8 of its
        range and the heat balance, as patch
energy  the explicit bar's energy balance: |ETOTAL| at most 1e-8 of the largest work (an explicit balance is exact to
        round-off).
usage: check_tie.py OUTDIR JOB CASE [OTHER_OUTDIR OTHER_JOB]
"""
import sys

import numpy as np

sys.path.insert(0, sys.path[0] + "/../tools")
from tslcheck import Result, check, check_true, finish

UX = (1e-3, 0.5e-3, -0.2e-3)
UY = (0.3e-3, -0.7e-3, 0.4e-3)
UZ = (-0.1e-3, 0.2e-3, 0.6e-3)
TH = (20.0, 10.0, 5.0, -3.0)
UXA, UYA, THA = (1e-3, 0.0), (0.0, -0.7e-3), (20.0, 0.0, 5.0)
UNI = ((1e-3, 0.0, 0.0), (0.0, -0.3e-3, 0.0), (0.0, 0.0, -0.3e-3))
THU = (20.0, 10.0, 0.0, 0.0)
E, NU = 200000.0, 0.3

r = Result(sys.argv[1], sys.argv[2])
case = sys.argv[3]


def patch(thermal_only=False):
    x = r.xyz
    dim = 3 if np.ptp(x[:, 2]) > 0 else 2
    axi = "cax" in sys.argv[2]  # u_r = a r: the hoop strain u_r / r = a is uniform too
    uni = "c3d4t" in sys.argv[2]  # uniaxial stress along x: the secondary nodes on the outer faces are left to the tie
    A = np.array([UXA, UYA] if axi else UNI if uni else [UX[:dim], UY[:dim], UZ[:dim]][:dim])
    T = THA if axi else THU if uni else TH
    u_exact = x[:, :dim] @ A.T
    t_exact = T[0] + x[:, :dim] @ np.array(T[1:1 + dim])
    nt = r.field("NT").reshape(-1)
    check("patch NT max error / range", np.abs(nt - t_exact).max() / np.ptp(t_exact), 0, 1e-8)
    if thermal_only:
        through = np.abs(r.field("RFL")).sum() / 2
        check("patch heat balance residual / heat through", abs(r.history["balance_residual"][-1]) / max(through, 1e-300), 0, 1e-8)
        return
    u = r.field("U")[:, :dim]
    scale_u = np.abs(u_exact).max()
    check("patch U max error / max |u|", np.abs(u - u_exact).max() / scale_u, 0, 1e-8)
    eps = 0.5 * (A + A.T)
    lam, mu = E * NU / ((1 + NU) * (1 - 2 * NU)), E / (2 * (1 + NU))
    e3 = np.zeros((3, 3))
    e3[:dim, :dim] = eps
    if axi:
        e3[2, 2] = UXA[0]
    sig = lam * np.trace(e3) * np.eye(3) + 2 * mu * e3
    voigt = np.array([sig[0, 0], sig[1, 1], sig[2, 2], sig[0, 1], sig[0, 2], sig[1, 2]])
    S = r.field("S")
    S = S.reshape(-1, S.shape[-1])
    ncomp = S.shape[1]
    check("patch S max error / max |sigma|", np.abs(S - voigt[:ncomp]).max() / np.abs(voigt).max(), 0, 1e-8)
    # the heat the prescribed temperatures bring in and take out: each half of k |g| times the area through which it
    # crosses; their sum, the balance residual, is round-off
    through = np.abs(r.field("RFL")).sum() / 2 if "RFL" in r.frame() else abs(r.history["reaction_heat"][-1])
    check("patch heat balance residual / heat through", abs(r.history["balance_residual"][-1]) / max(through, 1e-300), 0, 1e-8)


def energy():
    h = r.history
    scale = max(np.abs(h["ALLWK"]).max(), np.abs(h["ALLIE"] + h["ALLKE"]).max())
    check("energy balance |ETOTAL| / max work", np.abs(h["ETOTAL"]).max() / scale, 0, 1e-8)


def fall():
    """Free fall under GRAV g = 1e4 along (1, -2) / sqrt(5): u = g t^2 / 2 at every node and frame; the body flux
    q = 390 on rho c = 3.9e-3: theta = 20 + 1e5 t."""
    energy()
    n = np.array([1.0, -2.0]) / np.sqrt(5.0)
    worst, scale = 0.0, 0.0
    for f in range(len(r.frames)):
        t = float(r.frame(f).attrs["time"])
        exact = 0.5 * 1e4 * t * t * n
        u = r.field("U", f)[:, :2]
        worst = max(worst, np.abs(u - exact).max())
        scale = max(scale, np.abs(exact).max())
    check_true("fall frames", len(r.frames) >= 2, "%d" % len(r.frames))
    check("fall U - g t^2 / 2, max over frames and nodes / max |u|", worst / scale, 0, 1e-9)
    worst = 0.0
    for f in range(len(r.frames)):
        t = float(r.frame(f).attrs["time"])
        worst = max(worst, np.abs(r.field("NT", f) - (20 + 1e5 * t)).max())
    check("fall NT - (20 + q t / (rho c)), max over frames and nodes / rise", worst / (1e5 * 1e-5), 0, 1e-9)


def bar():
    energy()
    o = Result(sys.argv[4], sys.argv[5])
    check_true("bar frames", len(r.frames) == len(o.frames), "%d and %d" % (len(r.frames), len(o.frames)))
    # nodes by position: the tied bar has two nodes at each point of x = 1, both must follow the untied one
    key = lambda p: (round(p[0], 9), round(p[1], 9))
    where = {key(p): i for i, p in enumerate(o.xyz)}
    idx = np.array([where[key(p)] for p in r.xyz])
    for name in ("U", "NT"):
        worst, scale = 0.0, 0.0
        for f in range(len(o.frames)):
            a, b = r.field(name, f), o.field(name, f)[idx]
            worst = max(worst, np.abs(a - b).max())
            scale = max(scale, np.abs(b).max())
        check("bar %s tied - untied, max over frames and nodes / max |%s|" % (name, name), worst / scale, 0, 1e-9)


{"patch": patch, "heat": lambda: patch(True), "bar": bar, "energy": energy, "fall": fall}[case]()
finish()
