#!/usr/bin/python3
"""Loads across steps on a plate 1 x 0.5 (CPE4T, E = 30e6, nu = 0.3, k = 10), rollers at the bottom.

Step 1 (steady): the top edge is kept straight by *EQUATION (u2 of every top node = u2 of the first),
a point load of 100 pulls down the first top node only -> uniform S22 = -100 / (1 * 1), S11 = 0,
S33 = nu S22; flux q = 50 into the top, film h = 10 (sink 0) on the bottom ->
theta(y) = q/h + q y / k: 5 at the bottom, 7.5 at the top; heat in = film out = 50.
Step 2 (transient): *CLOAD, OP=NEW removes the point load, a pressure of 200 replaces it -> S22 = -200;
a nodal flux of 5 is added -> heat in 55; the film coefficient follows FILM AMPLITUDE (1 -> 3 over the
step) -> at the end, film out = 30 * integral of theta along the bottom (trapezoid: exact for the
consistent film of linear elements); the energy balance closes in every increment.
usage: check_loads.py OUTDIR JOB
"""
import sys

sys.path.insert(0, sys.path[0] + "/../tools")
from tslcheck import Result, check, finish

r = Result(sys.argv[1], sys.argv[2])
f1 = r.frame_of_step(1)
S, U, NT = r.field("S", f1), r.field("U", f1), r.field("NT", f1)[:, 0]
check("step 1 S22 (worst element)", max(S[:, 1], key=lambda x: abs(x + 100)), -100.0, 1e-8 * 100)
check("step 1 S11 (worst element)", max(abs(S[:, 0])), 0.0, 1e-8 * 100)
top = [i for i in range(len(r.xyz)) if abs(r.xyz[i, 1] - 0.5) < 1e-12]
spread = max(U[top, 1]) - min(U[top, 1])
check("step 1 top edge kept straight by *EQUATION (spread of U2)", spread, 0.0, 1e-8 * abs(U[top[0], 1]))
check("step 1 theta at the bottom", max(NT[r.xyz[:, 1] < 1e-12], key=lambda x: abs(x - 5)), 5.0, 1e-7)
check("step 1 theta at the top", max(NT[top], key=lambda x: abs(x - 7.5)), 7.5, 1e-7)
h = r.history
s1 = [i for i in range(len(h["step"])) if h["step"][i] == 1][-1]
check("step 1 heat in", h["heat_in"][s1], 50.0, 1e-10, relative=True)
check("step 1 film heat out", h["film_heat_out"][s1], 50.0, 1e-8, relative=True)
S = r.field("S")
check("step 2 S22 after OP=NEW (worst element)", max(S[:, 1], key=lambda x: abs(x + 200)), -200.0, 1e-8 * 200)
check("step 2 heat in (flux + nodal flux)", h["heat_in"][-1], 55.0, 1e-10, relative=True)
NT = r.field("NT")[:, 0]
bottom = sorted([i for i in range(len(r.xyz)) if abs(r.xyz[i, 1]) < 1e-12], key=lambda i: r.xyz[i, 0])
integral = sum(0.5 * (NT[a] + NT[b]) * (r.xyz[b, 0] - r.xyz[a, 0]) for a, b in zip(bottom, bottom[1:]))
check("step 2 film out with h = 10 * amplitude(end) = 30", h["film_heat_out"][-1], 30.0 * integral, 1e-8, relative=True)
worst = max(abs(h["balance_residual"]))
check("worst energy balance residual (all increments)", worst, 0.0, 1e-8 * 55)
finish()
