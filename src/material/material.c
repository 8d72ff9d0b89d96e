/* Evaluation of temperature tables (see include/thermoslide/material.h). */
#include <thermoslide/material.h>

/* Row interval of theta: the last row i with theta_i <= theta, clamped to [0, n-2]. Tables are short
 * (a few rows), so a linear scan is the fastest search. */
static PetscInt Interval(const TslPropertyTable *tab, PetscReal theta)
{
  PetscInt i = 0;
  while (i + 2 < tab->n && theta >= tab->theta[i + 1]) i++;
  return i;
}

PetscReal TslPropertyEval(const TslPropertyTable *tab, PetscInt col, PetscReal theta, PetscReal *dvalue)
{
  PetscInt  i;
  PetscReal s;

  if (dvalue) *dvalue = 0;
  if (tab->n <= 0) return 0;
  if (tab->n == 1 || theta <= tab->theta[0]) return tab->value[0][col];
  if (theta >= tab->theta[tab->n - 1]) return tab->value[tab->n - 1][col];
  i = Interval(tab, theta);
  s = (tab->value[i + 1][col] - tab->value[i][col]) / (tab->theta[i + 1] - tab->theta[i]);
  if (dvalue) *dvalue = s;
  return tab->value[i][col] + s * (theta - tab->theta[i]);
}

void TslMaterialEval(const TslMaterial *mat, PetscReal theta, TslMaterialPoint *mp)
{
  mp->E     = TslPropertyEval(&mat->prop[TSL_PROP_ELASTIC], 0, theta, &mp->dE);
  mp->nu    = TslPropertyEval(&mat->prop[TSL_PROP_ELASTIC], 1, theta, &mp->dnu);
  mp->k     = TslPropertyEval(&mat->prop[TSL_PROP_CONDUCTIVITY], 0, theta, &mp->dk);
  mp->rho   = TslPropertyEval(&mat->prop[TSL_PROP_DENSITY], 0, theta, NULL);
  mp->c     = TslPropertyEval(&mat->prop[TSL_PROP_SPECIFIC_HEAT], 0, theta, &mp->dc);
  mp->alpha = TslPropertyEval(&mat->prop[TSL_PROP_EXPANSION], 0, theta, &mp->dalpha);
}

/* Integral of the piecewise linear c from 0 to theta: the sum of trapezoids between the breakpoints. */
static PetscReal IntegralTo(const TslPropertyTable *tab, PetscReal theta)
{
  PetscReal a = 0, e = 0, ca = TslPropertyEval(tab, 0, 0, NULL);
  PetscReal sign = theta >= 0 ? 1 : -1, lo = PetscMin(0, theta), hi = PetscMax(0, theta);

  /* from lo to hi through every breakpoint in between */
  a  = lo;
  ca = TslPropertyEval(tab, 0, a, NULL);
  for (PetscInt i = 0; i < tab->n; i++) {
    PetscReal b = tab->theta[i];
    if (b <= a || b >= hi) continue;
    {
      PetscReal cb = TslPropertyEval(tab, 0, b, NULL);
      e += 0.5 * (ca + cb) * (b - a);
      a = b, ca = cb;
    }
  }
  e += 0.5 * (ca + TslPropertyEval(tab, 0, hi, NULL)) * (hi - a);
  return sign * e;
}

PetscReal TslMaterialHeatContent(const TslMaterial *mat, PetscReal theta, PetscReal *c)
{
  const TslPropertyTable *tab = &mat->prop[TSL_PROP_SPECIFIC_HEAT];

  if (c) *c = TslPropertyEval(tab, 0, theta, NULL);
  if (tab->n <= 1) return TslPropertyEval(tab, 0, theta, NULL) * theta;
  return IntegralTo(tab, theta);
}

PetscReal TslMaterialThermalStrain(const TslMaterial *mat, PetscReal theta, PetscReal theta_init, PetscReal *deps)
{
  const TslPropertyTable *tab = &mat->prop[TSL_PROP_EXPANSION];
  PetscReal               da, a = TslPropertyEval(tab, 0, theta, &da), ai = TslPropertyEval(tab, 0, theta_init, NULL);
  const PetscReal         t0 = mat->alpha_zero;

  if (deps) *deps = a + da * (theta - t0);
  return a * (theta - t0) - ai * (theta_init - t0);
}

PetscBool TslMaterialIsTemperatureDependent(const TslMaterial *mat)
{
  for (PetscInt k = 0; k < TSL_NPROP; k++)
    if (mat->prop[k].n > 1) return PETSC_TRUE;
  return PETSC_FALSE;
}
