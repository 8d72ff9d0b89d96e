/* Ghost updates of the explicit procedure's vectors (see include/thermoslide/sys.h). */
#include <thermoslide/sys.h>

PetscErrorCode TslGhostUpdate(Vec v, InsertMode mode, ScatterMode direction)
{
  PetscMPIInt size;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_size(PetscObjectComm((PetscObject)v), &size));
  if (size == 1) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(VecGhostUpdateBegin(v, mode, direction));
  PetscCall(VecGhostUpdateEnd(v, mode, direction));
  PetscFunctionReturn(PETSC_SUCCESS);
}
