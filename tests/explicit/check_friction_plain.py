#!/usr/bin/python3
"""Plain *FRICTION with explicit penalty contact (decks/friction_plain_penalty_cpe4t.inp, make_decks.py; issue 44,
item 6): mu = 0.2, contact force F = 150 (a pressure of 75 on the small block's top, width 2), slip path 5.

The Coulomb figure is mu F path = 150: the drive's work ALLWK and the dissipation ALLFD. What a penalty stick may
withhold: a node sticks until its elastic slip reaches the stick limit mu p / k_t, and each of its stick phases
(the start and the two reversals) costs that slip's heat; explicit steps stick with the normal penalty
(k_t = eps_n = 10 E / (2/3) = 4.5e8), so the loss is 5 x mu p / eps_n over the path 5 = 3.3e-8 of the heat:
nothing at the size of the spec's statement ("the default penalty stick underestimates the heat by about
0.7 %", which is Abaqus/Standard's elastic slip of 0.005 of a facet; implicit steps keep it). The interface of
this deck rings during the slide (friction-induced vibration of the penalty springs: the pressure swings
between 0 and several times 75 at about 100 Hz after the reversals, docs/explicit.md), and the drive's work that
goes into that vibration ends in the bulk viscosity (ALLVD) instead of the interface, so the check allows the
spec's 0.7 % below 150 and nothing above the drive's work:
  energy balance |ETOTAL| / the largest energy < 1e-6 in every row;
  ALLWK = 150 within 0.1 % (measured 149.999 on 1 and 2 ranks);
  150 (1 - 0.007) <= ALLFD <= ALLWK (measured 149.921 / 149.928: -0.05 %; 115.8 / 109.8 before explicit steps
  stuck with the normal penalty);
  the history's friction_dissipation_total = ALLFD, friction_heat_total = 0.5 of it (1e-9);
  at the end every node at absorbed / (rho c area 8) (spread and mean 1e-4; measured 9.37004, uniform to 7e-6)
  and that within 0.7 % of 75 / 8 = 9.375;
  quasi-static: the kinetic energy left at the end below 1e-3 of ALLFD (measured 5e-6 / 3.5e-6).
usage: check_friction_plain.py OUTDIR JOB
"""
import sys

sys.path.insert(0, sys.path[0] + "/../tools")
from tslcheck import Result, check, check_true, finish

outdir, job = sys.argv[1:3]
r = Result(outdir, job)
h = r.history
mu, force, path, eta, area = 0.2, 150.0, 5.0, 0.5, 8.0
coulomb = mu * force * path
scale = max(abs(h[k]).max() for k in ("ALLKE", "ALLIE", "ALLWK", "ALLCW"))
check("energy balance |ETOTAL| over all rows / largest energy", abs(h["ETOTAL"]).max() / scale, 0.0, 1e-6)
wk, fd = h["ALLWK"][-1], h["ALLFD"][-1]
check("ALLWK, the drive's work (mu F path)", wk, coulomb, 1e-3, relative=True)
check_true("ALLFD within the spec's 0.7 %% below mu F path = %g and not above the drive's work %.6g" % (coulomb, wk),
           coulomb * (1 - 0.007) <= fd <= wk * (1 + 1e-12), "%.6g (%.3f %%)" % (fd, 100 * (fd / coulomb - 1)))
check("friction_dissipation_total / ALLFD", h["friction_dissipation_total"][-1] / fd, 1.0, 1e-9)
absorbed = h["friction_heat_total"][-1]
check("friction_heat_total / friction_dissipation_total (eta)", absorbed / h["friction_dissipation_total"][-1], eta, 1e-9)
nt = r.field("NT")[:, 0]
check("final temperature spread / mean", (nt.max() - nt.min()) / nt.mean(), 0.0, 1e-4)
check("final mean temperature = absorbed / (rho c area)", nt.mean(), absorbed / area, 1e-4, relative=True)
check("final mean temperature against eta mu F path / (rho c area) = 9.375", nt.mean(), eta * coulomb / area, 0.007, relative=True)
check_true("kinetic energy left at the end below 1e-3 of ALLFD", h["ALLKE"][-1] < 1e-3 * fd, "%.3g" % h["ALLKE"][-1])
finish()
