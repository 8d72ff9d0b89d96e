#!/usr/bin/python3
"""Checks of the conventional shell decks of make_shell_decks.py against their analytic answers.

usage: check_shell.py OUTDIR JOB

plate_s8rt, plate_moved_s8rt  flux q = 100 in through SPOS, film h = 10 (sink 0) on SNEG, k = 10, t = 0.5,
                              area 2: heat 200 in and out; the temperature linear through the thickness from
                              q / h = 10 on SNEG to 10 + q t / k = 15 on SPOS (1e-9; moved: 1e-7); 12.5 on the
                              deck's (mid-surface) nodes; every node on the plane of its level (1e-9)
plate_mm_s8rt                 plate_s8rt moved by (2e6, 1e6) and re-expressed in kN and mm (transform_deck.py
                              2000000 1000000 1000: the thickness 500, k / 1000, q and h / 1e6): the same
                              temperatures and heat (1e-9), the levels at 1000 times their heights
plate_nodal_s8rt              plate_s8rt with its thickness from *NODAL THICKNESS: the same checks
taper_s8rt                    the nodal thickness 0.4 + 0.1 x: every node at y = 0, +-t / 4 or +-t / 2 (1e-12), the heat in
                              100 x the area of the tilted SPOS, 2 sqrt(1 + 0.05^2) (1e-9 relative), the film's heat out
                              the same (steady)
taper_parts_s8rt              the tapered plate as a part placed twice (the second moved by 3 along z): the same
                              checks, the heat twice
plate_labels_s8rt             the same by element labels, and a pressure 1000 on the shells (*DLOAD P): the
                              reaction along y 2000 (1e-9 relative)
plate_spos_s8rt               the same with the deck's nodes on SPOS: 15 there, the plate below them
cantilever_s8rt               step 1: tip deflection P L^3 / (3 E I) + P L / (5/6 G A) = 0.1068750 (0.5 %, the
                              clamped root's local restraint); step 2: the bending curvature alpha dT / t =
                              1e-4 from the centre line's deflections at x = 5 and 10 (0.5 %), its lateral
                              curvature the same from the tip's edges and centre (1 %)
cylinder_sax2t                step 1: Lame's open cylinder (a = 0.99, b = 1.01, p = 100): radial displacement
                              at r = 1 (1e-3 relative); step 2: flux 100 in at r = a, film 10 at r = b:
                              T(1) = q a / (h b) + q a / k ln(b / 1) (1e-6), the heat 2 pi a q (1e-9 relative)
"""
import math
import sys

sys.path.insert(0, sys.path[0] + "/../tools")
import numpy as np  # noqa: E402
from tslcheck import Result, check, check_true, finish  # noqa: E402

E, NU, K, ALPHA = 30.0e6, 0.3, 10.0, 1.0e-5


def deck_nodes(r, n):
    """Positions of the deck's nodes (ids 1..n): the expansion's nodes have ids above the deck's."""
    return np.where(r.node_ids <= n)[0]


def plate(r, job):
    f = r.frame_of_step(1)
    nt = r.field("NT", f)[:, 0]
    heat = r.history
    xyz = r.xyz
    if "moved" in job:  # back to the plate's own frame: the normal is the third column of nothing simpler than
        # the deck's own rotation; use the plane fit of the deck's nodes instead
        mid = deck_nodes(r, 15)
        c = xyz[mid].mean(axis=0)
        _, _, vt = np.linalg.svd(xyz[mid] - c)
        normal = vt[2]
        # orient the normal along +y of the plate's frame: SPOS is the hotter side
        h = (xyz - c) @ normal
        if np.corrcoef(h, nt)[0, 1] < 0:
            h = -h
    elif "mm" in job:  # moved along y by 1e6 (in mm) and 1000 times larger: back to the plate's frame in m
        h = (xyz[:, 1] - 1.0e6) / 1000.0
    else:
        h = xyz[:, 1]
    spos = "spos" in job
    lo, hi = (-0.5, 0.0) if spos else (-0.25, 0.25)
    check_true("every node on one of the five levels through the thickness",
               all(min(abs(v - (lo + k * (hi - lo) / 4)) for k in range(5)) < 1e-9 for v in h))
    exact = 10.0 + 10.0 * (h - lo)  # 10 on SNEG, gradient q / k = 10
    # 1e-7 where the plate is 3e5 from the origin: its levels are known to 1e-9 of the thickness there
    check("max |NT - exact| over every node", float(np.abs(nt - exact).max()), 0.0, 1e-7 if "moved" in job else 1e-9)
    mid = deck_nodes(r, 15)
    check("NT on the deck's nodes", float(nt[mid].mean()), 15.0 if spos else 12.5, 1e-9)
    check("heat in", float(heat["heat_in"][-1]), 200.0, 1e-9, relative=True)
    if "labels" in job:  # the pressure 1000 on the area 2, against the normal +y: the supports push back along +y
        rf = r.field("RF", f)
        check("reaction force along y of the pressure on SPOS", float(rf[:, 1].sum()), 2000.0, 1e-9, relative=True)


