/* Convergence of the thermal face terms (surface flux and film, TslElementFaceLoad) for every continuum
 * type of the catalogue. Steady conduction (displacements held at zero, no expansion) on the unit square
 * or cube (axisymmetric: r in [1, 2], z in [0, 1]) with a uniform film, or a uniform flux, on the face
 * x = X1 (the outer radius) and the exact temperature prescribed on the rest of the boundary. The
 * manufactured temperature
 *   theta = S + G x + A f(x),   A = A0 + alpha sin(ky y + kz z + phi),   f = sin(a (x - X1) + c)
 * meets the face condition with uniform data:
 *   film h, sink:  -k theta_x = h (theta - sink) on x = X1  <=>  f(X1) + (k / h) f'(X1) = 0:
 *                  c = -atan(a k / h), sink = S + G (X1 + k / h)
 *   flux q in:     k theta_x = q on x = X1                  <=>  f'(X1) = 0: c = pi / 2, q = k G
 * and the heat source is -k (lap theta + theta_x / x), the last term for axisymmetry only. The source is
 * integrated against the shape functions with a high-order rule (grid.c); the face terms are the
 * kernels' own. L2 and H1-seminorm errors of theta and, for the film, the error of the heat through the
 * face (the kernels' -int h (theta_h - sink) dA against the exact int k theta_x dA) are printed with
 * their rates; the rates of theta on the finest pair must reach the order of the family, as in
 * element_convergence (linear L2 >= 1.8, H1 >= 0.85; quadratic L2 >= 2.7, H1 >= 1.8).
 *
 * Why: C3D10MT integrated its film and flux on the four linear sub-faces of the tri6 face (one point
 * each, composite linear shape functions, as its pressure still is) until the thermal face terms got the
 * face's own shape functions and a degree-4 rule; between 4 and 8 cells its rates were then L2 1.4
 * (film) and 1.5 (flux), H1 0.35 and 0.4, and the film heat did not converge (docs/verification.md). */
#include "grid.h"
#include <time.h>

#define NLEVEL 3
#define NPD    5 /* Gauss points per direction of the source and error integrals */

static const PetscReal K = 2, H = 5, S = 0.5, G = 0.7, A0 = 1, ALPHA = 0.6, KY = 0.9, KZ = 1.3, PHI = 0.4, WAVE = 1.3;

typedef struct {
  const TslElementType *type;
  TslFaceLoadKind       kind; /* TSL_FACE_FILM or TSL_FACE_FLUX */
  PetscReal             X1, c;
} Problem;

/* theta, its gradient and its Laplacian (Cartesian; the axisymmetric term is the caller's). */
static void Temperature(const Problem *pb, const PetscReal x[3], PetscReal *T, PetscReal g[3], PetscReal *lap)
{
  const PetscBool third = (PetscBool)(pb->type->dim == 3);
  const PetscReal psi = KY * x[1] + (third ? KZ * x[2] : 0) + PHI, A = A0 + ALPHA * PetscSinReal(psi);
  const PetscReal arg = WAVE * (x[0] - pb->X1) + pb->c, f = PetscSinReal(arg), df = WAVE * PetscCosReal(arg);

  *T   = S + G * x[0] + A * f;
  g[0] = G + A * df;
  g[1] = ALPHA * KY * PetscCosReal(psi) * f;
  g[2] = third ? ALPHA * KZ * PetscCosReal(psi) * f : 0;
  *lap = -WAVE * WAVE * A * f - ALPHA * (KY * KY + (third ? KZ * KZ : 0)) * PetscSinReal(psi) * f;
}

/* The callbacks of grid.h: the displacements are zero, theta is the last unknown. */
static void ExactField(void *ctx, PetscInt slot, const PetscReal x[3], PetscReal *f, PetscReal g[3])
{
  const Problem *pb = (const Problem *)ctx;
  PetscReal      lap;

  if (slot == TslElementTypeThetaSlot(pb->type)) {
    Temperature(pb, x, f, g, &lap);
    return;
  }
  *f = g[0] = g[1] = g[2] = 0;
}

static void ExactSource(void *ctx, const PetscReal x[3], PetscReal s[])
{
  const Problem *pb = (const Problem *)ctx;
  const PetscInt th = TslElementTypeThetaSlot(pb->type);
  PetscReal      T, g[3], lap;

  Temperature(pb, x, &T, g, &lap);
  for (PetscInt i = 0; i < th; i++) s[i] = 0;
  s[th] = -K * (lap + (TslKinematicsRevolves(pb->type->kin) ? g[0] / x[0] : 0));
}

/* Exact heat into the body through the face x = X1: int k theta_x dA = k (G |face| + f'(X1) int A dA),
 * with int sin(ky y + kz z + phi) over the unit square (3D) or interval (2D) in closed form and dA
 * carrying 2 pi X1 for axisymmetry. */
static PetscReal ExactFaceHeat(const Problem *pb)
{
  const PetscReal measure = TslKinematicsRevolves(pb->type->kin) ? 2 * PETSC_PI * pb->X1 : 1;
  const PetscReal sine    = pb->type->dim == 3
                                ? (PetscSinReal(KY + PHI) - PetscSinReal(PHI) - PetscSinReal(KY + KZ + PHI) + PetscSinReal(KZ + PHI)) / (KY * KZ)
                                : (PetscCosReal(PHI) - PetscCosReal(KY + PHI)) / KY;

  return K * measure * (G + WAVE * PetscCosReal(pb->c) * (A0 + ALPHA * sine));
}

