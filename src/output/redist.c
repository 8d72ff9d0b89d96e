/* Natural-order redistribution: each rank's items (nodes or elements, any natural indices) are moved
 * to the rank owning the contiguous natural block that holds them, with one MPI_Alltoallv. The block
 * layout is PETSc's PETSC_DECIDE split, so it matches a Vec created with that layout. */
#include "output_impl.h"
#include <string.h>

/* Owner of natural index i in the split of n items over size ranks where the first n % size ranks get
 * n / size + 1 items (PetscSplitOwnership). */
static PetscMPIInt BlockOwner(PetscInt n, PetscMPIInt size, PetscInt i)
{
  const PetscInt q = n / size, rem = n % size, big = rem * (q + 1);
  if (i < big) return (PetscMPIInt)(i / (q + 1));
  return (PetscMPIInt)(rem + (i - big) / q);
}

static PetscInt BlockStart(PetscInt n, PetscMPIInt size, PetscMPIInt r)
{
  const PetscInt q = n / size, rem = n % size;
  return r * q + PetscMin((PetscInt)r, rem);
}

PetscErrorCode TslRedistSetUp(MPI_Comm comm, PetscInt nglobal, PetscInt nlocal, const PetscInt nat[], const char *what, TslRedist *rd)
{
  PetscMPIInt size, rank;
  PetscInt    total, nrecv, *sendnat, *recvnat, *next;
  char       *seen;

  PetscFunctionBeginUser;
  PetscCall(PetscMemzero(rd, sizeof(*rd)));
  PetscCallMPI(MPI_Comm_size(comm, &size));
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  PetscCallMPI(MPI_Allreduce(&nlocal, &total, 1, MPIU_INT, MPI_SUM, comm));
  PetscCheck(total == nglobal, comm, PETSC_ERR_ARG_SIZ, "%s: ranks hand over %" PetscInt_FMT " in all, expected %" PetscInt_FMT, what, total,
             nglobal);
  {
    PetscInt bad = -1, anybad;
    for (PetscInt k = 0; k < nlocal && bad < 0; k++)
      if (nat[k] < 0 || nat[k] >= nglobal) bad = nat[k];
    anybad = bad < 0 ? 0 : 1; /* checked collectively so that no rank is left waiting in a collective */
    PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &anybad, 1, MPIU_INT, MPI_MAX, comm));
    PetscCheck(!anybad, comm, PETSC_ERR_ARG_OUTOFRANGE,
               "%s: natural index out of range [0, %" PetscInt_FMT ") (this rank: %" PetscInt_FMT ", -1 = none)", what, nglobal, bad);
  }

  rd->nglobal = nglobal;
  rd->nlocal  = nlocal;
  rd->bstart  = BlockStart(nglobal, size, rank);
  rd->nblock  = BlockStart(nglobal, size, rank + 1) - rd->bstart;
  PetscCall(PetscCalloc4(size, &rd->scount, size, &rd->sdispl, size, &rd->rcount, size, &rd->rdispl));
  PetscCall(PetscMalloc1(nlocal, &rd->sorder));
  PetscCall(PetscMalloc1(rd->nblock, &rd->rslot));

  /* Counting sort of the local items by destination rank. */
  for (PetscInt k = 0; k < nlocal; k++) rd->scount[BlockOwner(nglobal, size, nat[k])]++;
  for (PetscMPIInt r = 1; r < size; r++) rd->sdispl[r] = rd->sdispl[r - 1] + rd->scount[r - 1];
  PetscCall(PetscMalloc1(size, &next));
  for (PetscMPIInt r = 0; r < size; r++) next[r] = rd->sdispl[r];
  for (PetscInt k = 0; k < nlocal; k++) rd->sorder[next[BlockOwner(nglobal, size, nat[k])]++] = k;
  PetscCall(PetscFree(next));

  PetscCallMPI(MPI_Alltoall(rd->scount, 1, MPI_INT, rd->rcount, 1, MPI_INT, comm));
  for (PetscMPIInt r = 1; r < size; r++) rd->rdispl[r] = rd->rdispl[r - 1] + rd->rcount[r - 1];
  nrecv = rd->rdispl[size - 1] + rd->rcount[size - 1];

  /* The receivers learn where each incoming item goes; every block slot must be filled exactly once,
   * which is what "disjoint and covering 0..N-1" means seen from one block. Checked collectively so
   * that no rank is left waiting in a later collective. */
  PetscCall(PetscMalloc2(nlocal, &sendnat, nrecv, &recvnat));
  for (PetscInt k = 0; k < nlocal; k++) sendnat[k] = nat[rd->sorder[k]];
  PetscCallMPI(MPI_Alltoallv(sendnat, rd->scount, rd->sdispl, MPIU_INT, recvnat, rd->rcount, rd->rdispl, MPIU_INT, comm));
  PetscCall(PetscCalloc1(rd->nblock, &seen));
  {
    PetscInt dup = -1, anydup;
    for (PetscInt k = 0; k < nrecv; k++) {
      const PetscInt slot = recvnat[k] - rd->bstart;
      if (seen[slot] && dup < 0) dup = recvnat[k];
      seen[slot] = 1;
      if (k < rd->nblock) rd->rslot[k] = slot;
    }
    if (nrecv != rd->nblock && dup < 0) dup = rd->bstart; /* a duplicate elsewhere left a hole here */
    anydup = dup < 0 ? 0 : 1;
    PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &anydup, 1, MPIU_INT, MPI_MAX, comm));
    PetscCheck(!anydup, comm, PETSC_ERR_ARG_WRONG,
               "%s: natural indices are not disjoint across ranks (this rank's block: near %" PetscInt_FMT ", -1 = fine)", what, dup);
  }
  PetscCall(PetscFree(seen));
  PetscCall(PetscFree2(sendnat, recvnat));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* src: nlocal records of width bytes in the caller's item order; dst: nblock records in natural order. */
PetscErrorCode TslRedistMove(MPI_Comm comm, const TslRedist *rd, size_t width, const void *src, void *dst)
{
  MPI_Datatype rec;
  char        *sbuf, *rbuf;
  const char  *s = (const char *)src;
  char        *d = (char *)dst;
  PetscMPIInt  iwidth;

  PetscFunctionBeginUser;
  PetscCall(PetscMPIIntCast((PetscInt)width, &iwidth));
  PetscCall(PetscMalloc2(rd->nlocal * width, &sbuf, rd->nblock * width, &rbuf));
  for (PetscInt k = 0; k < rd->nlocal; k++) memcpy(sbuf + k * width, s + rd->sorder[k] * width, width);
  PetscCallMPI(MPI_Type_contiguous(iwidth, MPI_BYTE, &rec));
  PetscCallMPI(MPI_Type_commit(&rec));
  PetscCallMPI(MPI_Alltoallv(sbuf, rd->scount, rd->sdispl, rec, rbuf, rd->rcount, rd->rdispl, rec, comm));
  PetscCallMPI(MPI_Type_free(&rec));
  for (PetscInt k = 0; k < rd->nblock; k++) memcpy(d + rd->rslot[k] * width, rbuf + k * width, width);
  PetscCall(PetscFree2(sbuf, rbuf));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TslRedistReset(TslRedist *rd)
{
  PetscFunctionBeginUser;
  PetscCall(PetscFree4(rd->scount, rd->sdispl, rd->rcount, rd->rdispl));
  PetscCall(PetscFree(rd->sorder));
  PetscCall(PetscFree(rd->rslot));
  PetscCall(PetscMemzero(rd, sizeof(*rd)));
  PetscFunctionReturn(PETSC_SUCCESS);
}