def taper(r, copies=1):
    xyz = r.xyz
    t = 0.4 + 0.1 * xyz[:, 0]
    off = np.min(np.abs(np.abs(xyz[:, 1])[:, None] - np.stack([0 * t, t / 4, t / 2], axis=1)), axis=1)
    check("every node at y = 0, +-t/4 or +-t/2 of its nodal thickness t = 0.4 + 0.1 x", float(off.max()), 0.0, 1e-12)
    area = copies * 2.0 * math.sqrt(1 + 0.05 ** 2)
    check("heat in = 100 x the tilted SPOS's area", float(r.history["heat_in"][-1]), 100.0 * area, 1e-9, relative=True)
    check("film heat out = heat in (steady)", float(r.history["film_heat_out"][-1]), 100.0 * area, 1e-9, relative=True)


def cantilever(r):
    L, W, t, P = 10.0, 1.0, 0.5, 100.0
    I, G, A = W * t ** 3 / 12, E / (2 * (1 + NU)), W * t
    xyz = r.xyz
    deck = deck_nodes(r, 63)
    centre = [i for i in deck if abs(xyz[i, 2] - 0.5) < 1e-12]
    at = lambda x, where: [i for i in where if abs(xyz[i, 0] - x) < 1e-12]
    u1 = r.field("U", r.frame_of_step(1))
    tip = at(L, centre)[0]
    check("step 1 tip deflection", float(-u1[tip, 1]), P * L ** 3 / (3 * E * I) + P * L / (5.0 / 6.0 * G * A), 5e-3, relative=True)
    u2 = r.field("U", r.frame_of_step(2))
    y5, y10 = u2[at(5.0, centre)[0], 1], u2[tip, 1]
    kappa = 2 * (y5 - y10) / (L ** 2 - 5.0 ** 2)
    check("step 2 bending curvature from the centre line", float(kappa), ALPHA * 5.0 / t, 5e-3, relative=True)
    edges = [i for i in at(L, deck) if abs(xyz[i, 2] - 0.5) > 0.4]
    lateral = 2 * (u2[tip, 1] - u2[edges, 1].mean()) / (W / 2) ** 2
    check("step 2 lateral curvature at the tip", float(lateral), ALPHA * 5.0 / t, 1e-2, relative=True)
    nt = r.field("NT", r.frame_of_step(2))[:, 0]
    check("step 2 NT on the deck's nodes (mid-surface)", float(np.abs(nt[deck] - 12.5).max()), 0.0, 1e-9)


def cylinder(r):
    a, b, p, q, h = 0.99, 1.01, 100.0, 100.0, 10.0
    deck = deck_nodes(r, 9)
    A, B = p * a * a / (b * b - a * a), p * a * a * b * b / (b * b - a * a)
    u = r.field("U", r.frame_of_step(1))
    check("step 1 radial displacement at r = 1 (Lame)", float(u[deck, 0].mean()), ((1 - NU) * A + (1 + NU) * B) / E, 1e-3, relative=True)
    check("step 1 the wall moves alike along its length: spread / mean", float(np.ptp(u[deck, 0]) / abs(u[deck, 0].mean())), 0.0, 1e-6)
    nt = r.field("NT", r.frame_of_step(2))[:, 0]
    check("step 2 NT at r = 1", float(nt[deck].mean()), q * a / (h * b) + q * a / K * math.log(b), 1e-6)
    outer = np.where(np.abs(r.xyz[:, 0] - b) < 1e-12)[0]
    check("step 2 NT at r = b", float(nt[outer].mean()), q * a / (h * b), 1e-6)
    check("step 2 heat in", float(r.history["heat_in"][-1]), 2 * math.pi * a * q, 1e-9, relative=True)


def main():
    outdir, job = sys.argv[1], sys.argv[2]
    r = Result(outdir, job)
    if job.startswith("plate"):
        plate(r, job)
    elif job.startswith("taper"):
        taper(r, 2 if "parts" in job else 1)
    elif job.startswith("cantilever"):
        cantilever(r)
    else:
        cylinder(r)
    finish()


if __name__ == "__main__":
    main()
