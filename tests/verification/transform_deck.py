#!/usr/bin/python3
"""Writes a copy of a verification deck moved and re-expressed in another length unit.

usage: transform_deck.py IN.inp OUT.inp DX DY SCALE [HEAT FORCE]

Coordinates become SCALE * (x, y) + (DX, DY) (DX, DY in the new unit). SCALE = 1000 re-expresses a deck
in N, m, s, J, K in kN, mm, s, J, K: the energy unit kN*mm = N*m = J, the time and temperature units
are unchanged, so temperatures, heat rates and heat totals keep their numbers and displacements are
multiplied by SCALE. With s = SCALE the other quantities convert as

  length, displacement, thickness, clearance        * s
  force (*CLOAD)                                   / s        (kN = 1000 N)
  stress, pressure (*ELASTIC E, *DLOAD P, k(p) args) / s^3    (kN/mm^2 = 1e9 Pa)
  heat flux per area (*DFLUX S, *DSFLUX), film (*FILM, *SFILM) and gap
  conductance (per area and degree), sigma          / s^2      (W/mm^2 = 1e6 W/m^2)
  conductivity (W per length and degree)            / s
  density                                           / s^5      (mass unit kN s^2/mm = 1e6 kg)
  specific heat                                     * s^2      (so rho c, J per volume and degree, / s^3)
  a shell section's THICKNESS MODULUS=           / s^3;  its number of points unchanged
  Poisson's ratio, expansion, friction coefficient, heat generation fractions, smoothing, point heat
  (*CFLUX, W), temperatures, times, amplitudes      unchanged

HEAT and FORCE (default 1) re-express the result in other energy units besides: every heat number (heat
rate, flux, film, conductivity, gap conductance, sigma, heat totals) is multiplied by HEAT, every force
number (force, stress, pressure, stick slope, the pressure arguments of k(p)) by FORCE, density by FORCE
(the mass unit, with length and time kept) and specific heat by HEAT / FORCE, so temperatures and
displacements keep their numbers while the two fields' residuals move HEAT / FORCE apart in scale (the
per-field convergence test, tests/verification/CMakeLists.txt). Frictional heating turns work into heat, so
a deck with *GAP HEAT GENERATION takes HEAT = FORCE only.

Only the keywords the sliding decks use are converted; any other keyword with data lines is an error,
so that a new deck cannot be converted silently wrong.
"""
import sys

PASS = {"*HEADING", "*ELSET", "*NSET", "*SURFACE", "*MATERIAL", "*EXPANSION", "*SURFACE INTERACTION",
        "*GAP HEAT GENERATION", "*CONTACT PAIR", "*AMPLITUDE", "*INITIAL CONDITIONS", "*EQUATION", "*STEP",
        "*COUPLED TEMPERATURE-DISPLACEMENT", "*END STEP", "*ELEMENT", "*NODE OUTPUT", "*ELEMENT OUTPUT",
        "*NODE PRINT", "*EL PRINT", "*SURFACE BEHAVIOR",
        # explicit steps: times, factors and the bulk viscosity's coefficients are unit-free here
        "*DYNAMIC TEMPERATURE-DISPLACEMENT", "*FIXED MASS SCALING", "*VARIABLE MASS SCALING", "*BULK VISCOSITY"}


def num(v):
    return "%.17g" % v


