#!/usr/bin/python3
"""Decks of the sequential-coupling tests (*TEMPERATURE, FILE=; CMakeLists.txt here): a steel plate 0.1 x 0.1 m
(SI units: E = 2.1e11 Pa beside k = 50 W/m K) of 4 x 4 CPE4T, its corner far from the origin (x0 = 1000 m), held at
its left edge (u1) and bottom (u2), heated at 100 K on the left and cooled by a film on the right, expanding.

  coupled.inp      the source: two transient coupled steps (100 s in 10 s, 200 s in 25 s), frames every increment
  static.inp       *STATIC steps on the same increments, each reading its step of coupled.h5 (BSTEP=1, BSTEP=2)
  static_fine.inp  the same on half the increments: the frames' times and, between them, interpolated temperatures
  static_one.inp   one *STATIC step ramping to one frame of the file (BSTEP=2, BINC=8: the end of the source run)
  coupled_file.inp static.inp's steps as transient coupled steps: every temperature prescribed from the file
  heat.inp         the source's thermal problem alone (*HEAT TRANSFER), and static_from_heat.inp static.inp reading it:
                   the sequential analysis, whose stresses must be the coupled run's (no mechanical heating here)
  bad_*.inp        bad input (CMakeLists.txt says what each must print)
usage: make_decks.py [OUTDIR]"""
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
X0, Y0, L, N = 1000.0, -500.0, 0.1, 4


def mesh(n=N):
    ids = lambda i, j: 1 + i + (n + 1) * j
    nodes = "".join(" %d, %.12g, %.12g\n" % (ids(i, j), X0 + L * i / n, Y0 + L * j / n) for j in range(n + 1) for i in range(n + 1))
    elems = "".join(" %d, %d, %d, %d, %d\n" % (1 + i + n * j, ids(i, j), ids(i + 1, j), ids(i + 1, j + 1), ids(i, j + 1))
                    for j in range(n) for i in range(n))
    sets = lambda name, pick: "*NSET, NSET=%s\n" % name + "".join(" %d,\n" % ids(i, j) for j in range(n + 1) for i in range(n + 1) if pick(i, j))
    return ("*NODE, NSET=NALL\n" + nodes + "*ELEMENT, TYPE=CPE4T, ELSET=PLATE\n" + elems +
            sets("LEFT", lambda i, j: i == 0) + sets("RIGHT", lambda i, j: i == n) + sets("BOTTOM", lambda i, j: j == 0) +
            "*ELSET, ELSET=RIGHTE\n" + "".join(" %d,\n" % (n + n * j) for j in range(n)))


MODEL = """*MATERIAL, NAME=STEEL
*ELASTIC
 2.1E11, 0.3
*EXPANSION
 1.2E-5
*CONDUCTIVITY
 50.0
*DENSITY
 7800.0
*SPECIFIC HEAT
 500.0
*SOLID SECTION, ELSET=PLATE, MATERIAL=STEEL
 0.01
*INITIAL CONDITIONS, TYPE=TEMPERATURE
 NALL, 0.0
"""
HOLD = "*BOUNDARY\n LEFT, 1, 1\n BOTTOM, 2, 2\n"


def deck(heading, steps, n=N):
    return "*HEADING\n %s\n" % heading + mesh(n) + MODEL + steps


def coupled():
    return deck("Sequential coupling, the source: a plate heated on its left, cooled on its right (coupled, 2 steps)",
                "*STEP, NAME=HEAT, INC=100\n*COUPLED TEMPERATURE-DISPLACEMENT, DIRECT\n 10.0, 100.0\n" + HOLD +
                " LEFT, 11, 11, 100.0\n*FILM\n RIGHTE, F2, 0.0, 25.0\n*END STEP\n"
                "*STEP, NAME=SOAK, INC=100\n*COUPLED TEMPERATURE-DISPLACEMENT, DIRECT\n 25.0, 200.0\n*END STEP\n")


def heat():
    """The source's thermal problem alone: *HEAT TRANSFER steps on the same increments (the CPE4T read as DC2D4)."""
    return deck("Sequential coupling, the heat-transfer source: the plate's temperatures alone (2 steps)",
                "*STEP, NAME=HEAT, INC=100\n*HEAT TRANSFER, DIRECT\n 10.0, 100.0\n*BOUNDARY\n LEFT, 11, 11, 100.0\n"
                "*FILM\n RIGHTE, F2, 0.0, 25.0\n*END STEP\n"
                "*STEP, NAME=SOAK, INC=100\n*HEAT TRANSFER, DIRECT\n 25.0, 200.0\n*END STEP\n")


def static(dt1, dt2, heading, proc="*STATIC, DIRECT", source="coupled"):
    return deck(heading, "*STEP, NAME=HEAT, INC=100\n%s\n %g, 100.0\n" % (proc, dt1) + HOLD +
                "*TEMPERATURE, FILE=%s, BSTEP=1\n*END STEP\n" % source +
                "*STEP, NAME=SOAK, INC=100\n%s\n %g, 200.0\n*TEMPERATURE, FILE=%s.h5, BSTEP=2\n*END STEP\n" % (proc, dt2, source))


def one(extra="", data="", n=N, step="*STATIC, DIRECT\n 0.25, 1.0\n"):
    return deck("Sequential coupling: one frame of the file as the step's target", "*STEP, NAME=RAMP\n" + step + HOLD +
                "*TEMPERATURE, FILE=coupled, BSTEP=2, BINC=8%s\n%s*END STEP\n" % (extra, data), n)


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else os.path.join(HERE, "decks")
    decks = {
        "coupled": coupled(),
        "heat": heat(),
        "static_from_heat": static(10.0, 25.0, "Sequential coupling as users run it: *STATIC steps reading the heat-transfer job's temperatures",
                                   source="heat"),
        "static": static(10.0, 25.0, "Sequential coupling: *STATIC steps reading the source's temperatures at its own increments"),
        "static_fine": static(5.0, 12.5, "Sequential coupling: *STATIC steps on half the source's increments (interpolated between)"),
        "static_one": one(),
        "coupled_file": static(10.0, 25.0, "Sequential coupling: coupled steps whose temperatures are all read from the file",
                               "*COUPLED TEMPERATURE-DISPLACEMENT, DIRECT"),
        "bad_mesh": one(n=3),
        "bad_window": one(", ESTEP=3"),
        "bad_binc": one().replace("BINC=8", "BINC=9"),
        "bad_missing": one().replace("FILE=coupled,", "FILE=no_such_job,"),
        "bad_interpolate": one(", INTERPOLATE"),
        "bad_data": one(data=" NALL, 20.0\n"),
        "bad_explicit": one(step="*DYNAMIC TEMPERATURE-DISPLACEMENT, EXPLICIT\n , 1.0e-4\n"),
        "bad_corrupt": one().replace("FILE=coupled,", "FILE=corrupt,"),
    }
    for name, text in decks.items():
        with open(os.path.join(out, name + ".inp"), "w") as f:
            f.write(text)


if __name__ == "__main__":
    main()
