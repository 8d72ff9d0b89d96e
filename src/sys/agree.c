/* Failures decided by all ranks together (see include/thermoslide/sys.h). */
#include <thermoslide/sys.h>
#include <string.h>

PetscErrorCode TslCaptureBegin(void)
{
  PetscFunctionBeginUser;
  PetscCall(PetscPushErrorHandler(PetscReturnErrorHandler, NULL));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TslCaptureEnd(void)
{
  PetscFunctionBeginUser;
  PetscCall(PetscPopErrorHandler());
  PetscFunctionReturn(PETSC_SUCCESS);
}

static TslFailure Classify(PetscErrorCode e)
{
  if (!e) return TSL_FAIL_NONE;
  if (e == PETSC_ERR_CONV_FAILED || e == PETSC_ERR_NOT_CONVERGED || e == PETSC_ERR_FP) return TSL_FAIL_CONVERGENCE;
  return TSL_FAIL_FATAL;
}

PetscErrorCode TslAgree(MPI_Comm comm, PetscErrorCode local, TslFailure *kind, char msg[])
{
  PetscMPIInt rank, size;
  /* [worst kind, lowest failing rank of that kind (as size - rank, so MAX finds it), its code] */
  int  loc[2], g[2], code = (int)local;
  char text[TSL_FAIL_MSG_LEN] = "";

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  PetscCallMPI(MPI_Comm_size(comm, &size));
  loc[0] = (int)Classify(local);
  PetscCallMPI(MPI_Allreduce(&loc[0], &g[0], 1, MPI_INT, MPI_MAX, comm));
  *kind = (TslFailure)g[0];
  if (msg) msg[0] = 0;
  if (*kind == TSL_FAIL_NONE) PetscFunctionReturn(PETSC_SUCCESS);
  loc[1] = loc[0] == g[0] ? size - rank : 0;
  PetscCallMPI(MPI_Allreduce(&loc[1], &g[1], 1, MPI_INT, MPI_MAX, comm));
  {
    PetscMPIInt root = size - g[1];
    if (rank == root) {
      const char *generic;
      char       *specific = NULL;
      PetscCall(PetscErrorMessage(local, &generic, &specific));
      PetscCall(PetscSNPrintf(text, sizeof(text), "%s", specific && specific[0] ? specific : (generic ? generic : "unknown error")));
    }
    PetscCallMPI(MPI_Bcast(text, (int)sizeof(text), MPI_CHAR, root, comm));
    PetscCallMPI(MPI_Bcast(&code, 1, MPI_INT, root, comm));
    /* the message may end with a newline from the original error: drop it */
    for (size_t n = strlen(text); n > 0 && (text[n - 1] == '\n' || text[n - 1] == ' '); n--) text[n - 1] = 0;
    if (*kind == TSL_FAIL_FATAL) SETERRQ(comm, (PetscErrorCode)code, "%s", text);
    if (msg) PetscCall(PetscSNPrintf(msg, TSL_FAIL_MSG_LEN, "%s (rank %d)", text, (int)root));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TslInjectSetFromOptions(MPI_Comm comm, TslInject *inj)
{
  const char *const kinds[] = {"none", "converge", "internal", "output", "element", "TslInjectKind", "TSL_INJECT_", NULL};
  PetscEnum         kind    = (PetscEnum)TSL_INJECT_NONE;
  PetscInt          r       = 0;
  PetscMPIInt       rank;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  inj->step  = 1;
  inj->count = 1;
  PetscOptionsBegin(comm, NULL, "thermoslide fault injection (testing aid)", NULL);
  PetscCall(PetscOptionsEnum("-tsl_debug_fail_kind", "testing aid: inject a failure of this kind", NULL, kinds, kind, &kind, NULL));
  PetscCall(TslOptionsInt(PetscOptionsObject, "-tsl_debug_fail_rank", "testing aid: the rank that fails", 0, PETSC_MAX_INT, &r));
  PetscCall(
      TslOptionsInt(PetscOptionsObject, "-tsl_debug_fail_step", "testing aid: the step (1-based) in which it fails", 1, PETSC_MAX_INT, &inj->step));
  PetscCall(TslOptionsInt(PetscOptionsObject, "-tsl_debug_fail_count", "testing aid: how many evaluations fail", 1, PETSC_MAX_INT, &inj->count));
  PetscOptionsEnd();
  inj->kind = (TslInjectKind)kind;
  inj->mine = (PetscBool)(inj->kind != TSL_INJECT_NONE && r == rank);
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscBool TslInjectNow(TslInject *inj, TslInjectKind kind, PetscInt step)
{
  if (!inj->mine || inj->kind != kind || inj->step != step || inj->count <= 0) return PETSC_FALSE;
  inj->count--;
  return PETSC_TRUE;
}
