/* Convergence with a body heat source applied through the kernels (TslElementFaceLoad, TSL_BODY_FLUX:
 * the deck's *DFLUX ..., BF) for every continuum type of the catalogue. Steady conduction (displacements
 * held at zero, no expansion) on the unit square or cube (axisymmetric: r in [1, 2], z in [0, 1]) with a
 * uniform source q on every element and the exact temperature prescribed on the whole boundary. The
 * manufactured temperature is a particular solution of -k lap theta = q plus a harmonic part that no
 * mesh of the families represents exactly:
 *   Cartesian:     theta = S - q x^2 / (2 k) + A exp(a y + b z) sin(c x + phi),   c^2 = a^2 + b^2 (2D: b = 0)
 *   axisymmetric:  theta = S - q r^2 / (4 k) + A ln r + B (z^3 - 3 r^2 z / 2)
 * (ln r and z^3 - 3 r^2 z / 2 are harmonic for theta_rr + theta_r / r + theta_zz). The load vector is
 * the kernels' own; nothing else is applied. L2 and H1-seminorm errors of theta are printed with their
 * rates; the rates between the two finest meshes must reach the order of the family, as in
 * element_convergence (linear L2 >= 1.8, H1 >= 0.85; quadratic L2 >= 2.7, H1 >= 1.8). The heat the
 * kernels report for the source must be q V exactly on every mesh.
 *
 * Why: the body flux was lumped with the capacity's nodal weights (HRZ for quad8, the linear sub-elements
 * for tri6 and tet10) until it got the family's full rule and its own shape functions; with those
 * weights the second-order types fell to L2 rate 2 and H1 rate 1 (docs/verification.md has the figures
 * before and after). */
#include "grid.h"
#include <time.h>

#define NLEVEL 3
#define NPD    5 /* Gauss points per direction of the error integrals */

static const PetscReal K = 2, Q = 4, S = 0.5, A = 1, B = 0.5, KY = 0.9, KZ = 0.7, PHI = 0.4;

/* theta and its gradient at x for a type (dim and kinematics) */
static void ExactField(void *ctx, PetscInt slot, const PetscReal x[3], PetscReal *f, PetscReal g[3])
{
  const TslElementType *t = (const TslElementType *)ctx;

  g[0] = g[1] = g[2] = 0;
  if (slot != TslElementTypeThetaSlot(t)) {
    *f = 0;
    return;
  }
  if (TslKinematicsRevolves(t->kin)) {
    const PetscReal r = x[0], z = x[1];
    *f   = S - Q * r * r / (4 * K) + A * PetscLogReal(r) + B * (z * z * z - 1.5 * r * r * z);
    g[0] = -Q * r / (2 * K) + A / r - 3 * B * r * z;
    g[1] = B * (3 * z * z - 1.5 * r * r);
  } else {
    const PetscReal a = KY, b = t->dim == 3 ? KZ : 0, c = PetscSqrtReal(a * a + b * b);
    const PetscReal ex = A * PetscExpReal(a * x[1] + b * x[2]), sn = PetscSinReal(c * x[0] + PHI), cs = PetscCosReal(c * x[0] + PHI);
    *f   = S - Q * x[0] * x[0] / (2 * K) + ex * sn;
    g[0] = -Q * x[0] / K + c * ex * cs;
    g[1] = a * ex * sn;
    g[2] = b * ex * sn;
  }
}

typedef struct {
  PetscReal err[2], residual, heat;
  PetscBool factored;
} Level;

