#!/usr/bin/python3
"""Decks of the plasticity tests (CMakeLists.txt here; docs/keywords.md *PLASTIC): a unit cube (a ring of unit
cross-section for CAX4T) in uniaxial stress, held on its three symmetry planes and pulled along x (the ring: along
its axis) by a prescribed displacement, through loading, unloading and reverse loading; Mises plasticity with
isotropic hardening, E = 200000, nu = 0.3, sigma_y = 200 + 1000 p (two points; constant past p = 0.5).

  uniaxial_<type>.inp   *STATIC steps: to strain 0.01, back to 0.004, on to -0.01 (check.py uniaxial)
  adiabatic_<type>.inp  one transient coupled step pulling to strain 0.02 in 1 s with no heat leaving, and
                        *INELASTIC HEAT FRACTION 0.9, rho c = 2: Delta theta = 0.9 ALLPD / (rho c V); the _soft variant
                        has a yield stress falling with temperature (200 + 1000 p at 0, 100 + 500 p at 50)
  uniaxial_kinematic_<type>.inp, adiabatic_kinematic_c3d8t.inp, jacobian_kinematic_c3d8t.inp  the same with linear
                        kinematic hardening (HARDENING=KINEMATIC, C = 1000: the reverse yield at the back stress - 200); the
                        Jacobian deck then shears the brick, a flow across the back stress of the pull
  uniaxial_combined_<type>.inp, uniaxial_combined1_c3d8t.inp  combined hardening (PLASTIC_COMB, PLASTIC_COMB1) through
                        the closed cycle CYCLE; adiabatic_combined_c3d8t.inp its pull on a ramp in 500 increments;
                        jacobian_combined_c3d8t.inp the pull-then-shear tangent test with a temperature-dependent
                        exponential law (PLASTIC_COMB_SOFT)
  jacobian_plastic_c3d8t.inp  a distorted brick pulled past yield, heated, a temperature-dependent modulus and yield
                        table: -snes_test_jacobian with the plastic flow, its heat and their temperature columns
  bad_*.inp             bad input (CMakeLists.txt gives each message)
usage: make_decks.py [OUTDIR]"""
import math
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
E, NU, RHO, C = 200000.0, 0.3, 1.0, 2.0
R0 = 10.0  # the ring's inner radius
PLASTIC = "*PLASTIC\n 200.0, 0.0\n 700.0, 0.5\n"
PLASTIC_KIN = "*PLASTIC, HARDENING=KINEMATIC\n 200.0, 0.0\n 700.0, 0.5\n"  # linear kinematic, C = 1000
# nonlinear kinematic (two back stresses: C = 40000, gamma = 400, saturating at 100, and a linear one of C = 1000)
# with the exponential isotropic law 200 + 50 (1 - exp(-20 p)); COMBINED1: Abaqus's defaults, one back stress, a
# surface of constant size
PLASTIC_COMB = ("*PLASTIC, HARDENING=COMBINED, DATA TYPE=PARAMETERS, NUMBER BACKSTRESSES=2\n 200.0, 40000.0, 400.0, 1000.0, 0.0\n"
                "*CYCLIC HARDENING, PARAMETERS\n 200.0, 50.0, 20.0\n")
PLASTIC_COMB1 = "*PLASTIC, HARDENING=COMBINED, DATA TYPE=PARAMETERS\n 200.0, 40000.0, 400.0\n"
PLASTIC_COMB_SOFT = ("*PLASTIC, HARDENING=COMBINED, DATA TYPE=PARAMETERS, NUMBER BACKSTRESSES=2\n 200.0, 40000.0, 400.0, 1000.0, 0.0\n"
                     "*CYCLIC HARDENING, PARAMETERS\n 200.0, 50.0, 20.0, 0.0\n 120.0, 30.0, 10.0, 100.0\n")
# rate dependence: R = 1 + (rate / 0.1)^(1/2) (Cowper-Symonds) and R = 1 + 0.05 ln(rate / 1e-3) (Johnson-Cook)
RATE_POWER = "*RATE DEPENDENT, TYPE=POWER LAW\n 0.1, 2.0\n"
RATE_JC = "*RATE DEPENDENT, TYPE=JOHNSON COOK\n 0.05, 0.001\n"
# temperature-dependent back stresses: linear kinematic 200 + C eps_p with C = 1000 at 0 and 100 + 400 eps_p at
# 100; combined with two back stresses softening from (40000, 400), (1000, 0) at 0 to (20000, 200), (500, 0) at 100
PLASTIC_KIN_THETA = "*PLASTIC, HARDENING=KINEMATIC\n 200.0, 0.0, 0.0\n 700.0, 0.5, 0.0\n 100.0, 0.0, 100.0\n 300.0, 0.5, 100.0\n"
PLASTIC_COMB_THETA = ("*PLASTIC, HARDENING=COMBINED, DATA TYPE=PARAMETERS, NUMBER BACKSTRESSES=2\n 200.0, 40000.0, 400.0, 1000.0, 0.0, 0.0\n"
                      " 120.0, 20000.0, 200.0, 500.0, 0.0, 100.0\n")