typedef struct {
  PetscReal err[3], residual; /* L2 and H1 of theta, heat through the face */
  PetscBool factored;
} Level;

static PetscErrorCode SolveLevel(const Problem *pb, PetscInt n, const GridRule *rule, Level *lv)
{
  const TslElementType *t   = pb->type;
  const PetscInt        dim = t->dim, ndof = t->ndof, ncell[3] = {n, n, n};
  const PetscReal       lo[3] = {pb->X1 - 1, 0, 0}, hi[3] = {pb->X1, 1, 1};
  const PetscBool       film = (PetscBool)(pb->kind == TSL_FACE_FILM);
  PetscInt              dir[5] = {0}, np = 1;
  PetscReal             value[5] = {lo[0]}, *F, *u, heat;
  Grid                  grid;
  GridSolveInfo         info;

  PetscFunctionBeginUser;
  PetscCall(GridCreate(t, ncell, lo, hi, &grid));
  GridSetMaterial(&grid, 1, 0.3, K, 0, 0, 1);
  if (film)
    PetscCall(GridAddFaceLoad(&grid, 0, pb->X1, TSL_FACE_FILM, H, S + G * (pb->X1 + K / H)));
  else
    PetscCall(GridAddFaceLoad(&grid, 0, pb->X1, TSL_FACE_FLUX, K * G, 0));
  PetscCall(PetscMalloc2(grid.nnode * ndof, &F, grid.nnode * ndof, &u));
  PetscCall(GridLoadVector(&grid, rule, ExactSource, (void *)pb, F));
  /* the temperature held on x = lo and on the lateral planes; the loaded face x = X1 is free */
  for (PetscInt d = 1; d < dim; d++) dir[np] = d, value[np++] = lo[d], dir[np] = d, value[np++] = hi[d];
  PetscCall(GridSolveConduction(&grid, rule, F, np, dir, value, ExactField, (void *)pb, u, &info, lv->err));
  lv->factored = info.factored;
  lv->residual = info.residual;
  lv->err[2]   = PETSC_MAX_REAL;
  if (info.factored) {
    PetscCall(GridFaceHeat(&grid, u, &heat));
    lv->err[2] = film ? PetscAbsReal(heat - ExactFaceHeat(pb)) : 0;
  }
  PetscCall(PetscFree2(F, u));
  PetscCall(GridDestroy(&grid));
  PetscFunctionReturn(PETSC_SUCCESS);
}

int main(int argc, char **argv)
{
  static const char *kind_name[2] = {"film", "flux"};
  TestLog            log          = {0, 0};
  const clock_t      start        = clock();

  PetscCall(PetscInitialize(&argc, &argv, NULL, NULL));
  for (PetscInt ti = 0; ti < TslElementTypeCount(); ti++) {
    const TslElementType *t = TslElementTypeGet(ti);
    PetscInt              n0;
    PetscReal             min[2];
    if (!GridConvergenceRow(t, &n0, min)) continue;
    GridRule        rule;

    GridRuleCreate(t->geom, NPD, &rule);
    for (PetscInt kc = 0; kc < 2; kc++) {
      const PetscBool film = (PetscBool)(kc == 0);
      const Problem   pb   = {t, film ? TSL_FACE_FILM : TSL_FACE_FLUX, TslKinematicsRevolves(t->kin) ? 2 : 1,
                          film ? -PetscAtanReal(WAVE * K / H) : PETSC_PI / 2};
      Level           lv[NLEVEL];
      PetscReal       residual = 0;
      PetscBool       factored = PETSC_TRUE;

      printf("---- %s, %s on S at x = %g (%s)\n", t->name, kind_name[kc], (double)pb.X1, TslElementTypeFormulationName(t));
      printf("  cells   |T-Th|_L2  rate   |T-Th|_H1  rate%s   residual\n", film ? "  film heat error  rate" : "");
      for (PetscInt l = 0; l < NLEVEL; l++) {
        PetscCall(SolveLevel(&pb, n0 << l, &rule, &lv[l]));
        printf("  %5" PetscInt_FMT, n0 << l);
        for (PetscInt k = 0; k < (film ? 3 : 2); k++) {
          if (l)
            printf(" %10.3e %5.2f", (double)lv[l].err[k], (double)PetscLog2Real(lv[l - 1].err[k] / lv[l].err[k]));
          else
            printf(" %10.3e   -  ", (double)lv[l].err[k]);
        }
        printf("  %9.2e\n", (double)lv[l].residual);
        residual = PetscMax(residual, lv[l].residual);
        factored = (PetscBool)(factored && lv[l].factored);
      }
      Check(&log, factored, PETSC_TRUE, 0, "%s %s LU factorisations succeed", t->name, kind_name[kc]);
      CheckAtMost(&log, residual, 1e-8, "%s %s relative residual after one Newton step (linear problem)", t->name, kind_name[kc]);
      CheckAtLeast(&log, PetscLog2Real(lv[NLEVEL - 2].err[0] / lv[NLEVEL - 1].err[0]), min[0], "%s %s rate L2(theta)", t->name, kind_name[kc]);
      CheckAtLeast(&log, PetscLog2Real(lv[NLEVEL - 2].err[1] / lv[NLEVEL - 1].err[1]), min[1], "%s %s rate H1(theta)", t->name, kind_name[kc]);
    }
  }
  printf("run time %.1f s\n", (double)(clock() - start) / CLOCKS_PER_SEC);
  PetscCall(PetscFinalize());
  return Summary(&log);
}