static PetscErrorCode SolveLevel(const TslElementType *t, PetscInt n, const GridRule *rule, Level *lv)
{
  const PetscInt  dim = t->dim, ndof = t->ndof, ncell[3] = {n, n, n};
  const PetscReal r0 = TslKinematicsRevolves(t->kin) ? 1 : 0, lo[3] = {r0, 0, 0}, hi[3] = {r0 + 1, 1, 1};
  PetscInt        dir[6], np = 0;
  PetscReal       value[6], *F, *u;
  Grid            grid;
  GridSolveInfo   info;

  PetscFunctionBeginUser;
  PetscCall(GridCreate(t, ncell, lo, hi, &grid));
  GridSetMaterial(&grid, 1, 0.3, K, 0, 0, 1);
  PetscCall(GridAddBodyFlux(&grid, Q));
  PetscCall(PetscCalloc2(grid.nnode * ndof, &F, grid.nnode * ndof, &u)); /* F = 0: the source is in R(u), through the kernels */
  for (PetscInt d = 0; d < dim; d++) dir[np] = d, value[np++] = lo[d], dir[np] = d, value[np++] = hi[d]; /* the whole boundary */
  PetscCall(GridSolveConduction(&grid, rule, F, np, dir, value, ExactField, (void *)t, u, &info, lv->err));
  lv->factored = info.factored;
  lv->residual = info.residual;
  PetscCall(GridFaceHeat(&grid, u, &lv->heat));
  PetscCall(PetscFree2(F, u));
  PetscCall(GridDestroy(&grid));
  PetscFunctionReturn(PETSC_SUCCESS);
}

int main(int argc, char **argv)
{
  TestLog       log   = {0, 0};
  const clock_t start = clock();

  PetscCall(PetscInitialize(&argc, &argv, NULL, NULL));
  for (PetscInt ti = 0; ti < TslElementTypeCount(); ti++) {
    const TslElementType *t = TslElementTypeGet(ti);
    PetscInt              n0;
    PetscReal             min[2];
    if (!GridConvergenceRow(t, &n0, min)) continue;
    /* the box's volume: 1, or 2 pi int_1^2 r dr = 3 pi around the axis */
    const PetscReal volume = TslKinematicsRevolves(t->kin) ? 3 * PETSC_PI : 1;
    Level           lv[NLEVEL];
    GridRule        rule;
    PetscReal       residual = 0, heat_err = 0;
    PetscBool       factored = PETSC_TRUE;

    GridRuleCreate(t->geom, NPD, &rule);
    printf("---- %s, body flux q = %g (%s)\n", t->name, (double)Q, TslElementTypeFormulationName(t));
    printf("  cells   |T-Th|_L2  rate   |T-Th|_H1  rate    heat - qV   residual\n");
    for (PetscInt l = 0; l < NLEVEL; l++) {
      PetscCall(SolveLevel(t, n0 << l, &rule, &lv[l]));
      printf("  %5" PetscInt_FMT, n0 << l);
      for (PetscInt k = 0; k < 2; k++) {
        if (l)
          printf(" %10.3e %5.2f", (double)lv[l].err[k], (double)PetscLog2Real(lv[l - 1].err[k] / lv[l].err[k]));
        else
          printf(" %10.3e   -  ", (double)lv[l].err[k]);
      }
      printf("  %10.2e  %9.2e\n", (double)(lv[l].heat - Q * volume), (double)lv[l].residual);
      residual = PetscMax(residual, lv[l].residual);
      heat_err = PetscMax(heat_err, PetscAbsReal(lv[l].heat - Q * volume) / (Q * volume));
      factored = (PetscBool)(factored && lv[l].factored);
    }
    Check(&log, factored, PETSC_TRUE, 0, "%s body flux LU factorisations succeed", t->name);
    CheckAtMost(&log, residual, 1e-8, "%s body flux relative residual after one Newton step (linear problem)", t->name);
    CheckAtMost(&log, heat_err, 1e-12, "%s body flux heat = q V (relative error)", t->name);
    CheckAtLeast(&log, PetscLog2Real(lv[NLEVEL - 2].err[0] / lv[NLEVEL - 1].err[0]), min[0], "%s body flux rate L2(theta)", t->name);
    CheckAtLeast(&log, PetscLog2Real(lv[NLEVEL - 2].err[1] / lv[NLEVEL - 1].err[1]), min[1], "%s body flux rate H1(theta)", t->name);
  }
  printf("run time %.1f s\n", (double)(clock() - start) / CLOCKS_PER_SEC);
  PetscCall(PetscFinalize());
  return Summary(&log);
}
