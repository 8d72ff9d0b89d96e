#!/usr/bin/python3
"""Checks of the radiation decks (tests/radiate/decks, written by make_decks.py).

plate     a thin plate (rho c V = 24300 J/K, top face A = 1 m^2, eps = 0.8, Celsius with absolute zero -273.15) at
          T0 = 1000 K radiating to Ta = 300 K. With k = 1e6 it stays isothermal (the top face's radiation, 4.2e4 W,
          crosses the 0.01 of thickness with a drop of q t / k = 4e-4 K), so it is the lumped body of
          rho c V dT/dt = -sigma eps A (T^4 - Ta^4), whose closed form is
              t(T) = K [F(T0) - F(T)],  F(T) = [ln((T - Ta) / (T + Ta)) - 2 atan(T / Ta)] / (4 Ta^3),  K = rho c V / (sigma eps A).
          Checks, at every increment (the history's radiation_heat_out gives the face temperature,
          T = (q / (sigma eps A) + Ta^4)^(1/4), and the frames' NT the temperature of every node):
          all temperatures against the drop over the step, T0 - T_end = 383 K:
          - the plate is isothermal: max - min of NT at most 1e-5 of the drop;
          - thermoslide = backward Euler on the lumped equation, T_{n+1} + dt/K (T_{n+1}^4 - Ta^4) = T_n: at most 1e-6
            of the drop (what is left is the radiating face's offset from the plate's mean, q t / (3 k) = 1.4e-4 K at
            the start, and the Newton tolerance);
          - thermoslide = the closed form within 2 % of the drop: backward Euler's own first-order error, which the
            recurrence above shows as 1.72 % at dt = 20 s (0.87 % at 10 s, 0.44 % at 5 s);
          - the heat balance: radiated = - stored heat rate (1e-6 of the radiated heat: the Newton tolerance; measured
            4e-11) and the
            heat radiated over the step, sum of q dt, = rho c V (T0 - T_end) (1e-8: backward Euler conserves heat);
plate_explicit  the same cooling in an explicit step (rho c V = 2.43, A = 1, t = 0.001, k = 50: Biot number
          4 sigma eps T^3 t / k = 3.6e-3): forward Euler with the stable increment (2.2e-5 s, 1/600 of the initial
          time constant rho c V / (4 sigma eps A T0^3)), and the plate's through-thickness gradient (the top
          radiates from q t / (3 k) = 0.28 K below the mean at the start), each slowing or speeding the cooling by
          about 1e-3 of the drop (measured together: 5.6e-4). Checks: the closed form at every history row within
          2e-3 of the drop, the balance residual at most 1e-10 of the radiated heat (the explicit balance is exact
          to round-off), and stored heat rate = - radiated within the rates' change over one increment (the row's
          rates are the next state's: 4 dT / T = 1.6e-3 at the start; 3e-3).
steady    a bar of length L = 2 (k = 20) heated by q = 5000 at x = 0 and radiating at x = L to Ta (kelvin): the
          steady temperature is linear, theta(L) = (q / (sigma eps) + Ta^4)^(1/4), theta(0) = theta(L) + q L / k
          (exact for CPE8T, and the radiating face is isothermal); step 1 Ta = 300, eps = 0.6; step 2 under the
          amplitudes at the step's end: Ta = 1.5 x 300, eps = 0.5 x 0.6; step 3 (OP=NEW) Ta = 500, eps = 1. Checks:
          theta at both ends (1e-9 relative), radiated = flux in = 2500 (1e-8), balance residual (1e-8 of it).
usage: check_radiate.py OUTDIR JOB CASE
"""
import math
import sys

import numpy as np

sys.path.insert(0, sys.path[0] + "/../tools")
from tslcheck import Result, check, finish

SIGMA = 5.670374419e-8
r = Result(sys.argv[1], sys.argv[2])
case = sys.argv[3]
h = r.history


def closed_form(K, Ta, T0, t):
    """T(t) of rho c V dT/dt = -sigma eps A (T^4 - Ta^4), K = rho c V / (sigma eps A), by bisection on t(T)."""
    F = lambda T: (math.log((T - Ta) / (T + Ta)) - 2 * math.atan(T / Ta)) / (4 * Ta ** 3)
    lo, hi = Ta * (1 + 1e-12), T0
    for _ in range(200):
        m = 0.5 * (lo + hi)
        lo, hi = (lo, m) if K * (F(T0) - F(m)) < t else (m, hi)  # t(T) decreases with T
    return 0.5 * (lo + hi)