PLASTIC_SOFT = "*PLASTIC\n 200.0, 0.0, 0.0\n 700.0, 0.5, 0.0\n 100.0, 0.0, 50.0\n 350.0, 0.5, 50.0\n"
# the strain path of the uniaxial decks: (step, period, increment, target strain)
PATH = [("LOAD", 1.0, 0.1, 0.01), ("UNLOAD", 1.0, 0.25, 0.004), ("REVERSE", 1.0, 0.1, -0.01)]
CYCLE = PATH + [("RELOAD", 1.0, 0.1, 0.01)]  # the nonlinear kinematic decks close the cycle


def cube(typ):
    """A unit cube of one element (C3D20T: its midside nodes too), or the CAX4T ring r in [R0, R0 + 1], z in [0, 1]."""
    if typ.startswith("CPS") or typ.startswith("CPEG"):  # the unit square
        nodes = [(1, 0.0, 0.0), (2, 1.0, 0.0), (3, 1.0, 1.0), (4, 0.0, 1.0)]
        return nodes, [[1, 1, 2, 3, 4]], "*NSET, NSET=X0\n 1, 4\n*NSET, NSET=X1\n 2, 3\n*NSET, NSET=Y0\n 1, 2\n*NSET, NSET=Y1\n 3, 4\n"
    if typ.startswith("CAX4"):
        nodes = [(1, R0, 0.0), (2, R0 + 1, 0.0), (3, R0 + 1, 1.0), (4, R0, 1.0)]
        return nodes, [[1, 1, 2, 3, 4]], "*NSET, NSET=X0\n 1, 2\n*NSET, NSET=X1\n 3, 4\n"  # X0: z = 0, X1: z = 1 (the pulled face)
    corner = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0), (0, 0, 1), (1, 0, 1), (1, 1, 1), (0, 1, 1)]
    pts = list(corner)
    conn = list(range(1, 9))
    if typ == "C3D20T":
        edges = [(0, 1), (1, 2), (2, 3), (3, 0), (4, 5), (5, 6), (6, 7), (7, 4), (0, 4), (1, 5), (2, 6), (3, 7)]
        for a, b in edges:
            pts.append(tuple(0.5 * (corner[a][k] + corner[b][k]) for k in range(3)))
        conn = list(range(1, 21))
    nodes = [(i + 1,) + p for i, p in enumerate(pts)]
    sel = lambda k, v: [n[0] for n in nodes if abs(n[1 + k] - v) < 1e-12]
    sets = "".join("*NSET, NSET=%s\n" % name + "".join(" %d,\n" % i for i in sel(k, v)) for name, k, v in
                   [("X0", 0, 0.0), ("X1", 0, 1.0), ("Y0", 1, 0.0), ("Z0", 2, 0.0)])
    return nodes, [[1] + conn], sets


def model(typ, plastic, heat=False):
    nodes, elems, sets = cube(typ)
    dim = 2 if typ.startswith("CAX4") or typ.startswith("CPS") or typ.startswith("CPEG") else 3
    fmt = lambda n: " %d, " % n[0] + ", ".join("%.12g" % v for v in n[1:1 + dim]) + "\n"
    return ("*NODE, NSET=NALL\n" + "".join(fmt(n) for n in nodes) + "*ELEMENT, TYPE=%s, ELSET=ALL\n" % typ +
            "".join(" " + ", ".join(str(v) for v in e) + "\n" for e in elems) + sets +
            "*MATERIAL, NAME=STEEL\n*ELASTIC\n %g, %g\n" % (E, NU) + plastic + ("*INELASTIC HEAT FRACTION\n 0.9\n" if heat else "") +
            "*CONDUCTIVITY\n 50.0\n*DENSITY\n %g\n*SPECIFIC HEAT\n %g\n*SOLID SECTION, ELSET=ALL, MATERIAL=STEEL\n 1.0\n" % (RHO, C) +
            "*INITIAL CONDITIONS, TYPE=TEMPERATURE\n NALL, 0.0\n")


def holds(typ):
    """The symmetry planes (the ring: z = 0 axially, radially free) and the pulled direction's dof."""
    if typ.startswith("CPS"):
        return "*BOUNDARY\n X0, 1, 1\n Y0, 2, 2\n", 1
    ax = typ.startswith("CAX4")
    return ("*BOUNDARY\n X0, 2, 2\n" if ax else "*BOUNDARY\n X0, 1, 1\n Y0, 2, 2\n Z0, 3, 3\n"), (2 if ax else 1)


def uniaxial(typ, kin=False, law=None, path=PATH):
    hold, dof = holds(typ)
    text = ("*HEADING\n Uniaxial stress of one %s: loading, unloading, reverse loading (Mises, %s hardening)\n" %
            (typ, "combined" if law else "kinematic" if kin else "isotropic") + model(typ, law or (PLASTIC_KIN if kin else PLASTIC)))
    for k, (name, period, inc, strain) in enumerate(path):
        text += ("*STEP, NAME=%s, INC=100\n*STATIC, DIRECT\n %g, %g\n" % (name, inc, period) + (hold if k == 0 else "") +
                 "*BOUNDARY\n X1, %d, %d, %.12g\n*END STEP\n" % (dof, dof, strain))
    return text


