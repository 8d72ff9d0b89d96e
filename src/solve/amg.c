/* thermoslide's application of BoomerAMG's V-cycle (the split's sub-solvers, split.c).
 *
 * PCHYPRE applies a BoomerAMG preconditioner by zeroing the iterate and running hypre's cycle from it. With
 * weighted-Jacobi smoothing (the split's default) the first sweep on each level then starts from zero, and
 * hypre still computes it as f - A u: a pass over the level's matrix whose product is zero. On the finest
 * level that is one of the four passes over the block per CG iteration (pre-smoothing, residual,
 * post-smoothing, and CG's own product), and likewise one of three on every coarser level. Here the cycle is
 * hypre's own, level by level, with that first sweep computed as u = w D^-1 f, which is what hypre's
 * sweep yields from zero, to the bit: the iterates, and so the iteration counts, are the same as hypre's.
 * Everything else is hypre's: the residual and restriction (MatvecOutOfPlace, MatvecT with R), the
 * interpolation, further and post-smoothing sweeps (hypre_BoomerAMGRelaxIF), and the coarsest level's
 * Gaussian elimination (hypre_GaussElimSolve).
 *
 * The cycle runs only where it is hypre's plain V-cycle: one cycle (max_iter 1, tol 0), cycle type V,
 * Jacobi (relax type 0) on the way down and up without C/F ordering, the coarsest level by Jacobi or
 * Gaussian elimination, no smoother of hypre's smoothers list (Schwarz, ILU, ...), no block mode, no
 * additive cycles, no restriction operator other than P^T, no coarse-level agglomeration, no per-cycle
 * residual printed or logged by hypre. Any other setting, or a hierarchy of one level, takes PCHYPRE's own
 * application unchanged; -tsl_amg_cycle 0 turns the cycle off (the same arithmetic either way). */
#include "solve_impl.h"
#include <string.h>
#include <petscmathypre.h>
#include <_hypre_parcsr_ls.h>
#include <petsc/private/pcimpl.h>

typedef struct {
  PetscErrorCode (*apply)(PC, Vec, Vec); /* PCHYPRE's own application */
  hypre_ParVector *f, *u;                /* the finest level's right-hand side and iterate, on PETSc's arrays */
  /* each level's diagonal, gathered from its rows' first entries for the sweeps from zero (which otherwise
   * read one entry per row across the whole matrix); for the hierarchy of PCHYPRE's set-up at pc->matstate */
  PetscInt         nl, *len;
  HYPRE_Real     **diag;
  PetscObjectState state;
} Cycle;

static const char key[] = "thermoslide_amg_cycle";

/* Whether amg's cycle is the plain one this file runs. */
static PetscBool Plain(hypre_ParAMGData *amg)
{
  const HYPRE_Int *rt, *ns;

  if (!amg || !hypre_ParAMGDataAArray(amg) || hypre_ParAMGDataNumLevels(amg) < 2) return PETSC_FALSE;
  rt = hypre_ParAMGDataGridRelaxType(amg), ns = hypre_ParAMGDataNumGridSweeps(amg);
  if (!rt || !ns || rt[1] != 0 || rt[2] != 0 || !(rt[3] == 0 || rt[3] == 9) || ns[1] < 1 || ns[2] < 0 || ns[3] < 1) return PETSC_FALSE;
  if (hypre_ParAMGDataMaxIter(amg) != 1 || hypre_ParAMGDataTol(amg) != 0 || hypre_ParAMGDataCycleType(amg) != 1 || hypre_ParAMGDataFCycle(amg))
    return PETSC_FALSE;
  if (hypre_ParAMGDataRelaxOrder(amg) != 0 || hypre_ParAMGDataGridRelaxPoints(amg) || hypre_ParAMGDataSmoothNumLevels(amg) > 0 ||
      hypre_ParAMGDataBlockMode(amg))
    return PETSC_FALSE;
  if (hypre_ParAMGDataAdditive(amg) >= 0 || hypre_ParAMGDataMultAdditive(amg) >= 0 || hypre_ParAMGDataSimple(amg) >= 0) return PETSC_FALSE;
  if (hypre_ParAMGDataRestriction(amg) || hypre_ParAMGDataParticipate(amg) || hypre_ParAMGDataPartialCycleCoarsestLevel(amg) >= 0) return PETSC_FALSE;
  if (hypre_ParAMGDataPrintLevel(amg) > 1 || hypre_ParAMGDataLogging(amg) > 1) return PETSC_FALSE; /* hypre's per-cycle residuals */
  if (!hypre_ParAMGDataRArray(amg) || !hypre_ParAMGDataPArray(amg) || !hypre_ParAMGDataFArray(amg) || !hypre_ParAMGDataUArray(amg) ||
      !hypre_ParAMGDataVtemp(amg) || !hypre_ParAMGDataRelaxWeight(amg))
    return PETSC_FALSE;
  return PETSC_TRUE;
}

