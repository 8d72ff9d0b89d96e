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