def adiabatic(typ, soft, kin=False, law=None, inc=0.05):
    """law: pulled on a ramp (the coupled step's default is a jump), so that the law's path is followed in small
    increments"""
    hold, dof = holds(typ)

    return ("*HEADING\n Adiabatic heating of one %s pulled past yield%s\n" % (typ, " (a yield stress falling with temperature)" if soft else
                                                                             " (kinematic hardening)" if kin else " (combined hardening)" if law else "") +
            model(typ, law or (PLASTIC_SOFT if soft else PLASTIC_KIN if kin else PLASTIC), heat=True) +
            ("*AMPLITUDE, NAME=RAMP\n 0.0, 0.0, 1.0, 1.0\n" if law else "") + "*STEP, NAME=PULL, INC=%d\n*COUPLED TEMPERATURE-DISPLACEMENT, DIRECT\n %g, 1.0\n" % (max(100, round(2 / inc)), inc) + hold +
            "*BOUNDARY%s\n X1, %d, %d, 0.02\n*END STEP\n" % (", AMPLITUDE=RAMP" if law else "", dof, dof))


def explicit(typ, law=None, period=None):
    """An explicit step: the pull of adiabatic() to strain 0.02 on a smooth step over 2 s (quasi-static: the cube's
    wave transit is 2e-3 s), then held for 0.5 s, so that all the plastic work's heat has entered the temperature;
    period: the pull's time instead (then held a quarter of it), every increment a frame (the rate-dependent check
    takes each increment's rate from consecutive frames)"""
    hold, dof = holds(typ)
    T = period or 2.0
    out = "*OUTPUT, FIELD, NUMBER INTERVAL=500\n" if period else "*OUTPUT, FIELD, NUMBER INTERVAL=50\n"
    return ("*HEADING\n Explicit: one %s pulled past yield on a smooth step and held%s\n" % (typ, " (rate dependent)" if law and "RATE" in law else " (combined hardening)" if law else "") +
            model(typ, law or PLASTIC, heat=True) + "*AMPLITUDE, NAME=PULL, DEFINITION=SMOOTH STEP\n 0.0, 0.0, %s, 1.0\n" % float(T) +
            "*STEP, NAME=PULL\n*DYNAMIC TEMPERATURE-DISPLACEMENT, EXPLICIT\n , %s\n" % (1.25 * T) + hold +
            "*BOUNDARY, AMPLITUDE=PULL\n X1, %d, %d, 0.02\n" % (dof, dof) + out + "*END STEP\n")


def biaxial(typ):
    """Equibiaxial stress in plane stress: the square pulled along x and y alike (to 0.01, back to 0.004, on to
    -0.01): the thickness takes the flow, eps_33 = -2 nu sigma / E - eps_p (check.py biaxial)"""
    text = "*HEADING\n Equibiaxial plane stress of one %s: the thickness strain of the flow\n" % typ + model(typ, PLASTIC)
    for k, (name, period, inc, strain) in enumerate(PATH):
        text += ("*STEP, NAME=%s, INC=100\n*STATIC, DIRECT\n %g, %g\n" % (name, inc, period) + ("*BOUNDARY\n X0, 1, 1\n Y0, 2, 2\n" if k == 0 else "") +
                 "*BOUNDARY\n X1, 1, 1, %.12g\n Y1, 2, 2, %.12g\n*END STEP\n" % (strain, strain))
    return text


def jacobian_2d(typ, law):
    """jacobian() for a distorted plane-stress quad (millimetres), pulled then sheared: the plane-stress return's
    condensed tangent, heat and temperature columns"""
    corner = [(0, 0), (1000, 0), (1100, 1200), (-100, 1000)]
    return ("*HEADING\n A distorted %s pulled and sheared past yield and heated: the plane-stress tangent against finite differences\n" % typ +
            "*NODE, NSET=NALL\n" + "".join(" %d, %g, %g\n" % ((i + 1,) + c) for i, c in enumerate(corner)) +
            "*ELEMENT, TYPE=%s, ELSET=ALL\n 1, 1, 2, 3, 4\n*NSET, NSET=FIX\n 1, 4\n*NSET, NSET=PULL\n 2, 3\n" % typ +
            "*MATERIAL, NAME=STEEL\n*ELASTIC\n 200000., 0.3, 0.\n 150000., 0.3, 100.\n" + law +
            "*INELASTIC HEAT FRACTION\n*EXPANSION\n 1.2E-5\n*CONDUCTIVITY\n 50.0\n*DENSITY\n 1.0\n*SPECIFIC HEAT\n 2.0\n"
            "*SOLID SECTION, ELSET=ALL, MATERIAL=STEEL\n 10.0\n*INITIAL CONDITIONS, TYPE=TEMPERATURE\n NALL, 20.0\n"
            "*STEP, INC=10\n*COUPLED TEMPERATURE-DISPLACEMENT, DIRECT\n 0.5, 1.0\n*BOUNDARY\n FIX, 1, 1\n 1, 2, 2\n"
            " PULL, 1, 1, 40.0\n*CFLUX\n 3, 11, 5.0E6\n*END STEP\n"
            "*STEP, INC=10\n*COUPLED TEMPERATURE-DISPLACEMENT, DIRECT\n 0.5, 1.0\n*BOUNDARY\n PULL, 2, 2, 40.0\n*END STEP\n")


