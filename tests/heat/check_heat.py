#!/usr/bin/python3
"""Checks of the heat-transfer decks (tests/heat/decks, written by make_decks.py).

bar       transient 1D conduction (alpha = k / (rho c) = 1, L = 1, T(0, t) = 1, T(x, 0) = 0, insulated at x = L): the
          Fourier series T = 1 - sum_n 4 / ((2n+1) pi) sin(lambda_n x) exp(-lambda_n^2 t), lambda_n = (2n+1) pi / 2,
          at t = 0.1 and t = 0.2 (frames 2 and 4) at every node; tolerance 5e-3 of the unit drop, which covers the
          mesh (h = 0.05, lumped capacity) and backward Euler (dt = 0.0025) errors together: measured 3.4e-3 at t = 0.1
          and 1.3e-3 at t = 0.2, backward Euler's first-order error (6.8e-3 and 2.6e-3 at dt = 0.005);
          the heat balance residual at most 1e-10 per increment, and the heat that entered (the reaction heat summed
          over the increments) = the heat stored, rho c A int T dx, within 1e-9 relative (backward Euler conserves heat).
endss     the bar of k(theta) = 1.5 + theta (a table 1.5 at 0, 2.5 at 1; c likewise) with T = 1 at x = 0 and a film
          (h = 0.5, sink 0) at x = L, transient with END=SS (rate 1e-4): the step must end before its period (50) with
          the steady state, whose flux q = -k dT/dx is one constant: with Kirchhoff's phi(T) = 1.5 T + T^2 / 2, linear in
          x, phi(1) - phi(T_L) = q L = h T_L L, so T_L = sqrt(8) - 2. Checks: the last frame before t = 50; T_L within
          1e-4 (the rate 1e-4 times the time constant left, and k's interpolation by the nodal temperatures; measured
          1.0e-5); the film heat out = the reaction heat in at the end within 1e-3 relative (the last increment's rate).
cylinder  steady radial conduction through a thick cylinder (CAX8 read as DCAX8; r1 = 1, r2 = 2, height H = 0.1, k = 3):
          T = 100 at r1, a film h = 5 to 20 at r2. The heat flow Q = 2 pi H (T1 - Ts) / (ln(r2/r1) / k + 1 / (h r2)) and
          T(r) = T1 - Q ln(r/r1) / (2 pi k H). Checks: every node within 1e-5 of the drop T1 - Ts (8 quadratic elements;
          measured 1.1e-6), the reaction heat and the film heat out both = Q (1e-5 relative; axisymmetric loads and
          reactions are totals around the axis), the balance residual (1e-10 of Q).
gap       two blocks (k = 50, unit height, unit area) across a clearance d = 0.01 with the gap conductance
          k(d) = 1000 (1 - d / 0.02) = 500, T = 0 and 1 on the outer faces, steady, no displacement (the contact
          geometry as the deck gives it): the interface is a film between the blocks, q = 1 / (2 / 50 + 1 / 500). Checks:
          the interface heat of the history, the heat in at the hot face (reaction) and HFLA at every secondary node
          against q (1e-9 relative); the balance residual (1e-10 of q).
gap_nodes the same with the upper block's bottom tilted, d = 0.01 + 0.01 x: at every secondary node (above its
          main-surface node at the same x) HFLA = k(d) (T_main - T_secondary), d from the deck's coordinates (1e-9 of
          the largest HFLA): the interface law node by node.
gap_off   the upper block moved off the lower one (x in [1.5, 2.5]): no contact, no interface heat (0), the upper
          block isothermal at its held 1 and the lower at 0 (1e-12), no heat in.
gap_radiation  the two DC3D8 blocks across the clearance 0.01 with *GAP RADIATION alone (eps 0.8, 0.8, view factor 1;
          kelvin), T = 300 and 600 held outside: q = C (T_b^4 - T_a^4), C = sigma / (1/0.8 + 1/0.8 - 1), with
          T_a = 300 + q / 50 and T_b = 600 - q / 50 (each block's conduction), solved here by bisection. Checks: the
          interface heat and the heat in against q (1e-8 relative: the Newton tolerance of the nonlinear solve).
deltmx    the bar of 10 DC3D8 with DELTMX=0.1 and automatic increments (initial and largest 0.05, a frame every
          increment): no free temperature changes by more than 0.1 (1e-4 relative) between two increments, the first
          increment was cut back (more than the 4 increments of 0.05), and the heat balance closes (1e-10).
same      the temperatures of this job equal those of another job (OTHER_OUTDIR OTHER_JOB): at every node and frame
          within 1e-8 of the unit drop (the two solves' tolerance).
usage: check_heat.py OUTDIR JOB CASE [OTHER_OUTDIR OTHER_JOB]
"""
import math
import sys