def plate(explicit):
    zero, eps, A, Ta, T0 = -273.15, 0.8, 1.0, 300.0, 1000.0
    rcv = 2.43 if explicit else 24300.0
    K = rcv / (SIGMA * eps * A)
    q, t = h["radiation_heat_out"], h["time"]
    T = (q / (SIGMA * eps * A) + Ta ** 4) ** 0.25  # the radiating face's temperature, in kelvin
    drop = T0 - T[-1]  # the drop over the step: the scale of every temperature check
    exact = np.array([closed_form(K, Ta, T0, x) for x in t])
    if explicit:
        check("cooling against the closed form, worst row / drop", np.max(np.abs(T - exact) / drop), 0.0, 2e-3)
        check("balance residual / radiated heat, worst row", np.max(np.abs(h["balance_residual"]) / q), 0.0, 1e-10)
        check("stored heat rate = - radiated, worst row (relative)", np.max(np.abs(h["stored_heat_rate"] + q) / q), 0.0, 3e-3)
        check("final temperature (K)", T[-1], exact[-1], 2e-3 * drop)
        finish()
        return
    spread = max((lambda v: v.max() - v.min())(r.field("NT", i)) for i in range(len(r.frames)))
    check("isothermal plate: max - min of NT in any frame / drop", spread / drop, 0.0, 1e-5)
    be, Tn, tn = [], T0, 0.0
    for x in t:  # backward Euler on the lumped equation, Newton to round-off
        dt, Tb = x - tn, Tn
        for _ in range(60):
            Tb -= (Tb + dt / K * (Tb ** 4 - Ta ** 4) - Tn) / (1 + 4 * dt / K * Tb ** 3)
        be.append(Tb)
        Tn, tn = Tb, x
    be = np.array(be)
    check("thermoslide = backward Euler of the lumped plate, worst increment / drop", np.max(np.abs(T - be) / drop), 0.0, 1e-6)
    check("thermoslide = the closed form, worst increment / drop (backward Euler's first order)", np.max(np.abs(T - exact) / drop), 0.0, 2e-2)
    check("final temperature (K)", T[-1], exact[-1], 2e-2 * drop)
    nt = r.field("NT")[:, 0] - zero
    check("final NT = the face temperature from the radiated heat (K)", nt.mean(), T[-1], 1e-6 * drop)
    check("radiated = - stored heat rate, worst increment (relative)", np.max(np.abs(h["stored_heat_rate"] + q) / q), 0.0, 1e-6)
    check("balance residual / radiated heat, worst increment", np.max(np.abs(h["balance_residual"]) / q), 0.0, 1e-6)
    check("heat radiated over the step = rho c V (T0 - T_end)", np.sum(q * h["dt"]), rcv * (T0 - nt.mean()), 1e-8 * rcv * drop)
    finish()


def steady():
    q, k, L = 5000.0, 20.0, 2.0
    x = r.xyz[:, 0]
    for step, (Ta, eps) in enumerate(((300.0, 0.6), (450.0, 0.3), (500.0, 1.0)), start=1):
        i = r.frame_of_step(step)
        theta = r.field("NT", i)[:, 0]
        tl = (q / (SIGMA * eps) + Ta ** 4) ** 0.25
        check("step %d: theta at x = L (Ta %g, eps %g)" % (step, Ta, eps), theta[x == L].max(), tl, 1e-9 * tl)
        check("step %d: theta spread on x = L" % step, np.ptp(theta[x == L]), 0.0, 1e-9 * tl)
        check("step %d: theta at x = 0" % step, theta[x == 0].min(), tl + q * L / k, 1e-9 * tl)
        row = np.nonzero(h["step"] == step)[0][-1]
        check("step %d: radiated = flux in" % step, h["radiation_heat_out"][row], h["heat_in"][row], 1e-8 * h["heat_in"][row])
        check("step %d: flux in = q x 0.5" % step, h["heat_in"][row], q * 0.5, 1e-12 * q)
        check("step %d: balance residual / flux in" % step, abs(h["balance_residual"][row]) / h["heat_in"][row], 0.0, 1e-8)
    finish()


{"plate": lambda: plate(False), "plate_explicit": lambda: plate(True), "steady": steady}[case]()