# the thick-walled cylinder: a = 1, b = 2, elastic-perfectly plastic sigma_0 = 200 (k = sigma_0 / sqrt(3)), nearly
# incompressible (nu = 0.49: the closed form's sigma_z = the mean in plane strain), the fronts c = 1.5, 1.7
CYL_A, CYL_B, CYL_S0, CYL_NU, CYL_FRONTS = 1.0, 2.0, 200.0, 0.49, (1.5, 1.7)


def cylinder_pressure(c):
    """The internal pressure that pushes the plastic front to c (plane strain, Tresca yield in k)"""
    k = CYL_S0 / 3 ** 0.5
    return k * (1 - c * c / CYL_B ** 2 + 2 * math.log(c / CYL_A))


def cylinder(typ, nr=24, nt=8, nu=CYL_NU):
    """A thick-walled cylinder under internal pressure (check.py cylinder): CPE8RT a quarter annulus (nr x nt, symmetry
    on both cuts), CAX8RT a radial strip of nr square elements held axially (plane strain); the pressure to the fronts
    CYL_FRONTS in two steps, then removed (elastic unloading: the residual stresses); a frame at each step's end (automatic
    increments, which 1 and 2 ranks may choose differently near the limit load)"""
    a, b = CYL_A, CYL_B
    ax = typ.startswith("CAX")
    nt = 1 if ax else nt
    h = (b - a) / nr
    pts, ids = [], {}
    for j in range(2 * nt + 1):
        for i in range(2 * nr + 1):
            if i % 2 and j % 2:
                continue  # the quad8's centre
            r = a + (b - a) * i / (2 * nr)
            if ax:
                xy = (r, h * j / 2)
            else:
                t = 0.5 * math.pi * j / (2 * nt)
                xy = (r * math.cos(t), r * math.sin(t))
            ids[(i, j)] = len(pts) + 1
            pts.append(xy)
    elems = []
    for j in range(nt):
        for i in range(nr):
            I, J = 2 * i, 2 * j
            elems.append([ids[(I, J)], ids[(I + 2, J)], ids[(I + 2, J + 2)], ids[(I, J + 2)], ids[(I + 1, J)], ids[(I + 2, J + 1)], ids[(I + 1, J + 2)],
                          ids[(I, J + 1)]])
    text = "*HEADING\n A thick-walled %s cylinder under internal pressure, elastic-perfectly plastic: fronts at %s, then unloaded\n" % (
        typ, ", ".join("%g" % c for c in CYL_FRONTS))
    text += "*NODE, NSET=NALL\n" + "".join(" %d, %.15g, %.15g\n" % (k + 1, x, y) for k, (x, y) in enumerate(pts))
    text += "*ELEMENT, TYPE=%s, ELSET=ALL\n" % typ + "".join(" %d, " % (e + 1) + ", ".join(str(v) for v in c) + "\n" for e, c in enumerate(elems))
    text += "*ELSET, ELSET=INNER\n" + "".join(" %d,\n" % (1 + nr * j) for j in range(nt)) + "*SURFACE, NAME=BORE\n INNER, S4\n"
    if ax:
        text += "*BOUNDARY\n NALL, 2, 2\n"
    else:
        text += "*NSET, NSET=CUT0\n" + "".join(" %d,\n" % ids[(i, 0)] for i in range(2 * nr + 1)) + \
                "*NSET, NSET=CUT90\n" + "".join(" %d,\n" % ids[(i, 2 * nt)] for i in range(2 * nr + 1)) + "*BOUNDARY\n CUT0, 2, 2\n CUT90, 1, 1\n"
    text += ("*MATERIAL, NAME=STEEL\n*ELASTIC\n %g, %g\n*PLASTIC\n %g, 0.0\n*CONDUCTIVITY\n 50.0\n*DENSITY\n 1.0\n*SPECIFIC HEAT\n 2.0\n"
             "*SOLID SECTION, ELSET=ALL, MATERIAL=STEEL\n 1.0\n*INITIAL CONDITIONS, TYPE=TEMPERATURE\n NALL, 0.0\n" % (E, nu, CYL_S0))
    for k, c in enumerate(CYL_FRONTS + (None,)):
        pr = cylinder_pressure(c) if c else 0.0
        text += ("*STEP, NAME=%s, INC=100\n*STATIC\n 0.1, 1.0\n*DSLOAD\n BORE, P, %.12g\n*OUTPUT, FIELD, NUMBER INTERVAL=1\n*END STEP\n" %
                 ("FRONT%d" % (k + 1) if c else "UNLOAD", pr))
    return text