def convert(keyword, options, fields, s, dx, dy, heat=1.0, force=1.0):
    """Data line (list of strings) of a keyword -> converted fields."""
    f = [x.strip() for x in fields]
    if keyword == "*GAP HEAT GENERATION" and heat != force:
        raise SystemExit("transform_deck.py: frictional heating ties the heat unit to the force unit (HEAT = FORCE)")
    if keyword == "*NODE":
        f[1] = num(float(f[1]) * s + dx)
        f[2] = num(float(f[2]) * s + dy)
        if len(f) > 3 and f[3]:
            f[3] = num(float(f[3]) * s)
    elif keyword == "*ELASTIC":
        f[0] = num(float(f[0]) / s**3 * force)
    elif keyword == "*CONDUCTIVITY":
        f[0] = num(float(f[0]) / s * heat)
    elif keyword == "*DENSITY":
        f[0] = num(float(f[0]) / s**5 * force)
    elif keyword == "*SPECIFIC HEAT":
        f[0] = num(float(f[0]) * s**2 * heat / force)
    elif keyword in ("*SOLID SECTION", "*SHELL SECTION"):  # thickness; a shell's point count unchanged
        if f and f[0]:
            f[0] = num(float(f[0]) * s)
    elif keyword == "*GAP CONDUCTANCE":
        f[0] = num(float(f[0]) / s**2 * heat)
        if len(f) > 1 and f[1]:
            f[1] = num(float(f[1]) / s**3 * force if "PRESSURE" in options else float(f[1]) * s)
    elif keyword == "*GAP RADIATION":
        if "first" not in options:  # clearance, view factor
            f[0] = num(float(f[0]) * s)
    elif keyword == "*FRICTION":
        if len(f) > 1 and f[1]:  # stick slope: stress per length
            f[1] = num(float(f[1]) / s**4 * force)
    elif keyword == "*CLOAD":
        f[2] = num(float(f[2]) / s * force)
    elif keyword == "*BOUNDARY":
        first = int(f[1])
        if len(f) > 3 and f[3] and first <= 3:
            f[3] = num(float(f[3]) * s)
    elif keyword == "*DLOAD":
        f[2] = num(float(f[2]) / s**3 * force)
    elif keyword == "*DFLUX":
        f[2] = num(float(f[2]) / s**2 * heat)
    elif keyword == "*FILM":
        f[3] = num(float(f[3]) / s**2 * heat)
    elif keyword == "*DSFLUX":  # surface, S, flux per area
        f[2] = num(float(f[2]) / s**2 * heat)
    elif keyword == "*SFILM":  # surface, F, sink temperature, film coefficient
        f[3] = num(float(f[3]) / s**2 * heat)
    elif keyword == "*CFLUX":
        f[2] = num(float(f[2]) * heat)
    elif keyword not in PASS:
        raise SystemExit("transform_deck.py: do not know how to convert the data of %s" % keyword)
    return f


def main():
    src, dst, dx, dy, s = sys.argv[1], sys.argv[2], float(sys.argv[3]), float(sys.argv[4]), float(sys.argv[5])
    heat, force = (float(v) for v in sys.argv[6:8]) if len(sys.argv) > 7 else (1.0, 1.0)
    out, keyword, options = [], None, set()
    for line in open(src):
        text = line.rstrip("\n")
        if text.startswith("**"):
            out.append(text)
            continue
        if text.startswith("*"):
            parts = [p.strip().upper() for p in text.split(",")]
            keyword, options = parts[0], set(parts[1:])
            if keyword == "*PHYSICAL CONSTANTS":
                items = []
                for p in text.split(",")[1:]:
                    k, v = p.split("=")
                    if k.strip().upper() == "STEFAN BOLTZMANN":
                        v = num(float(v) / s**2 * heat)
                    items.append("%s=%s" % (k.strip(), v.strip()))
                text = "*PHYSICAL CONSTANTS, " + ", ".join(items)
            if keyword == "*GAP RADIATION":
                options.add("first")
            if keyword == "*SHELL SECTION":  # THICKNESS MODULUS= is a stress
                items = text.split(",")
                for i, p in enumerate(items):
                    if "=" in p and p.split("=")[0].strip().upper() == "THICKNESS MODULUS":
                        items[i] = " THICKNESS MODULUS=%s" % num(float(p.split("=")[1]) / s**3 * force)
                text = ",".join(items)
            out.append(text)
            continue
        if keyword is None or not text.strip():
            out.append(text)
            continue
        out.append(" " + ", ".join(convert(keyword, options, text.split(","), s, dx, dy, heat, force)))
        options.discard("first")
    with open(dst, "w") as fh:
        fh.write("\n".join(out) + "\n")


if __name__ == "__main__":
    main()
