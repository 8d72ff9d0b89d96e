/* thermoslide materials: the properties of a TslMaterial (model.h) evaluated at a temperature.
 *
 * Each property is a table in temperature (one row: a constant); between rows it is linear and beyond
 * the ends constant, as in the dialect. Evaluation returns the values and their derivatives in theta,
 * so element kernels get exact tangents of temperature-dependent properties. Plain functions on plain
 * data: no MPI, no PETSc objects.
 *
 * Definitions the kernels rely on (Abaqus Analysis User's Guide, "Thermal expansion"; "Specific heat"):
 *   thermal strain   eps_th(theta) = alpha(theta) (theta - theta_0) - alpha(theta_I) (theta_I - theta_0)
 *                    with theta_0 = ZERO= and theta_I the initial temperature of the point;
 *   heat content     e(theta) = int_0^theta c(s) ds per unit mass (exact for the piecewise linear c),
 *                    so the heat stored between two states is rho (e(theta) - e(theta_old)) whatever the
 *                    temperature dependence, and a heat balance closes exactly.
 */
#pragma once
#include <thermoslide/model.h>

/* Properties at one temperature and their derivatives d/dtheta. */
typedef struct {
  PetscReal E, nu, k, rho, c, alpha;
  PetscReal dE, dnu, dk, dc, dalpha;
} TslMaterialPoint;

/* Value (and derivative, may be NULL) of column col of a property table at theta. */
PetscReal TslPropertyEval(const TslPropertyTable *tab, PetscInt col, PetscReal theta, PetscReal *dvalue);

void TslMaterialEval(const TslMaterial *mat, PetscReal theta, TslMaterialPoint *mp);

/* Heat content per unit mass e(theta) = int_0^theta c ds and de/dtheta = c(theta). */
PetscReal TslMaterialHeatContent(const TslMaterial *mat, PetscReal theta, PetscReal *c);

/* Thermal strain (isotropic, per normal component) at theta for a point whose initial temperature is
 * theta_init, and its derivative in theta. */
PetscReal TslMaterialThermalStrain(const TslMaterial *mat, PetscReal theta, PetscReal theta_init, PetscReal *deps);

/* The Mises yield stress of *PLASTIC at equivalent plastic strain peeq and temperature theta, its slope H =
 * d sigma_y / d peeq and d sigma_y / d theta (either may be NULL): linear between the table's points, the last
 * point's stress held beyond it (perfect plasticity), the end temperatures' curves held outside their range. */
PetscReal TslMaterialYield(const TslMaterial *mat, PetscReal peeq, PetscReal theta, PetscReal *H, PetscReal *dtheta);
/* The rate dependence of the yield stress (*RATE DEPENDENT): the factor R on the static yield stress at the plastic
 * strain rate r >= 0 and dR/dr (1 and 0 without rate dependence; dR/dr is infinite at r = 0 for the power law of
 * n > 1: returned as a large finite number). */
PetscReal TslMaterialRateFactor(const TslMaterial *mat, PetscReal r, PetscReal *dR);
/* The plastic work of a flow from p0 to p1 >= p0 at theta, int_p0^p1 sigma_y(p, theta) dp (exact for the table's
 * piecewise linear curves), and its derivative in theta. */
PetscReal TslMaterialYieldIntegral(const TslMaterial *mat, PetscReal p0, PetscReal p1, PetscReal theta, PetscReal *dtheta);
static inline PetscBool TslMaterialIsPlastic(const TslMaterial *mat)
{
  return mat->plastic.n > 0 || mat->plastic.nvoce > 0 ? PETSC_TRUE : PETSC_FALSE;
}
/* Reals of the plastic state at a point: the plastic strain (Voigt, engineering shear) and the equivalent plastic
 * strain, then each back stress (Voigt, tensor components; none with isotropic hardening). */
static inline PetscInt TslMaterialPlasticState(const TslMaterial *mat)
{
  return 7 + 6 * mat->plastic.nback + (mat->plastic.nkt > 1 ? 2 : 0); /* + (committed, its temperature) with temperature-dependent back stresses */
}
/* The back stresses' moduli C_k and recoveries gamma_k at theta and their theta-derivatives (constant unless the
 * kinematic data depend on temperature: linear between their temperatures, the ends held). */
void TslMaterialBackStress(const TslMaterial *mat, PetscReal theta, PetscReal C[], PetscReal gamma[], PetscReal dC[], PetscReal dgamma[]);

/* True when any property varies with temperature (the kernels then add the property-derivative terms). */
PetscBool TslMaterialIsTemperatureDependent(const TslMaterial *mat);