def friction_plastic():
    """The spec's CPE4T friction deck (jobs/verification/sliding_friction_cpe4t.inp) with the small block of a metal
    that yields under the press (sigma_y = 30 + 10000 p against the pressure of 100) and again in the slide, with
    *INELASTIC HEAT FRACTION 0.9: frictional and plastic heat together (check.py friction_plastic)"""
    with open(os.path.join(HERE, "..", "..", "jobs", "verification", "sliding_friction_cpe4t.inp")) as f:
        text = f.read()
    soft = ("*MATERIAL, NAME=SOFT\n*ELASTIC\n 30.0E6, 0.3\n*PLASTIC\n 30.0, 0.0\n 130.0, 0.01\n*INELASTIC HEAT FRACTION\n 0.9\n"
            "*CONDUCTIVITY\n 10.0\n*DENSITY\n 1000.0\n*SPECIFIC HEAT\n 0.001\n")
    text = text.replace("*SOLID SECTION, ELSET=SMALL, MATERIAL=STEEL", "*SOLID SECTION, ELSET=SMALL, MATERIAL=SOFT")
    text = text.replace("*SOLID SECTION, ELSET=LARGE", soft + "*SOLID SECTION, ELSET=LARGE", 1)
    return text.replace(" Finite sliding between coupled temperature-displacement CPE4T blocks: friction series",
                        " The spec's CPE4T friction series with a small block that yields: frictional and plastic heat", 1)


def uniaxial_theta(typ, law):
    """Temperature-dependent back stresses: pulled to 0.01 at 0, heated to 100 at that strain (the back stress carried
    to the hot modulus, the surface shrunk), reversed to -0.01 and pulled back to 0.006 hot (check.py
    uniaxial_theta)"""
    hold, dof = holds(typ)
    text = "*HEADING\n Uniaxial stress of one %s with temperature-dependent back stresses: pulled cold, heated, reversed hot\n" % typ + model(typ, law)
    path = [("PULL", 0.1, 0.01, 0.0), ("HEAT", 0.1, 0.01, 100.0), ("REVERSE", 0.1, -0.01, 100.0), ("RELOAD", 0.1, 0.006, 100.0)]
    for k, (name, inc, strain, temp) in enumerate(path):
        text += ("*STEP, NAME=%s, INC=100\n*STATIC, DIRECT\n %g, 1.0\n" % (name, inc) + (hold if k == 0 else "") +
                 "*BOUNDARY\n X1, %d, %d, %.12g\n NALL, 11, 11, %g\n*END STEP\n" % (dof, dof, strain, temp))
    return text


def uniaxial_gps(typ):
    """Generalized plane strain: the unit square (thickness 1) free in its plane, pulled along z by its reference
    node's dof 3 (the length change) through PATH: uniaxial stress along z (check.py uniaxial, axis 2)"""
    text = ("*HEADING\n Generalized plane strain %s pulled along z by its reference node: uniaxial stress (isotropic hardening)\n" % typ +
            model(typ, PLASTIC).replace("*NODE, NSET=NALL\n", "*NODE, NSET=REF\n 100, 0.0, 0.0\n*NODE, NSET=NALL\n", 1)
            .replace("*SOLID SECTION, ELSET=ALL, MATERIAL=STEEL", "*SOLID SECTION, ELSET=ALL, MATERIAL=STEEL, REF NODE=100"))
    for k, (name, period, inc, strain) in enumerate(PATH):
        text += ("*STEP, NAME=%s, INC=100\n*STATIC, DIRECT\n %g, %g\n" % (name, inc, period) +
                 ("*BOUNDARY\n X0, 1, 1\n Y0, 2, 2\n REF, 4, 5\n" if k == 0 else "") + "*BOUNDARY\n REF, 3, 3, %.12g\n*END STEP\n" % strain)
    return text


def impact_plastic():
    """The explicit 3D impact of tests/explicit (kinematic_blocks_c3d8t.inp: a C3D8T block struck onto a base with
    kinematic contact and gap conductance) with a metal that yields (sigma_y = 20 + 800 p) and *INELASTIC HEAT
    FRACTION: plastic flow, its heat and contact together, 1 and 2 ranks (check.py impact)"""
    with open(os.path.join(HERE, "..", "explicit", "decks", "kinematic_blocks_c3d8t.inp")) as f:
        text = f.read()
    return text.replace("*ELASTIC\n 200000, 0.3\n", "*ELASTIC\n 200000, 0.3\n*PLASTIC\n 20.0, 0.0\n 100.0, 0.1\n*INELASTIC HEAT FRACTION\n", 1)


