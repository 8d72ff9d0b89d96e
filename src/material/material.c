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
  for (PetscInt i = 1; i < mat->plastic.n; i++)
    if (mat->plastic.row[i][2] != mat->plastic.row[0][2]) return PETSC_TRUE;
  return mat->plastic.nvoce > 1 || mat->plastic.nkt > 1 ? PETSC_TRUE : PETSC_FALSE;
}

/* The exponential law's parameters at theta (*CYCLIC HARDENING, PARAMETERS: rows sigma_0, Q, b, temperature; linear
 * between the rows' temperatures, the end rows held beyond) and their derivatives in theta. */
static void VoceAt(const TslPlasticTable *t, PetscReal theta, PetscReal v[3], PetscReal dv[3])
{
  PetscInt k = 0;

  for (PetscInt i = 0; i < 3; i++) v[i] = t->voce[0][i], dv[i] = 0;
  if (t->nvoce < 2 || theta <= t->voce[0][3]) return;
  while (k + 2 < t->nvoce && theta > t->voce[k + 1][3]) k++;
  if (theta >= t->voce[t->nvoce - 1][3]) {
    for (PetscInt i = 0; i < 3; i++) v[i] = t->voce[t->nvoce - 1][i];
    return;
  }
  {
    const PetscReal dt = t->voce[k + 1][3] - t->voce[k][3], w = (theta - t->voce[k][3]) / dt;
    for (PetscInt i = 0; i < 3; i++) v[i] = (1 - w) * t->voce[k][i] + w * t->voce[k + 1][i], dv[i] = (t->voce[k + 1][i] - t->voce[k][i]) / dt;
  }
}

void TslMaterialBackStress(const TslMaterial *mat, PetscReal theta, PetscReal C[], PetscReal gamma[], PetscReal dC[], PetscReal dgamma[])
{
  const TslPlasticTable *t = &mat->plastic;
  PetscInt               k = 0;

  for (PetscInt b = 0; b < t->nback; b++) C[b] = t->kt_C[0][b], gamma[b] = t->kt_gamma[0][b], dC[b] = dgamma[b] = 0;
  if (t->nkt < 2) return;
  if (theta <= t->kt_theta[0] || theta >= t->kt_theta[t->nkt - 1]) {
    const PetscInt e = theta <= t->kt_theta[0] ? 0 : t->nkt - 1;
    for (PetscInt b = 0; b < t->nback; b++) C[b] = t->kt_C[e][b], gamma[b] = t->kt_gamma[e][b];
    return;
  }
  while (k + 2 < t->nkt && theta > t->kt_theta[k + 1]) k++;
  {
    const PetscReal dt = t->kt_theta[k + 1] - t->kt_theta[k], w = (theta - t->kt_theta[k]) / dt;
    for (PetscInt b = 0; b < t->nback; b++) {
      C[b]      = (1 - w) * t->kt_C[k][b] + w * t->kt_C[k + 1][b];
      gamma[b]  = (1 - w) * t->kt_gamma[k][b] + w * t->kt_gamma[k + 1][b];
      dC[b]     = (t->kt_C[k + 1][b] - t->kt_C[k][b]) / dt;
      dgamma[b] = (t->kt_gamma[k + 1][b] - t->kt_gamma[k][b]) / dt;
    }
  }
}

PetscReal TslMaterialRateFactor(const TslMaterial *mat, PetscReal r, PetscReal *dR)
{
  const TslPlasticTable *t = &mat->plastic;

  *dR = 0;
  if (t->rate_law == 1) { /* 1 + (r / D)^(1 / n) */
    const PetscReal x = r / t->rate[0], e = 1 / t->rate[1];
    if (!(x > 0)) {
      *dR = e == 1 ? 1 / t->rate[0] : (e < 1 ? 0 : PETSC_MAX_REAL / 1e10);
      return 1;
    }
    *dR = e * PetscPowReal(x, e - 1) / t->rate[0];
    return 1 + PetscPowReal(x, e);
  }
  if (t->rate_law == 2 && r > t->rate[1]) { /* 1 + C ln(r / rate_0) above rate_0 */
    *dR = t->rate[0] / r;
    return 1 + t->rate[0] * PetscLogReal(r / t->rate[1]);
  }
  return 1;
}

/* (1 - exp(-x)) / x and (1 - exp(-x) (1 + x)) / x^2 = int_0^1 s exp(-x s) ds, without their cancellation near 0 */
static PetscReal Phi1(PetscReal x)
{
  return x < 1e-8 ? 1 - 0.5 * x : -expm1(-x) / x;
}
static PetscReal Phi2(PetscReal x)
{
  return x < 1e-3 ? 0.5 - x / 3 + x * x / 8 - x * x * x / 30 : (-expm1(-x) - x * PetscExpReal(-x)) / (x * x);
}

