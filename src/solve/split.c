/* The default preconditioner of the implicit steps: the temperature-displacement block Gauss-Seidel of
 * PETSc's multiplicative field split (temperature first, then the displacement with the coupling block's
 * update), built so that the displacement block is held once.
 *
 * PCFIELDSPLIT extracts the displacement block as an AIJ matrix and keeps it for the next set-up, and
 * BoomerAMG (PCHYPRE) copies it again into hypre's format: with the Jacobian, the block's values were
 * held three times. Here, when the displacement solver is hypre, the block is extracted, converted to a
 * MATHYPRE matrix (which PCHYPRE takes without a copy) and the AIJ extract freed, and the previous
 * hierarchy is freed before the next extraction: the 3D contact benchmark's peak memory at N = 128 fell
 * from 1 205 to 1 046 MB (docs/running.md "Contact at scale"). The temperature block (a sixteenth of the
 * Jacobian in 3D) and the coupling block (displacement rows, temperature columns) stay AIJ extracts,
 * reused while the pattern is unchanged. The arithmetic is the field split's: y_T = B_T^-1 b_T,
 * y_u = B_u^-1 (b_u - A_uT y_T).
 *
 * The sub-solvers keep the field split's options prefixes (-fieldsplit_T_..., -fieldsplit_u_...), so the
 * defaults and a user's sub-solver options apply unchanged; -pc_fieldsplit_type additive drops the coupling
 * update; anything else of PETSc's field split (Schur, more splits) is `-pc_type fieldsplit`. */
#include "solve_impl.h"
#include <string.h>

typedef struct {
  IS               is[2];  /* temperature, displacement */
  KSP              ksp[2]; /* sub-solvers */
  Mat              A[2];   /* the blocks as the sub-solvers hold them (AIJ extract, or hypre's copy) */
  Mat              Aut;    /* displacement rows, temperature columns */
  VecScatter       sc[2];  /* global vector -> block vectors */
  Vec              x[2], y[2], w;
  PetscBool        additive; /* -pc_fieldsplit_type additive */
  PetscObjectState state;    /* nonzero state of the operator the blocks were extracted from */
  Mat              from;     /* ... and the operator itself (not referenced) */
} Split;

static const char *const prefix[2] = {"fieldsplit_T_", "fieldsplit_u_"};