def explicit_beam():
    """Explicit: a CPE4T cantilever of 12 x 3 elements (L 12, h 3) clamped at x = 0, its tip moved 0.15 sideways on a
    smooth step over 10 s (its first bending period is 0.66 s: quasi-static) and held 0.5 s; the root yields (first
    yield at a tip deflection of about 0.03) and its plastic heat spreads by conduction. On 2 ranks the plastic zone
    and the heat cross the partition."""
    nx, ny = 12, 3
    nid = lambda i, j: 1 + i + (nx + 1) * j
    nodes = "".join(" %d, %d., %d.\n" % (nid(i, j), i, j) for j in range(ny + 1) for i in range(nx + 1))
    elems = "".join(" %d, %d, %d, %d, %d\n" % (1 + i + nx * j, nid(i, j), nid(i + 1, j), nid(i + 1, j + 1), nid(i, j + 1))
                    for j in range(ny) for i in range(nx))
    root = "".join(" %d,\n" % nid(0, j) for j in range(ny + 1))
    tip = "".join(" %d,\n" % nid(nx, j) for j in range(ny + 1))
    return ("*HEADING\n Explicit: a CPE4T cantilever bent past yield on a smooth step and held\n*NODE, NSET=NALL\n" + nodes +
            "*ELEMENT, TYPE=CPE4T, ELSET=ALL\n" + elems + "*NSET, NSET=ROOT\n" + root + "*NSET, NSET=TIP\n" + tip +
            "*MATERIAL, NAME=STEEL\n*ELASTIC\n %g, %g\n" % (E, NU) + PLASTIC + "*INELASTIC HEAT FRACTION\n 0.9\n"
            "*CONDUCTIVITY\n 50.0\n*DENSITY\n %g\n*SPECIFIC HEAT\n %g\n*SOLID SECTION, ELSET=ALL, MATERIAL=STEEL\n 1.0\n" % (RHO, C) +
            "*INITIAL CONDITIONS, TYPE=TEMPERATURE\n NALL, 0.0\n*AMPLITUDE, NAME=BEND, DEFINITION=SMOOTH STEP\n 0.0, 0.0, 10.0, 1.0\n"
            "*STEP, NAME=BEND\n*DYNAMIC TEMPERATURE-DISPLACEMENT, EXPLICIT\n , 10.5\n*BOUNDARY\n ROOT, 1, 2\n"
            "*BOUNDARY, AMPLITUDE=BEND\n TIP, 2, 2, 0.15\n*OUTPUT, FIELD, NUMBER INTERVAL=20\n*END STEP\n")


def jacobian(kin=False, law=None, typ="C3D8T"):
    """One distorted C3D8T pulled well past yield in two increments (every point flows in both: a point near the yield
    surface would put the finite differences across its kink), heated at a corner, with a modulus and a yield stress
    falling with temperature, expansion and the plastic heat. In millimetres (a brick of about 1000): PETSc's
    finite-difference step is 1.5e-8 of a value but at least 1.5e-6, which on a unit brick would move a point's strain by
    1e-6, a thousandth of its elastic strain, and the differences would measure the return's curvature, not the tangent
    (1e-5 against 1e-8 in millimetres)."""
    corner = [(1000 * a, 1000 * b, 1000 * c) for a, b, c in
              [(0, 0, 0), (1, 0, 0), (1.1, 1.2, 0.1), (0, 1, 0), (0, 0.1, 1), (1.2, 0, 1.1), (1, 1, 1), (-0.1, 1, 0.9)]]
    return ("*HEADING\n A distorted %s pulled past yield and heated: the plastic tangent against finite differences\n" % typ +
            "*NODE, NSET=NALL\n" + "".join(" %d, %g, %g, %g\n" % ((i + 1,) + c) for i, c in enumerate(corner)) +
            ("*ELEMENT, TYPE=%s, ELSET=ALL\n 1, 1, 2, 3, 4, 5, 6, 7, 8\n*NSET, NSET=FIX\n 1, 4, 5, 8\n*NSET, NSET=PULL\n 2, 3, 6, 7\n" % typ) +
            "*MATERIAL, NAME=STEEL\n*ELASTIC\n 200000., 0.3, 0.\n 150000., 0.3, 100.\n" + (law or (PLASTIC_KIN if kin else PLASTIC_SOFT)) +
            "*INELASTIC HEAT FRACTION\n*EXPANSION\n 1.2E-5\n*CONDUCTIVITY\n 50.0\n*DENSITY\n 1.0\n*SPECIFIC HEAT\n 2.0\n"
            "*SOLID SECTION, ELSET=ALL, MATERIAL=STEEL\n*INITIAL CONDITIONS, TYPE=TEMPERATURE\n NALL, 20.0\n"
            "*STEP, INC=10\n*COUPLED TEMPERATURE-DISPLACEMENT, DIRECT\n 0.5, 1.0\n*BOUNDARY\n FIX, 1, 1\n 1, 2, 3\n 4, 3, 3\n"
            " PULL, 1, 1, 40.0\n*CFLUX\n 7, 11, 5.0E6\n*END STEP\n" +
            ("*STEP, INC=10\n*COUPLED TEMPERATURE-DISPLACEMENT, DIRECT\n 0.5, 1.0\n*BOUNDARY\n PULL, 2, 2, 40.0\n*END STEP\n" if kin or law else ""))


