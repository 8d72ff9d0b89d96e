#!/usr/bin/python3
"""Checks of the *DLOAD body-force decks (tests/dload/decks, written by make_decks.py): steel, E = 2e11,
rho = 7800, nu = 0.

column AXIS VOLUME  a column of height L = 1 along axis AXIS (1-based) under its own weight (g = 9.81), held
                    at its base in that direction only: the reactions there sum to the weight rho g V (1e-10),
                    and with nu = 0 the stress is uniaxial, sigma = -rho g (L - s), so the nodal displacements
                    are the exact u(s) = -(rho g / E) (L s - s^2 / 2) (nodally exact for linear elements under
                    consistent loads), the end's -rho g L^2 / (2 E); step 2's *DLOAD, OP=NEW removes the weight
                    and the column springs back to zero
weight AXIS VOLUME [H]  the reactions sum to the weight rho g V (1e-10), and with H the nodes at the largest
                    coordinate H move by -rho g H^2 / (2 E) (a plate lying on its bottom face: the continuum
                    shells' thickness modulus 2 G is E when nu = 0; one element through the thickness is nodally exact)
disc A B            an annular disc a < r < b spinning about its axis (CAX4T, omega^2 = 1e4): with nu = 0 the
                    plane stress disc (Timoshenko and Goodier, "Rotating disks") is the exact solution,
                    sigma_theta = A - B / r^2 - rho omega^2 r^2 / 8 with A = 3 rho omega^2 (a^2 + b^2) / 8,
                    B = -3 rho omega^2 a^2 b^2 / 8, u_r = r sigma_theta / E, at both radii to the mesh's error
quarter A B T       the same disc as a quarter plate (CPS4T, thickness T, symmetry on x = 0 and y = 0): the
                    reactions on each symmetry edge balance the centrifugal force of the meshed area, rho omega^2
                    T int x dA (and int y dA) of the straight-sided elements (1e-10), and u_r at r = b as above
freefall AXIS       an unsupported block in an explicit step falls along AXIS as u = -g t^2 / 2 (central
                    differences integrate a constant acceleration exactly)
usage: check_dload.py OUTDIR JOB CASE ARGS...
"""
import math
import sys

import numpy as np

sys.path.insert(0, sys.path[0] + "/../tools")
from tslcheck import Result, check, finish

E, RHO, G, W2 = 2e11, 7800.0, 9.81, 1e4
r = Result(sys.argv[1], sys.argv[2])
case, args = sys.argv[3], sys.argv[4:]


def disc_u(a, b, x):
    k = 3 * RHO * W2 / 8
    A, B = k * (a * a + b * b), -k * a * a * b * b
    return x * (A - B / (x * x) - RHO * W2 * x * x / 8) / E


if case == "column":
    ax, vol = int(args[0]) - 1, float(args[1])
    f1 = r.frame_of_step(1)
    U, RF = r.field("U", f1), r.field("RF", f1)
    s = r.xyz[:, ax]
    base = np.abs(s) < 1e-12
    check("reaction at the base = weight rho g V", RF[base, ax].sum(), RHO * G * vol, 1e-10, relative=True)
    end = -RHO * G / (2 * E)
    top = np.abs(s - 1) < 1e-12
    check("end displacement (worst top node) = -rho g L^2 / (2 E)", max(U[top, ax], key=lambda v: abs(v - end)), end, 1e-8, relative=True)
    exact = -(RHO * G / E) * (s - s * s / 2)
    check("worst nodal displacement error / end displacement", np.abs(U[:, ax] - exact).max() / abs(end), 0.0, 1e-8)
    lateral = [i for i in range(U.shape[1]) if i != ax]
    check("worst lateral displacement / end displacement (nu = 0)", np.abs(U[:, lateral]).max() / abs(end), 0.0, 1e-8)
    U2 = r.field("U")
    check("after *DLOAD, OP=NEW: worst displacement / end displacement", np.abs(U2).max() / abs(end), 0.0, 1e-8)
elif case == "weight":
    ax, vol = int(args[0]) - 1, float(args[1])
    RF = r.field("RF")
    check("reactions = weight rho g V", RF[:, ax].sum(), RHO * G * vol, 1e-10, relative=True)
    if len(args) < 3:
        finish()
    H = float(args[2])
    top, end, U = np.abs(r.xyz[:, ax] - H) < 1e-12, -RHO * G * H * H / (2 * E), r.field("U")
    check("top displacement (worst node) = -rho g H^2 / (2 E)", max(U[top, ax], key=lambda v: abs(v - end)), end, 1e-8, relative=True)
elif case == "disc":
    a, b = float(args[0]), float(args[1])
    U = r.field("U")
    for name, x in (("inner", a), ("outer", b)):
        at = np.abs(r.xyz[:, 0] - x) < 1e-12
        exact = disc_u(a, b, x)
        check("u_r at the %s radius (worst node) against the rotating disc" % name, max(U[at, 0], key=lambda v: abs(v - exact)), exact, 2e-4,
              relative=True)
    check("u_z (worst node; nu = 0)", np.abs(U[:, 1]).max() / disc_u(a, b, b), 0.0, 1e-8)
elif case == "quarter":
    a, b, t = float(args[0]), float(args[1]), float(args[2])
    U, RF = r.field("U"), r.field("RF")
    mx = my = 0.0
    for el in r.elements():  # first moments of the straight-sided quadrilaterals (the polygon formula)
        p = r.xyz[el, :2]
        for i in range(len(el)):
            (x0, y0), (x1, y1) = p[i], p[(i + 1) % len(el)]
            c = x0 * y1 - x1 * y0
            mx += c * (x0 + x1) / 6
            my += c * (y0 + y1) / 6
    xedge, yedge = np.abs(r.xyz[:, 1]) < 1e-12, np.abs(r.xyz[:, 0]) < 1e-12
    check("reaction on y = 0 = -rho omega^2 t int y dA", RF[xedge, 1].sum(), -RHO * W2 * t * my, 1e-10, relative=True)
    check("reaction on x = 0 = -rho omega^2 t int x dA", RF[yedge, 0].sum(), -RHO * W2 * t * mx, 1e-10, relative=True)
    rad = np.hypot(r.xyz[:, 0], r.xyz[:, 1])
    outer = np.abs(rad - b) < 1e-9
    ur = (U[:, 0] * r.xyz[:, 0] + U[:, 1] * r.xyz[:, 1]) / rad
    exact = disc_u(a, b, b)
    check("u_r at the outer radius (worst node) against the rotating disc", max(ur[outer], key=lambda v: abs(v - exact)), exact, 2e-3, relative=True)
elif case == "freefall":
    ax, worst, last = int(args[0]) - 1, 0.0, 0.0
    for k in range(len(r.frames)):
        fr = r.frame(k)
        t = float(fr.attrs["time"])
        U = fr["U"][...]
        exact = -G * t * t / 2
        others = [i for i in range(U.shape[1]) if i != ax]
        worst = max(worst, np.abs(U[:, ax] - exact).max() / (G * 2e-4**2 / 2), np.abs(U[:, others]).max())
        last = t
    check("frames up to the step's end", last, 2e-4, 1e-12, relative=True)
    check("worst |u + g t^2 / 2| / (g T^2 / 2), all frames and nodes", worst, 0.0, 1e-10)
else:
    sys.exit("unknown case " + case)
finish()