import numpy as np

sys.path.insert(0, sys.path[0] + "/../tools")
from tslcheck import Result, check, finish

r = Result(sys.argv[1], sys.argv[2])
case = sys.argv[3]
h = r.history


def fourier(x, t, terms=200):
    T = np.ones_like(x)
    for n in range(terms):
        lam = (2 * n + 1) * math.pi / 2
        T -= 4 / ((2 * n + 1) * math.pi) * np.sin(lam * x) * math.exp(-lam * lam * t)
    return T


if case == "bar":
    x = r.xyz[:, 0]
    for idx, t in ((1, 0.1), (3, 0.2)):
        nt = r.field("NT", idx)[:, 0]
        err = float(np.max(np.abs(nt - fourier(x, t))))
        check("bar: max |T - Fourier series| at t = %g" % t, err, 0.0, 5e-3)
    rate = np.abs(h["balance_residual"])
    check("bar: largest heat balance residual", float(np.max(rate)), 0.0, 1e-10)
    entered = float(np.sum(h["reaction_heat"] * h["dt"]))
    # the stored heat from the last frame: rho c times the integral of T over the bar (trapezoidal = exact for the
    # lumped capacity of the linear bricks: each node carries its share of the volume)
    nt = r.field("NT", -1)[:, 0]
    xs = np.unique(np.round(x, 12))
    Tx = np.array([np.mean(nt[np.abs(x - xv) < 1e-9]) for xv in xs])
    stored = 0.5 * 2.0 * 0.1 * 0.1 * float(np.sum(0.5 * (Tx[1:] + Tx[:-1]) * np.diff(xs)))
    check("bar: heat in over the step / heat stored", entered / stored, 1.0, 1e-9)
elif case == "endss":
    fr = r.frame(-1)
    check("endss: the step ended at its steady state before its period 50", float(fr.attrs["time"]) < 50, True, 0)
    x = r.xyz[:, 0]
    TL = float(np.mean(r.field("NT", -1)[:, 0][x > 1 - 1e-9]))
    check("endss: T at the film face (Kirchhoff's closed form)", TL, math.sqrt(8) - 2, 1e-4)
    check("endss: film heat out / reaction heat in, last increment", h["film_heat_out"][-1] / h["reaction_heat"][-1], 1.0, 1e-3)
elif case == "cylinder":
    k, hf, Ts, T1, r1, r2, H = 3.0, 5.0, 20.0, 100.0, 1.0, 2.0, 0.1
    Q = 2 * math.pi * H * (T1 - Ts) / (math.log(r2 / r1) / k + 1 / (hf * r2))
    x = r.xyz[:, 0]
    exact = T1 - Q * np.log(x / r1) / (2 * math.pi * k * H)
    check("cylinder: max |T - closed form| / (T1 - Ts)", float(np.max(np.abs(r.field("NT")[:, 0] - exact))) / (T1 - Ts), 0.0, 1e-5)
    check("cylinder: reaction heat / Q", h["reaction_heat"][-1] / Q, 1.0, 1e-5)
    check("cylinder: film heat out / Q", h["film_heat_out"][-1] / Q, 1.0, 1e-5)
    check("cylinder: balance residual / Q", abs(h["balance_residual"][-1]) / Q, 0.0, 1e-10)