# bad decks made from the uniaxial one by one substitution: name -> (text, replacement)
TABLE = "*PLASTIC\n 200.0, 0.0\n 700.0, 0.5\n"
BAD_EDITS = {
    "first_strain": ("*PLASTIC\n 200.0, 0.0\n", "*PLASTIC\n 200.0, 0.001\n"),
    "yield_zero": (" 200.0, 0.0\n", " 0.0, 0.0\n"),
    "descending": (" 700.0, 0.5\n", " 700.0, 0.5\n 800.0, 0.4\n"),
    "combined": ("*PLASTIC\n", "*PLASTIC, HARDENING=COMBINED\n"),
    "combined_count": (TABLE, "*PLASTIC, HARDENING=COMBINED, DATA TYPE=PARAMETERS, NUMBER BACKSTRESSES=2\n 200.0, 40000.0, 400.0\n"),
    "combined_theta": (TABLE, "*PLASTIC, HARDENING=COMBINED, DATA TYPE=PARAMETERS\n 200.0, 40000.0, 400.0, 100.0\n 150.0, 30000.0, 400.0, 0.0\n"),
    "combined_gamma": (TABLE, "*PLASTIC, HARDENING=COMBINED, DATA TYPE=PARAMETERS\n 200.0, 40000.0, -400.0\n"),
    "backstresses": (TABLE, "*PLASTIC, HARDENING=COMBINED, DATA TYPE=PARAMETERS, NUMBER BACKSTRESSES=11\n 200.0, 40000.0, 400.0\n"),
    "data_type_isotropic": ("*PLASTIC\n", "*PLASTIC, DATA TYPE=PARAMETERS\n"),
    "cyclic_isotropic": (TABLE, TABLE + "*CYCLIC HARDENING, PARAMETERS\n 200.0, 50.0, 20.0\n"),
    "cyclic_b": (TABLE, PLASTIC_COMB1 + "*CYCLIC HARDENING, PARAMETERS\n 200.0, 50.0, -20.0\n"),
    "kinematic_lines": (TABLE, "*PLASTIC, HARDENING=KINEMATIC\n 200.0, 0.0\n 700.0, 0.5\n 800.0, 1.0\n"),
    "kinematic_theta": (TABLE, "*PLASTIC, HARDENING=KINEMATIC\n 200.0, 0.0, 0.0\n 700.0, 0.5, 0.0\n 100.0, 0.0, 50.0\n 90.0, 0.5, 50.0\n"),
    "rate": (TABLE, TABLE + "*RATE DEPENDENT, TYPE=YIELD RATIO\n 1.0, 0.0\n 1.5, 10.0\n"),
    "rate_first": (TABLE, "*RATE DEPENDENT\n 0.1, 2.0\n" + TABLE),
    "rate_theta": (TABLE, TABLE + "*RATE DEPENDENT\n 0.1, 2.0, 0.0\n 0.2, 2.0, 100.0\n"),
    "rate_d": (TABLE, TABLE + "*RATE DEPENDENT\n 0.0, 2.0\n"),
    "heat_fraction": ("*CONDUCTIVITY", "*INELASTIC HEAT FRACTION\n 1.5\n*CONDUCTIVITY"),
}


def bad(name):
    base = uniaxial("C3D8T")
    if name in BAD_EDITS:
        return base.replace(*BAD_EDITS[name])
    if name == "shell":
        return base.replace("TYPE=C3D8T", "TYPE=SC8RT").replace("*SOLID SECTION, ELSET=ALL, MATERIAL=STEEL\n 1.0\n", "*SHELL SECTION, ELSET=ALL, MATERIAL=STEEL\n 1.0\n")
    raise KeyError(name)


