#!/usr/bin/python3
"""The increment controller under the deck's *CONTROLS, PARAMETERS=TIME INCREMENTATION (decks/make_hertz_deck.py
--controls: I_L 10, I_G blank, I_A 6, D_D 2; a surface-to-surface pair, so CalculiX's I_G = 4 + 12 = 16 and I_L = 10 + 12 = 22). From the .csv
history: every increment after the first has the size the dialect's rule gives from the two before it, D_D = 2
after two consecutive increments of at most 16 Newton iterations, D_B = 0.75 after one of more than 22, else the
same (never beyond the step's end); and the increment did grow (from 0.05 to at least 0.2).
usage: check_controls.py OUTDIR JOB
"""
import sys

sys.path.insert(0, sys.path[0] + "/../tools")
from tslcheck import Result, check, check_true, finish

h = Result(sys.argv[1], sys.argv[2]).history
t, dt, its = h["step_time"], h["dt"], h["newton_its"]
n = len(dt)
check_true("the step completes (step time 1)", abs(t[-1] - 1.0) < 1e-12, "(%g)" % t[-1])
for k in range(1, n):
    prev = its[k - 2] if k >= 2 else 1e9
    f = 0.75 if its[k - 1] > 22 else 2.0 if its[k - 1] <= 16 and prev <= 16 else 1.0
    want = min(f * dt[k - 1], 1.0 - t[k - 1])
    check("increment %d: dt after %d and %d iterations" % (k + 1, its[k - 1], prev if k >= 2 else -1), dt[k], want, 1e-12 * want)
check_true("the increment grew from 0.05 to at least 0.2", max(dt) >= 0.2 - 1e-12, "(largest %g)" % max(dt))
finish()
