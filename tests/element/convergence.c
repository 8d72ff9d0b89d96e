/* Convergence of every continuum type of the catalogue on a manufactured steady coupled solution.
 *
 * u(x) and theta(x) are sums of plane waves; the body force b and heat source q that make them exact
 * solutions of
 *   div sigma + b = 0,  sigma = D (eps - alpha (theta - theta_init) m),   -div(k grad theta) = q
 * are derived by hand for each kinematics (plane strain, plane stress with its condensed D, axisymmetric
 * with the hoop terms, 3D) and integrated against the element's shape functions with a high-order rule
 * (F_a = int N_a b dV, Q_a = int N_a q dV; the kernels' body flux takes one value per element). The exact solution is
 * prescribed on the whole boundary (row elimination), the coupled system assembled from
 * TslElementInternal and solved by LU on three refinements of a structured mesh of the type: the unit
 * square (axisymmetric: r in [1, 2], z in [0, 1]) or cube. L2 and H1-seminorm errors of u and theta and
 * their rates are printed; the rate between the two finest meshes must reach the order of the family:
 *   linear (and reduced-integration) types   L2 >= 1.8, H1 >= 0.85
 *   quadratic types                           L2 >= 2.7, H1 >= 1.8
 * The types come from the catalogue table, so a new row is tested without touching this file. */
#include "grid.h"
#include <time.h>

#define NLEVEL 3
#define NPD    5 /* Gauss points per direction of the load and error integrals */

static const PetscReal E = 100, NU = 0.3, K = 2, ALPHA = 0.02, THETA_INIT = 0.5;

/* f(x) = sum of a sin(k . x + phase) */
typedef struct {
  PetscReal a, k[3], phase;
} Wave;

/* u_x, u_y, u_z, theta: wave numbers of order 1 on the unit box, so that two quadratic cells per side
 * are already near the asymptotic range; the z terms vanish on 2D meshes (z = 0). */
static const Wave Exact[4][2] = {
    {{0.10, {1.2, 0.8, 0.6}, 0.4}, {0.05, {-0.7, 1.5, 0.9}, 1.1}},
    {{0.08, {0.9, -1.1, 0.7}, 0.2}, {0.06, {1.4, 0.5, -0.8}, 2.0}},
    {{0.07, {0.6, 1.0, -1.3}, 0.9}, {0.05, {-1.2, 0.4, 1.1}, 0.3}},
    {{1.00, {1.3, 0.9, -0.7}, 0.5}, {0.60, {-0.8, 1.6, 1.0}, 1.7}},
};

/* Value, gradient and Hessian of one field. */
static void Field(PetscInt c, const PetscReal x[3], PetscReal *f, PetscReal g[3], PetscReal H[3][3])
{
  *f = 0;
  for (PetscInt i = 0; i < 3; i++) {
    g[i] = 0;
    for (PetscInt j = 0; j < 3; j++) H[i][j] = 0;
  }
  for (PetscInt m = 0; m < 2; m++) {
    const Wave *w   = &Exact[c][m];
    PetscReal   arg = w->phase;
    for (PetscInt i = 0; i < 3; i++) arg += w->k[i] * x[i];
    *f += w->a * PetscSinReal(arg);
    for (PetscInt i = 0; i < 3; i++) {
      g[i] += w->a * w->k[i] * PetscCosReal(arg);
      for (PetscInt j = 0; j < 3; j++) H[i][j] -= w->a * w->k[i] * w->k[j] * PetscSinReal(arg);
    }
  }
}

/* In-plane moduli of the kinematics: sigma = lambda tr(eps) 1 + 2 mu eps - beta (theta - theta_init) 1.
 * Plane strain and 3D: beta = (3 lambda + 2 mu) alpha (the constrained eps_33 carries its share).
 * Plane stress (sigma_33 = 0): lambda* = 2 lambda mu / (lambda + 2 mu), beta* = E alpha / (1 - nu). */
typedef struct {
  PetscReal lambda, mu, beta, k;
} Moduli;