static PetscErrorCode CreateSubSolver(PC pc, Split *s, PetscInt i)
{
  const char *pre;

  PetscFunctionBeginUser;
  PetscCall(KSPCreate(PetscObjectComm((PetscObject)pc), &s->ksp[i]));
  PetscCall(PetscObjectIncrementTabLevel((PetscObject)s->ksp[i], (PetscObject)pc, 1));
  PetscCall(PCGetOptionsPrefix(pc, &pre));
  PetscCall(KSPSetOptionsPrefix(s->ksp[i], pre));
  PetscCall(KSPAppendOptionsPrefix(s->ksp[i], prefix[i]));
  PetscCall(KSPSetFromOptions(s->ksp[i]));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Frees the blocks and sub-solvers (a new pattern, or the end). */
PetscErrorCode TslSplitReset(PC pc)
{
  Split *s;

  PetscFunctionBeginUser;
  PetscCall(PCShellGetContext(pc, &s));
  if (!s) PetscFunctionReturn(PETSC_SUCCESS);
  for (PetscInt i = 0; i < 2; i++) {
    PetscCall(KSPDestroy(&s->ksp[i]));
    PetscCall(MatDestroy(&s->A[i]));
    PetscCall(VecScatterDestroy(&s->sc[i]));
    PetscCall(VecDestroy(&s->x[i]));
    PetscCall(VecDestroy(&s->y[i]));
  }
  PetscCall(MatDestroy(&s->Aut));
  PetscCall(VecDestroy(&s->w));
  s->from = NULL;
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode Destroy(PC pc)
{
  Split *s;

  PetscFunctionBeginUser;
  PetscCall(TslSplitReset(pc));
  PetscCall(PCShellGetContext(pc, &s));
  PetscCall(ISDestroy(&s->is[0]));
  PetscCall(ISDestroy(&s->is[1]));
  PetscCall(PetscFree(s));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode SetUp(PC pc)
{
  Split           *s;
  Mat              P;
  PetscObjectState state;
  MatReuse         reuse;
  PC               sub;
  PetscBool        hypre;

  PetscFunctionBeginUser;
  PetscCall(PCShellGetContext(pc, &s));
  PetscCall(PCGetOperators(pc, NULL, &P));
  PetscCall(MatGetNonzeroState(P, &state));
  if (s->from != P || s->state != state) PetscCall(TslSplitReset(pc));
  reuse    = s->from ? MAT_REUSE_MATRIX : MAT_INITIAL_MATRIX;
  s->from  = P;
  s->state = state;
  if (!s->ksp[0]) {
    Vec X;
    PetscCall(MatCreateVecs(P, &X, NULL));
    for (PetscInt i = 0; i < 2; i++) {
      PetscCall(CreateSubSolver(pc, s, i));
      {
        PetscInt n;
        PetscCall(ISGetLocalSize(s->is[i], &n));
        PetscCall(VecCreateMPI(PetscObjectComm((PetscObject)pc), n, PETSC_DETERMINE, &s->x[i]));
        PetscCall(VecDuplicate(s->x[i], &s->y[i]));
        PetscCall(VecScatterCreate(X, s->is[i], s->x[i], NULL, &s->sc[i]));
      }
    }
    PetscCall(VecDuplicate(s->x[1], &s->w));
    PetscCall(VecDestroy(&X));
  }
  /* temperature block: an AIJ extract, reused while the pattern holds */
  PetscCall(MatCreateSubMatrix(P, s->is[0], s->is[0], reuse, &s->A[0]));
  PetscCall(KSPSetOperators(s->ksp[0], s->A[0], s->A[0]));
  /* coupling block */
  if (!s->additive) PetscCall(MatCreateSubMatrix(P, s->is[1], s->is[0], s->Aut ? MAT_REUSE_MATRIX : MAT_INITIAL_MATRIX, &s->Aut));
  /* displacement block */
  PetscCall(KSPGetPC(s->ksp[1], &sub));
  PetscCall(PetscObjectTypeCompare((PetscObject)sub, PCHYPRE, &hypre));
  {
    MatNullSpace sp = NULL;
    PetscCall(PetscObjectQuery((PetscObject)s->is[1], "nearnullspace", (PetscObject *)&sp));
    if (hypre) {
      Mat Au;
      /* the previous hierarchy and hypre copy go first (a new solver object: PCHYPRE frees its hierarchy
       * only when it builds the next one), then the extract lives only until it is converted */
      PetscCall(KSPDestroy(&s->ksp[1]));
      PetscCall(MatDestroy(&s->A[1]));
      PetscCall(CreateSubSolver(pc, s, 1));
      PetscCall(MatCreateSubMatrix(P, s->is[1], s->is[1], MAT_INITIAL_MATRIX, &Au));
      PetscCall(MatConvert(Au, MATHYPRE, MAT_INITIAL_MATRIX, &s->A[1]));
      /* the node block size (BoomerAMG's number of functions), which the conversion drops */
      PetscCall(MatSetBlockSizesFromMats(s->A[1], Au, Au));
      PetscCall(MatDestroy(&Au));
    } else PetscCall(MatCreateSubMatrix(P, s->is[1], s->is[1], s->A[1] ? MAT_REUSE_MATRIX : MAT_INITIAL_MATRIX, &s->A[1]));
    if (sp) PetscCall(MatSetNearNullSpace(s->A[1], sp));
  }
  PetscCall(KSPSetOperators(s->ksp[1], s->A[1], s->A[1]));
  for (PetscInt i = 0; i < 2; i++) {
    PC             subpc;
    PCFailedReason why;
    PetscCall(KSPSetUp(s->ksp[i]));
    PetscCall(KSPGetPC(s->ksp[i], &subpc));
    PetscCall(PCGetFailedReason(subpc, &why));
    if (why != PC_NOERROR) PetscCall(PCSetFailedReason(pc, PC_SUBPC_ERROR));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Solves one block; a failed sub-solve poisons the result, so the outer Krylov method stops on it. */
static PetscErrorCode SubSolve(PC pc, Split *s, PetscInt i)
{
  KSPConvergedReason r;

  PetscFunctionBeginUser;
  PetscCall(KSPSolve(s->ksp[i], s->x[i], s->y[i]));
  PetscCall(KSPGetConvergedReason(s->ksp[i], &r));
  if (r < 0) {
    PetscCall(PCSetFailedReason(pc, PC_SUBPC_ERROR));
    PetscCall(VecSetInf(s->y[i]));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode Apply(PC pc, Vec b, Vec y)
{
  Split *s;

  PetscFunctionBeginUser;
  PetscCall(PCShellGetContext(pc, &s));
  PetscCall(VecScatterBegin(s->sc[0], b, s->x[0], INSERT_VALUES, SCATTER_FORWARD));
  PetscCall(VecScatterEnd(s->sc[0], b, s->x[0], INSERT_VALUES, SCATTER_FORWARD));
  PetscCall(VecScatterBegin(s->sc[1], b, s->x[1], INSERT_VALUES, SCATTER_FORWARD));
  PetscCall(VecScatterEnd(s->sc[1], b, s->x[1], INSERT_VALUES, SCATTER_FORWARD));
  PetscCall(SubSolve(pc, s, 0));
  if (!s->additive) {
    PetscCall(MatMult(s->Aut, s->y[0], s->w));
    PetscCall(VecAXPY(s->x[1], -1.0, s->w));
  }
  PetscCall(SubSolve(pc, s, 1));
  for (PetscInt i = 0; i < 2; i++) {
    PetscCall(VecScatterBegin(s->sc[i], s->y[i], y, INSERT_VALUES, SCATTER_REVERSE));
    PetscCall(VecScatterEnd(s->sc[i], s->y[i], y, INSERT_VALUES, SCATTER_REVERSE));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode View(PC pc, PetscViewer v)
{
  Split    *s;
  PetscBool ascii;

  PetscFunctionBeginUser;
  PetscCall(PCShellGetContext(pc, &s));
  PetscCall(PetscObjectTypeCompare((PetscObject)v, PETSCVIEWERASCII, &ascii));
  if (!ascii) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(PetscViewerASCIIPrintf(v, "thermoslide field split (%s): temperature block, then displacement block%s\n",
                                   s->additive ? "additive" : "multiplicative", s->additive ? "" : " with the coupling block's update"));
  for (PetscInt i = 0; i < 2; i++) {
    PetscCall(PetscViewerASCIIPrintf(v, "%s block solver (options prefix %s):\n", i ? "displacement" : "temperature", prefix[i]));
    PetscCall(PetscViewerASCIIPushTab(v));
    if (s->ksp[i]) PetscCall(KSPView(s->ksp[i], v));
    else PetscCall(PetscViewerASCIIPrintf(v, "not set up\n"));
    PetscCall(PetscViewerASCIIPopTab(v));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* -pc_fieldsplit_type under options prefix pre: multiplicative (the default) or additive; any other type is
 * a user error that names the option. */
PetscErrorCode TslSplitOptionType(const char *pre, PetscBool *additive)
{
  char type[64] = "multiplicative";

  PetscFunctionBeginUser;
  PetscCall(PetscOptionsGetString(NULL, pre, "-pc_fieldsplit_type", type, sizeof(type), NULL));
  PetscCheck(!strcmp(type, "multiplicative") || !strcmp(type, "additive"), PETSC_COMM_WORLD, PETSC_ERR_USER_INPUT,
             "option -pc_fieldsplit_type %s: thermoslide's field split is multiplicative or additive; add -pc_type fieldsplit for PETSc's "
             "field split of that type",
             type);
  *additive = (PetscBool)!strcmp(type, "additive");
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Reads the split's type (TslSplitOptionType) into pc. */
PetscErrorCode TslSplitSetFromOptions(PC pc)
{
  Split      *s;
  const char *pre;

  PetscFunctionBeginUser;
  PetscCall(PCShellGetContext(pc, &s));
  PetscCall(PCGetOptionsPrefix(pc, &pre));
  PetscCall(TslSplitOptionType(pre, &s->additive));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Makes pc thermoslide's split over the temperature and displacement index sets (referenced). */
PetscErrorCode TslSplitSetUp(PC pc, IS is_theta, IS is_u)
{
  Split *s;

  PetscFunctionBeginUser;
  PetscCall(PetscNew(&s));
  PetscCall(PetscObjectReference((PetscObject)is_theta));
  PetscCall(PetscObjectReference((PetscObject)is_u));
  s->is[0] = is_theta;
  s->is[1] = is_u;
  PetscCall(PCSetType(pc, PCSHELL));
  PetscCall(PCShellSetContext(pc, s));
  PetscCall(PCShellSetName(pc, "thermoslide field split"));
  PetscCall(PCShellSetSetUp(pc, SetUp));
  PetscCall(PCShellSetApply(pc, Apply));
  PetscCall(PCShellSetView(pc, View));
  PetscCall(PCShellSetDestroy(pc, Destroy));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Whether pc is thermoslide's split. */
PetscErrorCode TslSplitIs(PC pc, PetscBool *is)
{
  const char *name = NULL;
  PetscBool   shell;

  PetscFunctionBeginUser;
  *is = PETSC_FALSE;
  PetscCall(PetscObjectTypeCompare((PetscObject)pc, PCSHELL, &shell));
  if (!shell) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(PCShellGetName(pc, &name));
  *is = (PetscBool)(name && !strcmp(name, "thermoslide field split"));
  PetscFunctionReturn(PETSC_SUCCESS);
}
