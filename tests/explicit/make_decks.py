#!/usr/bin/python3
"""Writes the explicit test decks of decks/ (run from this directory; the decks are committed).

Bars of one row of square CPE4T elements, nu = 0 so that the plane-strain dilatational speed equals the
bar speed c = sqrt(E / rho) = 100 (E = 1e4, rho = 1); conductivity small so that the mechanical limit
controls the increment.
"""


def bar_mesh(n, L=1.0):
    h = L / n
    lines = ["*NODE, NSET=ALL"]
    for j in range(2):
        for i in range(n + 1):
            lines.append(" %d, %.10g, %.10g" % (j * (n + 1) + i + 1, i * h, j * h))
    lines.append("*ELEMENT, TYPE=CPE4T, ELSET=BAR")
    for i in range(n):
        a = i + 1
        lines.append(" %d, %d, %d, %d, %d" % (i + 1, a, a + 1, a + n + 2, a + n + 1))
    lines.append("*NSET, NSET=LEFT\n 1, %d" % (n + 2))
    lines.append("*NSET, NSET=RIGHT\n %d, %d" % (n + 1, 2 * n + 2))
    lines.append("*NSET, NSET=MIDDLE\n %d" % (n // 2 + 1))
    return "\n".join(lines) + "\n"


MATERIAL = """*MATERIAL, NAME=ROD
*ELASTIC
 1.0E4, 0.0
*DENSITY
 1.0
*CONDUCTIVITY
 1.0E-3
*SPECIFIC HEAT
 1.0
*SOLID SECTION, ELSET=BAR, MATERIAL=ROD
 1.0
*INITIAL CONDITIONS, TYPE=TEMPERATURE
 ALL, 0.0
"""


def write(name, text):
    with open("decks/%s.inp" % name, "w") as f:
        f.write(text)


n = 100
# A step force on the left end of a free bar: a front moving at c; at t = 0.007 it is at x = 0.7.
write("wave_bar_cpe4t", "*HEADING\n Explicit: step load on the end of a bar, front speed c = sqrt(E/rho) = 100\n" + bar_mesh(n) + MATERIAL + """*STEP
*DYNAMIC TEMPERATURE-DISPLACEMENT, EXPLICIT
 , 0.007
*CLOAD
 LEFT, 1, 0.5
*OUTPUT, FIELD, NUMBER INTERVAL=7
*NODE OUTPUT
 U
*END STEP
""")
# A bar stretched statically by 0.001 (implicit step), then released: free-free vibration of period
# 2 L / c = 0.02.
write("vibration_bar_cpe4t", "*HEADING\n Explicit: released stretched free-free bar, period 2 L / c = 0.02 (undamped: no bulk viscosity)\n" + bar_mesh(n) + MATERIAL + """*STEP
*COUPLED TEMPERATURE-DISPLACEMENT
 1.0, 1.0
*BOUNDARY
 LEFT, 1, 1, 0.0
 1, 2, 2, 0.0
 RIGHT, 1, 1, 0.001
*NODE OUTPUT
 U
*END STEP
*STEP, NAME=RELEASE
*DYNAMIC TEMPERATURE-DISPLACEMENT, EXPLICIT
 , 0.03
*BULK VISCOSITY
 0.0, 0.0
*BOUNDARY, OP=NEW
*OUTPUT, FIELD, TIME INTERVAL=0.0002
*NODE OUTPUT
 U
*END STEP
""")

# The implicit transient conduction deck of jobs/verification as an explicit step: the same slab, the same
# prescribed face temperature, forward Euler on the lumped capacity instead of backward Euler.
with open("../../jobs/verification/conduction_transient_cpe4t.inp") as f:
    deck = f.read()
deck = deck.replace("*COUPLED TEMPERATURE-DISPLACEMENT, DELTMX=50.0\n 0.0005, 0.03, 1e-6, 0.0005\n",
                    "*DYNAMIC TEMPERATURE-DISPLACEMENT, EXPLICIT\n , 0.03\n")
deck = deck.replace("*NODE OUTPUT\n NT\n", "*OUTPUT, FIELD, TIME INTERVAL=0.0005\n*NODE OUTPUT\n NT\n")
deck = deck.replace("Transient 1D conduction, CPE4T", "Explicit transient 1D conduction, CPE4T")
assert "EXPLICIT" in deck and "TIME INTERVAL" in deck
write("conduction_explicit_cpe4t", deck)

# The wave deck with the mass scaled to a target element increment twice the stable one: every element's
# mass x 4, so the front moves at c / 2 = 50 and reaches x = 0.35 at t = 0.007.
with open("decks/wave_bar_cpe4t.inp") as f:
    deck = f.read()
deck = deck.replace("*CLOAD\n", "*VARIABLE MASS SCALING, DT=2.0E-4, ELSET=BAR, FREQUENCY=50\n*CLOAD\n")
deck = deck.replace("front speed c = sqrt(E/rho) = 100", "mass scaled x 4 to DT = 2e-4, front speed 50")
write("wave_mass_scaled_cpe4t", deck)

# A factor beyond the sane bound (100): the run goes on, the log warns with the figure.
write("mass_scaling_warning_cpe4t", deck.replace("*VARIABLE MASS SCALING, DT=2.0E-4, ELSET=BAR, FREQUENCY=50\n", "*FIXED MASS SCALING, FACTOR=200\n").replace(" , 0.007\n", " , 0.001\n").replace("NUMBER INTERVAL=7", "NUMBER INTERVAL=1"))

# Plain *FRICTION with explicit penalty contact, written as a user writes it (issue 44, item 6): no LAGRANGE, no
# slip tolerance, no SMOOTH, MECHANICAL CONSTRAINT=PENALTY; the two blocks of the spec's friction series (a
# small block 2 x 0.25, 4 x 2 cells, on a large block 6 x 1.25, 9 x 2 cells: facets of 2/3, the default normal
# penalty 10 E / (2/3) = 4.5e8), the spec's material (rho c = 1, total area 8), mu = 0.2 and a pressure of 75
# on the small block's top (a contact force of 150), ramped in by a smooth step; the top face then driven
# +1.25, -2.5, +1.25 in three SMOOTH STEP legs over 16 s (slip path 5: mu F path = 150, half of it heating the
# blocks, eta = 0.5), then 2 s at rest (5.5 conduction time constants of the large block). Before explicit steps
# stuck with the normal penalty, this deck dissipated 115.8 on 1 rank and 109.8 on 2 (the drive's work 132.1 and
# 128.5): every opening of the chattering interface restarted the automatic stick's elastic slip of
# 0.005 x 2/3 (docs/explicit.md, "Friction in explicit steps"; check_friction_plain.py).
def plain_friction_blocks():
    nodes, elems = [], []

    def grid(nx, ny, x0, x1, y0, y1, nid0, eid0):
        nid = lambda i, j: nid0 + 1 + i + j * (nx + 1)
        for j in range(ny + 1):
            for i in range(nx + 1):
                nodes.append(" %d, %.12g, %.12g" % (nid(i, j), x0 + (x1 - x0) * i / nx, y0 + (y1 - y0) * j / ny))
        rows = []
        for j in range(ny):
            rows.append([eid0 + 1 + i + j * nx for i in range(nx)])
            for i in range(nx):
                elems.append(" %d, %d, %d, %d, %d" % (eid0 + 1 + i + j * nx, nid(i, j), nid(i + 1, j), nid(i + 1, j + 1), nid(i, j + 1)))
        return nid, rows

    bn, brows = grid(9, 2, 0.0, 6.0, 0.0, 1.25, 0, 0)
    nlarge = len(elems)
    tn, trows = grid(4, 2, 2.0, 4.0, 1.25, 1.5, 1000, 1000)
    ids = lambda v: "\n".join(" " + ", ".join(str(i) for i in v[k:k + 8]) for k in range(0, len(v), 8))
    return ("*HEADING\n Plain *FRICTION, explicit penalty contact: two blocks, mu = 0.2, contact force 150, slip path 5\n"
            "*NODE, NSET=ALL\n" + "\n".join(nodes) + "\n*ELEMENT, TYPE=CPE4T, ELSET=LARGE\n" + "\n".join(elems[:nlarge]) +
            "\n*ELEMENT, TYPE=CPE4T, ELSET=SMALL\n" + "\n".join(elems[nlarge:]) +
            "\n*NSET, NSET=BASE\n" + ids([bn(i, 0) for i in range(10)]) + "\n*NSET, NSET=TOPFACE\n" + ids([tn(i, 2) for i in range(5)]) +
            "\n*ELSET, ELSET=MAINE\n" + ids(brows[-1]) + "\n*ELSET, ELSET=SECE\n" + ids(trows[0]) + "\n*ELSET, ELSET=PRESSED\n" + ids(trows[-1]) + """
*SURFACE, NAME=MAIN, TYPE=ELEMENT
 MAINE, S3
*SURFACE, NAME=SECONDARY, TYPE=ELEMENT
 SECE, S1
*MATERIAL, NAME=STEEL
*ELASTIC
 30.0E6, 0.3
*CONDUCTIVITY
 10.0
*DENSITY
 1000.0
*SPECIFIC HEAT
 0.001
*SOLID SECTION, ELSET=LARGE, MATERIAL=STEEL
 1.0
*SOLID SECTION, ELSET=SMALL, MATERIAL=STEEL
 1.0
*SURFACE INTERACTION, NAME=IFACE
*FRICTION
 0.2
*GAP CONDUCTANCE, PRESSURE
 20.0, 0.0
*GAP HEAT GENERATION
 0.5, 0.5
*CONTACT PAIR, INTERACTION=IFACE, MECHANICAL CONSTRAINT=PENALTY
 SECONDARY, MAIN
*INITIAL CONDITIONS, TYPE=TEMPERATURE
 ALL, 0.0
*AMPLITUDE, NAME=SLIDE, DEFINITION=SMOOTH STEP
 0, 0
 4, 1
 12, -1
 16, 0
*AMPLITUDE, NAME=RAMP, DEFINITION=SMOOTH STEP
 0, 0
 0.25, 1
*STEP, NAME=PRESS
*DYNAMIC TEMPERATURE-DISPLACEMENT, EXPLICIT
 , 0.25
*BOUNDARY
 BASE, 1, 2
 TOPFACE, 1, 1
*DLOAD, AMPLITUDE=RAMP
 PRESSED, P3, 75.0
*END STEP
*STEP, NAME=SLIDE
*DYNAMIC TEMPERATURE-DISPLACEMENT, EXPLICIT
 , 16
*BOUNDARY, AMPLITUDE=SLIDE
 TOPFACE, 1, 1, 1.25
*END STEP
*STEP, NAME=EQUILIBRATE
*DYNAMIC TEMPERATURE-DISPLACEMENT, EXPLICIT
 , 2
*END STEP
""")


write("friction_plain_penalty_cpe4t", plain_friction_blocks())