static Moduli ModuliOf(const TslElementType *t)
{
  Moduli m;

  m.lambda = E * NU / ((1 + NU) * (1 - 2 * NU));
  m.mu     = E / (2 * (1 + NU));
  m.beta   = (3 * m.lambda + 2 * m.mu) * ALPHA;
  m.k      = K;
  if (t->kin == TSL_KIN_PLANE_STRESS) {
    m.lambda = 2 * m.lambda * m.mu / (m.lambda + 2 * m.mu);
    m.beta   = E * ALPHA / (1 - NU);
  }
  return m;
}

/* Body force b = -div sigma and heat source q = -div(k grad theta) of the exact fields.
 * Cartesian (x, y[, z]):  div sigma_i = (lambda + mu) d_i div u + mu lap u_i - beta d_i theta.
 * Axisymmetric (x = r, y = z), with tr eps = u_r,r + u_r / r + u_z,z:
 *   b_r = -(d_r sigma_rr + d_z sigma_rz + (sigma_rr - sigma_hoop) / r)
 *       = -(lambda d_r tr + 2 mu u_r,rr - beta theta_,r + mu (u_r,zz + u_z,rz) + 2 mu (u_r,r - u_r / r) / r)
 *   b_z = -(d_r sigma_rz + d_z sigma_zz + sigma_rz / r)
 *       = -(mu (u_r,rz + u_z,rr) + lambda d_z tr + 2 mu u_z,zz - beta theta_,z + mu (u_r,z + u_z,r) / r)
 *   q   = -k (theta_,rr + theta_,r / r + theta_,zz). */
static void Source(const TslElementType *t, const Moduli *m, const PetscReal x[3], PetscReal b[3], PetscReal *q)
{
  const PetscInt dim = t->dim;
  PetscReal      u[3], gu[3][3], Hu[3][3][3], T, gT[3], HT[3][3];

  for (PetscInt i = 0; i < 3; i++) Field(i, x, &u[i], gu[i], Hu[i]);
  Field(3, x, &T, gT, HT);
  b[2] = 0;
  if (t->kin == TSL_KIN_AXISYMMETRIC) {
    const PetscReal r = x[0], ur = u[0], ur_r = gu[0][0], ur_z = gu[0][1], ur_rr = Hu[0][0][0], ur_rz = Hu[0][0][1], ur_zz = Hu[0][1][1];
    const PetscReal uz_r = gu[1][0], uz_rr = Hu[1][0][0], uz_rz = Hu[1][0][1], uz_zz = Hu[1][1][1];
    const PetscReal dtr_r = ur_rr + ur_r / r - ur / (r * r) + uz_rz, dtr_z = ur_rz + ur_z / r + uz_zz;

    b[0] = -(m->lambda * dtr_r + 2 * m->mu * ur_rr - m->beta * gT[0] + m->mu * (ur_zz + uz_rz) + 2 * m->mu * (ur_r - ur / r) / r);
    b[1] = -(m->mu * (ur_rz + uz_rr) + m->lambda * dtr_z + 2 * m->mu * uz_zz - m->beta * gT[1] + m->mu * (ur_z + uz_r) / r);
    *q   = -m->k * (HT[0][0] + gT[0] / r + HT[1][1]);
    return;
  }
  if (t->kin == TSL_KIN_CONTINUUM_SHELL) {
    /* the shell's law with its stack direction z (the grid's third reference direction): plane stress in
     * x-y, sigma_zz = 2 G eps_zz, transverse shear 5/6 G, all of eps - alpha theta m; b_i = -d_j sigma_ij */
    static const PetscInt vi[6] = {0, 1, 2, 0, 0, 1}, vj[6] = {0, 1, 2, 1, 2, 2};
    const PetscReal       G = E / (2 * (1 + NU)), c = E / (1 - NU * NU);
    PetscReal             D[6][6] = {{0}};
    D[0][0] = D[1][1] = c, D[0][1] = D[1][0] = NU * c, D[2][2] = 2 * G, D[3][3] = G, D[4][4] = D[5][5] = 5.0 / 6 * G;
    for (PetscInt i = 0; i < 3; i++) b[i] = 0;
    for (PetscInt r = 0; r < 6; r++)
      for (PetscInt j = 0; j < 3; j++) {
        PetscReal dsig = 0; /* d_j sigma_r */
        for (PetscInt s = 0; s < 6; s++) {
          const PetscInt  k = vi[s], l = vj[s];
          const PetscReal deps = (k == l ? Hu[k][k][j] : Hu[k][l][j] + Hu[l][k][j]) - (s < 3 ? ALPHA * gT[j] : 0);
          dsig += D[r][s] * deps;
        }
        if (vj[r] == j) b[vi[r]] -= dsig;
        if (vi[r] == j && vi[r] != vj[r]) b[vj[r]] -= dsig;
      }
    *q = -m->k * (HT[0][0] + HT[1][1] + HT[2][2]);
    return;
  }
  *q = 0;
  for (PetscInt i = 0; i < dim; i++) {
    PetscReal ddiv = 0, lap = 0;
    for (PetscInt j = 0; j < dim; j++) ddiv += Hu[j][j][i], lap += Hu[i][j][j];
    b[i] = -((m->lambda + m->mu) * ddiv + m->mu * lap - m->beta * gT[i]);
    *q -= m->k * HT[i][i];
  }
}