/* One temperature's curve (rows s..e-1): sigma_y at peeq and its slope. */
static PetscReal Curve(const PetscReal (*row)[3], PetscInt s, PetscInt e, PetscReal peeq, PetscReal *H)
{
  PetscInt k = s;

  *H = 0;
  if (peeq >= row[e - 1][1]) return row[e - 1][0];
  if (peeq <= row[s][1]) {
    if (e - s > 1) *H = (row[s + 1][0] - row[s][0]) / (row[s + 1][1] - row[s][1]); /* the first segment's slope at its start */
    return row[s][0];
  }
  while (k + 2 < e && peeq >= row[k + 1][1]) k++;
  *H = (row[k + 1][0] - row[k][0]) / (row[k + 1][1] - row[k][1]);
  return row[k][0] + *H * (peeq - row[k][1]);
}

PetscReal TslMaterialYield(const TslMaterial *mat, PetscReal peeq, PetscReal theta, PetscReal *H, PetscReal *dtheta)
{
  const TslPlasticTable *t = &mat->plastic;
  PetscInt               g0 = 0, g1, g2;
  PetscReal              h0, h1, s0, s1, w;

  if (dtheta) *dtheta = 0;
  if (t->nvoce) { /* sigma_0 + Q (1 - exp(-b p)) */
    PetscReal v[3], dv[3], e;
    VoceAt(t, theta, v, dv);
    e = PetscExpReal(-v[2] * peeq);
    if (H) *H = v[1] * v[2] * e;
    if (dtheta) *dtheta = dv[0] + dv[1] * (1 - e) + v[1] * peeq * e * dv[2];
    return v[0] + v[1] * (1 - e);
  }
  /* groups of equal temperature: [g0, g1) the last one at or below theta (or the first), [g1, g2) the next */
  for (;;) {
    g1 = g0 + 1;
    while (g1 < t->n && t->row[g1][2] == t->row[g0][2]) g1++;
    if (g1 >= t->n || theta < t->row[g1][2]) break;
    g0 = g1;
  }
  s0 = Curve(t->row, g0, g1, peeq, &h0);
  if (g1 >= t->n || theta <= t->row[g0][2]) {
    if (H) *H = h0;
    return s0;
  }
  g2 = g1 + 1;
  while (g2 < t->n && t->row[g2][2] == t->row[g1][2]) g2++;
  s1 = Curve(t->row, g1, g2, peeq, &h1);
  w  = (theta - t->row[g0][2]) / (t->row[g1][2] - t->row[g0][2]);
  if (H) *H = (1 - w) * h0 + w * h1;
  if (dtheta) *dtheta = (s1 - s0) / (t->row[g1][2] - t->row[g0][2]);
  return (1 - w) * s0 + w * s1;
}

/* int_a^b of one temperature's curve (rows s..e-1; a <= b): the trapezoids between its breakpoints, the last value
 * held beyond the last point */
static PetscReal CurveIntegral(const PetscReal (*row)[3], PetscInt s, PetscInt e, PetscReal a, PetscReal b)
{
  PetscReal H, x = a, fx = Curve(row, s, e, a, &H), sum = 0;

  for (PetscInt k = s; k < e; k++) {
    const PetscReal y = row[k][1];
    if (y <= x || y >= b) continue;
    sum += 0.5 * (fx + row[k][0]) * (y - x);
    x = y, fx = row[k][0];
  }
  return sum + 0.5 * (fx + Curve(row, s, e, b, &H)) * (b - x);
}

PetscReal TslMaterialYieldIntegral(const TslMaterial *mat, PetscReal p0, PetscReal p1, PetscReal theta, PetscReal *dtheta)
{
  const TslPlasticTable *t = &mat->plastic;
  PetscInt               g0 = 0, g1, g2;
  PetscReal              i0, i1, w;

  if (dtheta) *dtheta = 0;
  if (t->nvoce) { /* int (1 - exp(-b p)) dp = D (1 - e0 Phi1(b D)), its b-derivative int p exp(-b p) dp = e0 (p0 D Phi1 + D^2 Phi2) */
    PetscReal       v[3], dv[3];
    const PetscReal D = p1 - p0;
    VoceAt(t, theta, v, dv);
    {
      const PetscReal e0 = PetscExpReal(-v[2] * p0), f1 = Phi1(v[2] * D), F = D * (1 - e0 * f1);
      if (dtheta) *dtheta = dv[0] * D + dv[1] * F + v[1] * e0 * (p0 * D * f1 + D * D * Phi2(v[2] * D)) * dv[2];
      return v[0] * D + v[1] * F;
    }
  }
  for (;;) { /* the groups of TslMaterialYield */
    g1 = g0 + 1;
    while (g1 < t->n && t->row[g1][2] == t->row[g0][2]) g1++;
    if (g1 >= t->n || theta < t->row[g1][2]) break;
    g0 = g1;
  }
  i0 = CurveIntegral(t->row, g0, g1, p0, p1);
  if (g1 >= t->n || theta <= t->row[g0][2]) return i0;
  g2 = g1 + 1;
  while (g2 < t->n && t->row[g2][2] == t->row[g1][2]) g2++;
  i1 = CurveIntegral(t->row, g1, g2, p0, p1);
  w  = (theta - t->row[g0][2]) / (t->row[g1][2] - t->row[g0][2]);
  if (dtheta) *dtheta = (i1 - i0) / (t->row[g1][2] - t->row[g0][2]);
  return (1 - w) * i0 + w * i1;
}