BAD = ["first_strain", "yield_zero", "descending", "combined", "combined_count", "combined_theta", "backstresses", "data_type_isotropic", "combined_gamma", "cyclic_isotropic", "cyclic_b", "kinematic_lines", "kinematic_theta", "rate", "heat_fraction", "rate_first", "rate_theta", "rate_d"]


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else os.path.join(HERE, "decks")
    decks = {"jacobian_plastic_c3d8t": jacobian(), "jacobian_kinematic_c3d8t": jacobian(True), "adiabatic_kinematic_c3d8t": adiabatic("C3D8T", False, True)}
    for typ in ("C3D8T", "CAX4T"):
        decks["uniaxial_kinematic_%s" % typ.lower()] = uniaxial(typ, True)
        decks["uniaxial_combined_%s" % typ.lower()] = uniaxial(typ, law=PLASTIC_COMB, path=CYCLE)
    decks["uniaxial_combined1_c3d8t"] = uniaxial("C3D8T", law=PLASTIC_COMB1, path=CYCLE)
    decks["adiabatic_combined_c3d8t"] = adiabatic("C3D8T", False, law=PLASTIC_COMB, inc=0.002)
    decks["jacobian_combined_c3d8t"] = jacobian(law=PLASTIC_COMB_SOFT)
    for typ in ("C3D8T", "C3D8RT", "CAX4T"):
        decks["explicit_%s" % typ.lower()] = explicit(typ)
    decks["explicit_combined_c3d8t"] = explicit("C3D8T", PLASTIC_COMB)
    decks["explicit_beam_cpe4t"] = explicit_beam()
    # plane stress
    decks["uniaxial_cps4t"] = uniaxial("CPS4T")
    decks["uniaxial_combined_cps4rt"] = uniaxial("CPS4RT", law=PLASTIC_COMB, path=CYCLE)
    decks["uniaxial_rate_power_cps4t"] = uniaxial("CPS4T", law=PLASTIC + RATE_POWER)
    decks["biaxial_cps4t"] = biaxial("CPS4T")
    decks["explicit_cps4t"] = explicit("CPS4T")
    decks["jacobian_plastic_cps4t"] = jacobian_2d("CPS4T", PLASTIC_SOFT)
    decks["jacobian_combined_cps4t"] = jacobian_2d("CPS4T", PLASTIC_COMB_SOFT)
    decks["cylinder_cpe8rt"] = cylinder("CPE8RT")
    decks["cylinder_cax8rt"] = cylinder("CAX8RT")
    decks["friction_plastic_cpe4t"] = friction_plastic()
    decks["impact_plastic_c3d8t"] = impact_plastic()
    # incompatible modes (CalculiX's mechanical names, read with a temperature)
    decks["uniaxial_c3d8i"] = uniaxial("C3D8I")
    decks["uniaxial_combined_cax4i"] = uniaxial("CAX4I", law=PLASTIC_COMB, path=CYCLE)
    decks["uniaxial_cps4i"] = uniaxial("CPS4I")
    decks["jacobian_combined_c3d8i"] = jacobian(law=PLASTIC_COMB_SOFT, typ="C3D8I")
    decks["jacobian_plastic_cps4i"] = jacobian_2d("CPS4I", PLASTIC_SOFT)
    # continuum shells: the unit cube as one SC8RT (stacked along z), and the distorted brick
    decks["uniaxial_sc8rt"] = bad("shell")
    # (its shear step half the brick's: at 40 one of the five Simpson points ends the step at its yield surface, where the
    # differences cross the kink, 1.2e-3 in that evaluation alone)
    decks["jacobian_plastic_sc8rt"] = (jacobian(law=PLASTIC_SOFT, typ="SC8RT").replace("*SOLID SECTION, ELSET=ALL, MATERIAL=STEEL\n", "*SHELL SECTION, ELSET=ALL, MATERIAL=STEEL\n 1000.0\n")
                                       .replace(" PULL, 2, 2, 40.0\n", " PULL, 2, 2, 20.0\n"))
    # hybrid types: the deviatoric return beside the element's own pressure
    decks["uniaxial_c3d8rht"] = uniaxial("C3D8RHT")
    decks["uniaxial_combined_cax4rht"] = uniaxial("CAX4RHT", law=PLASTIC_COMB, path=CYCLE)
    decks["cylinder_cpe8rht"] = cylinder("CPE8RHT", nu=0.4999)
    decks["cylinder_cax8rht"] = cylinder("CAX8RHT", nu=0.4999)
    decks["jacobian_combined_cpe4rht"] = jacobian_2d("CPE4RHT", PLASTIC_COMB_SOFT)
    decks["uniaxial_cpeg4t"] = uniaxial_gps("CPEG4T")
    decks["uniaxial_kinematic_theta_c3d8t"] = uniaxial_theta("C3D8T", PLASTIC_KIN_THETA)
    decks["uniaxial_combined_theta_cax4t"] = uniaxial_theta("CAX4T", PLASTIC_COMB_THETA)
    decks["jacobian_combined_theta_c3d8t"] = jacobian(law=PLASTIC_COMB_THETA)
    # heated past the table's 100: the run warns at the *PLASTIC line (the end values hold)
    decks["warn_theta_c3d8t"] = uniaxial_theta("C3D8T", PLASTIC_KIN_THETA).replace(" NALL, 11, 11, 100\n", " NALL, 11, 11, 150\n")
    decks["jacobian_plastic_cpeg4t"] = (jacobian_2d("CPEG4T", PLASTIC_SOFT).replace("*NODE, NSET=NALL\n", "*NODE, NSET=REF\n 100, 0.0, 0.0\n*NODE, NSET=NALL\n", 1)
                                        .replace("MATERIAL=STEEL\n 10.0", "MATERIAL=STEEL, REF NODE=100\n 10.0")
                                        .replace(" FIX, 1, 1\n", " FIX, 1, 1\n REF, 3, 5\n", 1))
    # (the reference node held: with its length change free, the free unknowns' block agrees to 1e-8 but the whole
    # matrix parts by 2e-4 in the prescribed unknowns' rows and columns, which the check would count, docs/elements.md
    # "Plasticity"; the uniaxial deck checks the free length change's return exactly)
    decks["uniaxial_rate_power_c3d8t"] = uniaxial("C3D8T", law=PLASTIC + RATE_POWER)
    decks["uniaxial_rate_jc_cax4t"] = uniaxial("CAX4T", law=PLASTIC + RATE_JC)
    decks["explicit_rate_power_c3d8t"] = explicit("C3D8T", PLASTIC + RATE_POWER, period=0.2)
    decks["jacobian_rate_c3d8t"] = jacobian(law=PLASTIC_SOFT + RATE_POWER)
    for typ in ("C3D8T", "C3D8RT", "C3D20T", "CAX4T"):
        decks["uniaxial_%s" % typ.lower()] = uniaxial(typ)
    for typ in ("C3D8T", "CAX4T"):
        decks["adiabatic_%s" % typ.lower()] = adiabatic(typ, False)
    decks["adiabatic_soft_c3d8t"] = adiabatic("C3D8T", True)
    for b in BAD:
        decks["bad_%s" % b] = bad(b)
    for name, text in decks.items():
        with open(os.path.join(out, name + ".inp"), "w") as f:
            f.write(text)


if __name__ == "__main__":
    main()