/* The manufactured problem's callbacks (grid.h), ctx the type: the exact fields (theta, the last
 * unknown, is field 3) and the densities b (displacement rows) and q (temperature rows). */
static void ExactField(void *ctx, PetscInt slot, const PetscReal x[3], PetscReal *f, PetscReal g[3])
{
  const TslElementType *t = (const TslElementType *)ctx;
  PetscReal             H[3][3];

  Field(slot < t->dim ? slot : 3, x, f, g, H);
}

static void ExactSource(void *ctx, const PetscReal x[3], PetscReal s[])
{
  const TslElementType *t = (const TslElementType *)ctx;
  const Moduli          m = ModuliOf(t);
  PetscReal             b[3];

  Source(t, &m, x, b, &s[t->dim]);
  for (PetscInt i = 0; i < t->dim; i++) s[i] = b[i];
}

/* err[0..3]: ||u - u_h||, |u - u_h|_1, ||theta - theta_h||, |theta - theta_h|_1 (the measure dV of the
 * kinematics: 2 pi r dA for axisymmetry). */
static PetscErrorCode Errors(const Grid *grid, const PetscReal u[], const GridRule *rule, PetscReal err[4])
{
  const PetscInt dim = grid->type->dim;
  PetscReal      l2[TSL_MAX_NODE_DOF], h1[TSL_MAX_NODE_DOF];

  PetscFunctionBeginUser;
  PetscCall(GridErrors(grid, u, rule, ExactField, (void *)grid->type, l2, h1));
  for (PetscInt k = 0; k < 4; k++) err[k] = 0;
  for (PetscInt c = 0; c <= dim; c++) {
    err[c < dim ? 0 : 2] += l2[c];
    err[c < dim ? 1 : 3] += h1[c];
  }
  for (PetscInt k = 0; k < 4; k++) err[k] = PetscSqrtReal(err[k]);
  PetscFunctionReturn(PETSC_SUCCESS);
}

typedef struct {
  PetscReal h, err[4], residual, min_detJ;
  PetscInt  invalid;
  PetscBool factored;
} Level;

static PetscErrorCode SolveLevel(const TslElementType *t, PetscInt n, const GridRule *rule, Level *lv)
{
  const PetscInt  dim = t->dim, ndof = t->ndof;
  const PetscInt  ncell[3] = {n, n, n};
  const PetscReal r0       = t->kin == TSL_KIN_AXISYMMETRIC ? 1 : 0;
  const PetscReal lo[3] = {r0, 0, 0}, hi[3] = {r0 + 1, 1, 1};
  Grid            grid;
  PetscReal      *F, *u;
  PetscInt       *fix, nfix = 0;
  GridSolveInfo   info;

  PetscFunctionBeginUser;
  PetscCall(GridCreate(t, ncell, lo, hi, &grid));
  GridSetMaterial(&grid, E, NU, K, ALPHA, THETA_INIT, 1);
  PetscCall(GridMinJacobian(&grid, &lv->min_detJ, &lv->invalid));
  PetscCall(PetscMalloc3(grid.nnode * ndof, &F, grid.nnode * ndof, &u, grid.nnode * ndof, &fix));
  PetscCall(GridLoadVector(&grid, rule, ExactSource, (void *)t, F));
  for (PetscInt a = 0; a < grid.nnode; a++) {
    PetscBool boundary = PETSC_FALSE;
    for (PetscInt d = 0; d < dim; d++) boundary = (PetscBool)(boundary || GridOnPlane(&grid, a, d, lo[d]) || GridOnPlane(&grid, a, d, hi[d]));
    for (PetscInt c = 0; c <= dim; c++) {
      PetscReal f, g[3], H[3][3];
      Field(c < dim ? c : 3, &grid.x[3 * a], &f, g, H);
      u[ndof * a + c] = boundary ? f : 0;
      if (boundary) fix[nfix++] = ndof * a + c;
    }
  }
  PetscCall(GridSolve(&grid, F, nfix, fix, u, &info));
  lv->h        = 1.0 / n;
  lv->factored = info.factored;
  lv->residual = info.residual;
  for (PetscInt k = 0; k < 4; k++) lv->err[k] = PETSC_MAX_REAL;
  if (info.factored) PetscCall(Errors(&grid, u, rule, lv->err));
  PetscCall(PetscFree3(F, u, fix));
  PetscCall(GridDestroy(&grid));
  PetscFunctionReturn(PETSC_SUCCESS);
}

