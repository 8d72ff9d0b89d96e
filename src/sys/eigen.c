/* Largest eigenvalue of a small dense symmetric matrix, from above (sys.h, TslLargestEigenvalue).
 *
 * The matrix is reduced to tridiagonal form by Householder reflections (S <- H S H, H = I - beta v v^T,
 * applied as S <- S - v p^T - p v^T), whose eigenvalues are S's own to rounding; the largest lies between
 * the largest diagonal entry and Gershgorin's bound, and is bracketed by multisection on the Sturm count (the
 * number of negative pivots of T - x I is the number of eigenvalues below x). The bracket's upper end is
 * returned, so a stable increment computed from it is never too long. The explicit procedure takes one per
 * element and field (dynamics.c); LAPACK's syev, which computes all eigenvalues, was most of an explicit
 * step's set-up (88 s for a million C3D8T elements). */
#include <thermoslide/sys.h>

/* How many of the points x[0..M-1] have every eigenvalue of the symmetric tridiagonal matrix (diagonal
 * d[n], squared off-diagonal e2[n-1]) below them: the Sturm count, the number of negative pivots of
 * T - x I, equals n. The M recurrences run side by side: each is a chain of dependent divisions, so
 * interleaved they cost about what one costs alone. */
#define M 8
static PetscInt CountAbove(PetscInt n, const PetscReal d[], const PetscReal e2[], const PetscReal x[M])
{
  PetscReal q[M];
  PetscInt  count[M], above = 0;

  for (PetscInt m = 0; m < M; m++) q[m] = d[0] - x[m], count[m] = 0;
  for (PetscInt i = 0;; i++) {
    for (PetscInt m = 0; m < M; m++) {
      if (q[m] == 0) q[m] = -PETSC_SMALL * (PetscAbsReal(x[m]) + PETSC_SMALL); /* a zero pivot: perturbed, counted as below */
      count[m] += q[m] < 0 ? 1 : 0;
    }
    if (i == n - 1) break;
    for (PetscInt m = 0; m < M; m++) q[m] = d[i + 1] - x[m] - e2[i] / q[m];
  }
  for (PetscInt m = 0; m < M; m++) above += count[m] == n ? 1 : 0;
  return above;
}

PetscReal TslLargestEigenvalue(PetscInt n, PetscReal S[])
{
  PetscReal d[TSL_EIGEN_MAX_N] = {0}, e2[TSL_EIGEN_MAX_N] = {0}, lo, hi;

  if (n <= 0) return 0;
  if (n > TSL_EIGEN_MAX_N) return PETSC_MAX_REAL; /* (callers stay within: element blocks of at most TSL_MAX_ELEM_DOF) */

  for (PetscInt k = 0; k + 2 < n; k++) { /* annihilate column k below the subdiagonal */
    PetscReal      v[TSL_EIGEN_MAX_N], p[TSL_EIGEN_MAX_N], norm = 0, alpha, vtv = 0, beta, vp = 0, K;
    const PetscInt m0 = k + 1;
    for (PetscInt i = m0; i < n; i++) norm += S[i * n + k] * S[i * n + k];
    norm  = PetscSqrtReal(norm);
    alpha = S[m0 * n + k] > 0 ? -norm : norm;
    for (PetscInt i = m0; i < n; i++) v[i] = S[i * n + k];
    v[m0] -= alpha;
    for (PetscInt i = m0; i < n; i++) vtv += v[i] * v[i];
    S[m0 * n + k] = S[k * n + m0] = alpha;
    for (PetscInt i = m0 + 1; i < n; i++) S[i * n + k] = S[k * n + i] = 0;
    if (vtv == 0) continue; /* already reduced */
    beta = 2.0 / vtv;
    for (PetscInt i = m0; i < n; i++) { /* p = beta S22 v */
      PetscReal sum = 0;
      for (PetscInt j = m0; j < n; j++) sum += S[i * n + j] * v[j];
      p[i] = beta * sum, vp += v[i] * p[i];
    }
    K = 0.5 * beta * vp;
    for (PetscInt i = m0; i < n; i++) p[i] -= K * v[i]; /* S22 <- S22 - v p^T - p v^T */
    for (PetscInt i = m0; i < n; i++)
      for (PetscInt j = m0; j < n; j++) S[i * n + j] -= v[i] * p[j] + p[i] * v[j];
  }
  for (PetscInt i = 0; i < n; i++) d[i] = S[i * n + i];
  for (PetscInt i = 0; i + 1 < n; i++) e2[i] = S[(i + 1) * n + i] * S[(i + 1) * n + i];
  lo = hi = d[0];
  for (PetscInt i = 0; i < n; i++) { /* the largest lies between the largest diagonal entry and Gershgorin's bound */
    const PetscReal r = (i > 0 ? PetscAbsReal(S[i * n + i - 1]) : 0) + (i + 1 < n ? PetscAbsReal(S[(i + 1) * n + i]) : 0);
    lo = PetscMax(lo, d[i]), hi = PetscMax(hi, d[i] + r);
  }
  hi += 1e-12 * (PetscAbsReal(hi) + PetscAbsReal(lo)); /* above the bound's rounding */
  for (PetscInt it = 0; it < 100 && hi - lo > 1e-12 * PetscMax(PetscAbsReal(hi), PetscAbsReal(lo)); it++) {
    /* multisection: M points split [lo, hi] into M + 1 parts; the count is monotone in x, so the points
     * above every eigenvalue are the last `above` ones */
    PetscReal x[M];
    PetscInt  above;
    for (PetscInt m = 0; m < M; m++) x[m] = lo + (hi - lo) * (m + 1) / (M + 1);
    above = CountAbove(n, d, e2, x);
    if (above > 0) hi = x[M - above];
    if (above < M) lo = x[M - above - 1];
  }
  return hi;
}