elif case in ("gap", "gap_nodes", "gap_off"):
    x, y = r.xyz[:, 0], r.xyz[:, 1]
    nt, hfla, rfl = r.field("NT")[:, 0], r.field("HFLA")[:, 0], r.field("RFL")[:, 0]
    upper = y > 1 + 1e-9
    sec = upper & (y < 1.03)  # the upper block's bottom nodes
    kd = lambda d: 1000 * (1 - d / 0.02)
    if case == "gap":
        q = 1 / (2 / 50 + 1 / 500)
        check("gap: interface heat / q", -h["interface_heat"][-1] / q, 1.0, 1e-9)
        check("gap: heat in at the hot face / q", float(np.sum(rfl[upper & (y > 2)])) / q, 1.0, 1e-9)
        check("gap: largest |HFLA + q| / q over the secondary nodes", float(np.max(np.abs(hfla[sec] + q))) / q, 0.0, 1e-9)
        check("gap: balance residual / q", abs(h["balance_residual"][-1]) / q, 0.0, 1e-10)
    elif case == "gap_nodes":
        worst, scale = 0.0, float(np.max(np.abs(hfla[sec])))
        for i in np.where(sec)[0]:
            j = np.where((np.abs(y - 1) < 1e-9) & (np.abs(x - x[i]) < 1e-9) & (np.abs(r.xyz[:, 2] - r.xyz[i, 2]) < 1e-9))[0][0]
            worst = max(worst, abs(hfla[i] - kd(y[i] - 1) * (nt[j] - nt[i])))
        check("gap_nodes: largest |HFLA - k(d) (T_main - T_secondary)| / largest HFLA, node by node", worst / scale, 0.0, 1e-9)
        check("gap_nodes: the clearance varies (HFLA at the ends differ)", float(np.ptp(hfla[sec])) > 0.1 * scale, True, 0)
    else:
        check("gap_off: interface heat", abs(h["interface_heat"][-1]), 0.0, 0)
        check("gap_off: the upper block isothermal at 1", float(np.max(np.abs(nt[upper] - 1))), 0.0, 1e-12)
        check("gap_off: the lower block at 0", float(np.max(np.abs(nt[~upper]))), 0.0, 1e-12)
        check("gap_off: heat in", float(np.max(np.abs(rfl))), 0.0, 1e-12)
elif case == "gap_radiation":
    C = 5.67e-8 / (1 / 0.8 + 1 / 0.8 - 1)
    lo, hi = 0.0, 300 * 50 / 2
    for _ in range(200):
        q = 0.5 * (lo + hi)
        lo, hi = (q, hi) if C * ((600 - q / 50) ** 4 - (300 + q / 50) ** 4) > q else (lo, q)
    y = r.xyz[:, 1]
    check("gap_radiation: interface heat / q", -h["interface_heat"][-1] / q, 1.0, 1e-8)
    check("gap_radiation: heat in at the hot face / q", float(np.sum(r.field("RFL")[:, 0][y > 2])) / q, 1.0, 1e-8)
elif case == "deltmx":
    free = r.xyz[:, 0] > 1e-9
    worst, prev = 0.0, np.zeros(len(r.xyz))
    for i in range(len(r.frames)):
        nt = r.field("NT", i)[:, 0]
        worst = max(worst, float(np.max(np.abs(nt - prev)[free])))
        prev = nt
    check("deltmx: largest change of a free temperature in an increment (DELTMX 0.1)", worst <= 0.1 * 1.0001, True, 0)
    check("deltmx: increments taken (more than the 4 of the largest increment)", len(h["dt"]) > 4, True, 0)
    check("deltmx: largest heat balance residual", float(np.max(np.abs(h["balance_residual"]))), 0.0, 1e-10)
elif case == "same":
    o = Result(sys.argv[4], sys.argv[5])
    check("same: frames", len(r.frames), len(o.frames), 0)
    worst = 0.0
    for i in range(len(r.frames)):
        worst = max(worst, float(np.max(np.abs(r.field("NT", i) - o.field("NT", i)))))
    check("same: max |NT - NT of %s| over every frame" % sys.argv[5], worst, 0.0, 1e-8)
else:
    sys.exit("unknown case " + case)
finish()