int main(int argc, char **argv)
{
  static const char *name[4] = {"L2(u)", "H1(u)", "L2(theta)", "H1(theta)"};
  TestLog            log     = {0, 0};
  const clock_t      start   = clock();

  PetscCall(PetscInitialize(&argc, &argv, NULL, NULL));
  for (PetscInt ti = 0; ti < TslElementTypeCount(); ti++) {
    const TslElementType *t = TslElementTypeGet(ti);
    const TslGeometry    *g = t->geom;
    PetscInt              n0;
    PetscReal             min[4];
    if (!GridConvergenceRow(t, &n0, min)) continue;
    min[2] = min[0], min[3] = min[1]; /* the same rates for the displacement */
    Level           lv[NLEVEL];
    GridRule        rule;
    PetscReal       wsum = 0, min_detJ = PETSC_MAX_REAL, residual = 0;
    PetscInt        invalid  = 0;
    PetscBool       factored = PETSC_TRUE;

    printf("---- %s: %s (%s, %s)\n", t->name, t->description, TslElementTypeKinematicsName(t), TslElementTypeFormulationName(t));
    GridRuleCreate(g, NPD, &rule);
    for (PetscInt q = 0; q < rule.n; q++) wsum += rule.w[q];
    Check(&log, wsum, g->ref_volume, 1e-13, "%s %s load/error rule weight sum", t->name, g->name);
    printf("  cells        h   |u-uh|_L2  rate   |u-uh|_H1  rate   |T-Th|_L2  rate   |T-Th|_H1  rate   residual\n");
    for (PetscInt l = 0; l < NLEVEL; l++) {
      const PetscInt n = n0 << l;
      PetscCall(SolveLevel(t, n, &rule, &lv[l]));
      printf("  %5" PetscInt_FMT " %8.4f", n, (double)lv[l].h);
      for (PetscInt k = 0; k < 4; k++) {
        if (l)
          printf(" %10.3e %5.2f", (double)lv[l].err[k], (double)(PetscLog2Real(lv[l - 1].err[k] / lv[l].err[k])));
        else
          printf(" %10.3e   -  ", (double)lv[l].err[k]);
      }
      printf("  %9.2e\n", (double)lv[l].residual);
      min_detJ = PetscMin(min_detJ, lv[l].min_detJ);
      invalid += lv[l].invalid;
      residual = PetscMax(residual, lv[l].residual);
      factored = (PetscBool)(factored && lv[l].factored);
    }
    Check(&log, invalid, 0, 0, "%s mesh: points with an invalid map (min det J %.3e)", t->name, (double)min_detJ);
    Check(&log, factored, PETSC_TRUE, 0, "%s LU factorisations succeed", t->name);
    CheckAtMost(&log, residual, 1e-8, "%s relative residual after one Newton step (linear problem)", t->name);
    for (PetscInt k = 0; k < 4; k++) {
      const PetscReal rate = PetscLog2Real(lv[NLEVEL - 2].err[k] / lv[NLEVEL - 1].err[k]);
      CheckAtLeast(&log, rate, min[k], "%s rate %s", t->name, name[k]);
    }
  }
  printf("run time %.1f s\n", (double)(clock() - start) / CLOCKS_PER_SEC);
  PetscCall(PetscFinalize());
  return Summary(&log);
}