/* One weighted-Jacobi sweep from u = 0: u_i = (w f_i) / a_ii, as hypre's sweep computes it (the row's
 * products with the zero iterate add nothing; a row with a zero diagonal is left at zero). */
static void JacobiFromZero(const HYPRE_Real *d, hypre_ParVector *f, HYPRE_Real w, hypre_ParVector *u)
{
  const HYPRE_Int      n  = hypre_VectorSize(hypre_ParVectorLocalVector(u));
  const HYPRE_Complex *fa = hypre_VectorData(hypre_ParVectorLocalVector(f));
  HYPRE_Complex       *ua = hypre_VectorData(hypre_ParVectorLocalVector(u));

  for (HYPRE_Int i = 0; i < n; i++) ua[i] = d[i] != 0 ? w * fa[i] / d[i] : 0;
}

/* The levels' diagonals of the hierarchy PCHYPRE set up last (hypre keeps each row's diagonal first in the
 * local block), gathered again after each set-up. */
static PetscErrorCode Diagonals(PC pc, Cycle *cy, hypre_ParAMGData *amg)
{
  const PetscInt nl = hypre_ParAMGDataNumLevels(amg);

  PetscFunctionBeginUser;
  if (cy->nl != nl) {
    for (PetscInt l = 0; l < cy->nl; l++) PetscCall(PetscFree(cy->diag[l]));
    PetscCall(PetscFree2(cy->diag, cy->len));
    PetscCall(PetscCalloc2(nl, &cy->diag, nl, &cy->len));
    cy->nl = nl;
  }
  for (PetscInt l = 0; l < nl; l++) {
    hypre_CSRMatrix     *D  = hypre_ParCSRMatrixDiag(hypre_ParAMGDataAArray(amg)[l]);
    const HYPRE_Int     *di = hypre_CSRMatrixI(D), n = hypre_CSRMatrixNumRows(D);
    const HYPRE_Complex *da = hypre_CSRMatrixData(D);
    if (cy->len[l] < n) {
      PetscCall(PetscFree(cy->diag[l]));
      PetscCall(PetscMalloc1(n, &cy->diag[l]));
      cy->len[l] = n;
    }
    for (HYPRE_Int i = 0; i < n; i++) cy->diag[l][i] = di[i] < di[i + 1] ? da[di[i]] : 0;
  }
  cy->state = pc->matstate;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The sweeps after the first on one level (cycle_param: 1 down, 2 up, 3 coarsest), hypre's. */
static void Sweeps(hypre_ParAMGData *amg, PetscInt l, HYPRE_Int cp, HYPRE_Int from, hypre_ParVector *f, hypre_ParVector *u)
{
  hypre_IntArray *cf = hypre_ParAMGDataCFMarkerArray(amg) ? hypre_ParAMGDataCFMarkerArray(amg)[l] : NULL;
  hypre_Vector   *l1 = hypre_ParAMGDataL1Norms(amg) ? hypre_ParAMGDataL1Norms(amg)[l] : NULL;

  for (HYPRE_Int j = from; j < hypre_ParAMGDataNumGridSweeps(amg)[cp]; j++)
    hypre_BoomerAMGRelaxIF(hypre_ParAMGDataAArray(amg)[l], f, cf ? hypre_IntArrayData(cf) : NULL, hypre_ParAMGDataGridRelaxType(amg)[cp], 0, cp,
                           hypre_ParAMGDataRelaxWeight(amg)[l], hypre_ParAMGDataOmega(amg) ? hypre_ParAMGDataOmega(amg)[l] : 1.0,
                           l1 ? hypre_VectorData(l1) : NULL, u, hypre_ParAMGDataVtemp(amg), hypre_ParAMGDataZtemp(amg));
}

/* One V-cycle on f0 from a zero iterate into u0. hypre's calls report through its error flag, which the
 * caller reads, as hypre's own cycle leaves them. */
static void VCycle(hypre_ParAMGData *amg, HYPRE_Real *const *diag, hypre_ParVector *f0, hypre_ParVector *u0)
{
  hypre_ParCSRMatrix **A = hypre_ParAMGDataAArray(amg), **P = hypre_ParAMGDataPArray(amg), **R = hypre_ParAMGDataRArray(amg);
  hypre_ParVector    **F = hypre_ParAMGDataFArray(amg), **U = hypre_ParAMGDataUArray(amg), *V = hypre_ParAMGDataVtemp(amg);
  const HYPRE_Real    *w = hypre_ParAMGDataRelaxWeight(amg);
  const PetscInt       c = hypre_ParAMGDataNumLevels(amg) - 1;

  for (PetscInt l = 0; l < c; l++) { /* down: smoothing from zero, residual, restriction */
    hypre_ParVector *f = l ? F[l] : f0, *u = l ? U[l] : u0;
    hypre_ParVectorSetLocalSize(V, hypre_VectorSize(hypre_ParVectorLocalVector(f)));
    JacobiFromZero(diag[l], f, w[l], u);
    Sweeps(amg, l, 1, 1, f, u);
    hypre_ParCSRMatrixMatvecOutOfPlace(-1.0, A[l], u, 1.0, f, V);
    hypre_ParCSRMatrixMatvecT(1.0, R[l], V, 0.0, F[l + 1]);
  }
  hypre_ParVectorSetLocalSize(V, hypre_VectorSize(hypre_ParVectorLocalVector(F[c])));
  if (hypre_ParAMGDataGridRelaxType(amg)[3] == 9) { /* the coarsest level: hypre's direct solve, or Jacobi */
    hypre_ParVectorSetConstantValues(U[c], 0.0);
    for (HYPRE_Int j = 0; j < hypre_ParAMGDataNumGridSweeps(amg)[3]; j++) hypre_GaussElimSolve(amg, (HYPRE_Int)c, 9);
  } else {
    JacobiFromZero(diag[c], F[c], w[c], U[c]);
    Sweeps(amg, c, 3, 1, F[c], U[c]);
  }
  for (PetscInt l = c - 1; l >= 0; l--) { /* up: interpolation, smoothing */
    hypre_ParVector *f = l ? F[l] : f0, *u = l ? U[l] : u0;
    hypre_ParCSRMatrixMatvec(1.0, P[l], U[l + 1], 1.0, u);
    hypre_ParVectorSetLocalSize(V, hypre_VectorSize(hypre_ParVectorLocalVector(f)));
    Sweeps(amg, l, 2, 0, f, u);
  }
}

/* The finest level's vector wrapper (no storage of its own) for the layout of v. */
static PetscErrorCode Wrapper(hypre_ParVector *v, hypre_ParVector **w)
{
  PetscFunctionBeginUser;
  if (*w && hypre_ParVectorGlobalSize(*w) == hypre_ParVectorGlobalSize(v) && hypre_ParVectorFirstIndex(*w) == hypre_ParVectorFirstIndex(v) &&
      hypre_VectorSize(hypre_ParVectorLocalVector(*w)) == hypre_VectorSize(hypre_ParVectorLocalVector(v)))
    PetscFunctionReturn(PETSC_SUCCESS);
  if (*w) {
    hypre_VectorData(hypre_ParVectorLocalVector(*w)) = NULL;
    PetscCallExternal(hypre_ParVectorDestroy, *w);
  }
  *w = hypre_ParVectorCreate(hypre_ParVectorComm(v), hypre_ParVectorGlobalSize(v), hypre_ParVectorPartitioning(v));
  PetscCheck(*w, PETSC_COMM_SELF, PETSC_ERR_LIB, "hypre could not create a vector");
  hypre_VectorOwnsData(hypre_ParVectorLocalVector(*w)) = 0;
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode Apply(PC pc, Vec b, Vec x)
{
  PetscContainer     box;
  Cycle             *cy;
  hypre_ParAMGData  *amg = pc->data ? *(hypre_ParAMGData **)pc->data : NULL;
  const PetscScalar *ba;
  PetscScalar       *xa;
  HYPRE_Int          err;

  PetscFunctionBeginUser;
  PetscCall(PetscObjectQuery((PetscObject)pc, key, (PetscObject *)&box));
  PetscCheck(box, PETSC_COMM_SELF, PETSC_ERR_PLIB, "BoomerAMG cycle without its context");
  PetscCall(PetscContainerGetPointer(box, (void **)&cy));
  if (!Plain(amg) || !hypre_ParAMGDataFArray(amg)[0]) { /* a setting changed since the set-up: hypre's own */
    PetscCall(cy->apply(pc, b, x));
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  if (cy->state != pc->matstate || cy->nl != hypre_ParAMGDataNumLevels(amg)) PetscCall(Diagonals(pc, cy, amg));
  PetscCall(Wrapper(hypre_ParAMGDataFArray(amg)[0], &cy->f));
  PetscCall(Wrapper(hypre_ParAMGDataFArray(amg)[0], &cy->u));
  PetscCall(VecGetArrayRead(b, &ba));
  PetscCall(VecGetArrayWrite(x, &xa));
  hypre_VectorData(hypre_ParVectorLocalVector(cy->f)) = (HYPRE_Complex *)ba;
  hypre_VectorData(hypre_ParVectorLocalVector(cy->u)) = xa;
  PetscCall(PetscFPTrapPush(PETSC_FP_TRAP_OFF));
  VCycle(amg, cy->diag, cy->f, cy->u);
  PetscCall(PetscFPTrapPop());
  err = HYPRE_GetError();
  if (err) HYPRE_ClearAllErrors(); /* a "did not converge" of a smoother is no error here, as in PCHYPRE */
  hypre_VectorData(hypre_ParVectorLocalVector(cy->f)) = NULL;
  hypre_VectorData(hypre_ParVectorLocalVector(cy->u)) = NULL;
  PetscCall(VecRestoreArrayWrite(x, &xa));
  PetscCall(VecRestoreArrayRead(b, &ba));
  PetscCheck(!(err & ~HYPRE_ERROR_CONV), PETSC_COMM_SELF, PETSC_ERR_LIB, "hypre error %d in a BoomerAMG cycle", (int)err);
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode Free(void *ctx)
{
  Cycle *cy = (Cycle *)ctx;

  PetscFunctionBeginUser;
  for (int k = 0; k < 2; k++) {
    hypre_ParVector *v = k ? cy->u : cy->f;
    if (!v) continue;
    hypre_VectorData(hypre_ParVectorLocalVector(v)) = NULL;
    PetscCallExternal(hypre_ParVectorDestroy, v);
  }
  for (PetscInt l = 0; l < cy->nl; l++) PetscCall(PetscFree(cy->diag[l]));
  PetscCall(PetscFree2(cy->diag, cy->len));
  PetscCall(PetscFree(cy));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* After the set-up of pc (a sub-solver's preconditioner): thermoslide's cycle when on (-tsl_amg_cycle) and pc is
 * BoomerAMG with the plain cycle; otherwise PCHYPRE's own application. *used: which. */
PetscErrorCode TslAmgCycleSet(PC pc, PetscBool on, PetscBool *used)
{
  PetscBool      hypre;
  const char    *type = NULL;
  PetscContainer box;
  Cycle         *cy;

  PetscFunctionBeginUser;
  *used = PETSC_FALSE;
  PetscCall(PetscObjectTypeCompare((PetscObject)pc, PCHYPRE, &hypre));
  if (!hypre || !pc->data) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(PetscObjectQuery((PetscObject)pc, key, (PetscObject *)&box));
  if (box) PetscCall(PetscContainerGetPointer(box, (void **)&cy));
  if (on) {
    PetscCall(PCHYPREGetType(pc, &type));
    on = (PetscBool)(type && !strcmp(type, "boomeramg") && Plain(*(hypre_ParAMGData **)pc->data));
  }
  if (!on) {
    if (box) pc->ops->apply = cy->apply;
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  if (!box) {
    PetscCall(PetscNew(&cy));
    cy->apply = pc->ops->apply;
    PetscCall(PetscContainerCreate(PETSC_COMM_SELF, &box));
    PetscCall(PetscContainerSetPointer(box, cy));
    PetscCall(PetscContainerSetUserDestroy(box, Free));
    PetscCall(PetscObjectCompose((PetscObject)pc, key, (PetscObject)box));
    PetscCall(PetscContainerDestroy(&box));
  }
  pc->ops->apply = Apply;
  *used          = PETSC_TRUE;
  PetscFunctionReturn(PETSC_SUCCESS);
}
