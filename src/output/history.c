/* History output: one CSV row per increment, written by rank 0 and flushed row by row so that a
 * crashed run still leaves every completed increment readable in <job>.csv.part. */
#include "output_impl.h"
#include <errno.h>
#include <string.h>
#include <unistd.h>
#include <stdlib.h>

PetscErrorCode TslHistoryCreate(MPI_Comm comm, const char *dir, const char *jobname, PetscInt ncol, const char *const names[], TslHistory *hist)
{
  TslHistory h;
  int        err = 0;

  PetscFunctionBeginUser;
  PetscCheck(hist, comm, PETSC_ERR_ARG_NULL, "TslHistoryCreate(): hist is NULL");
  *hist = NULL;
  PetscCall(TslOutputCheckName(comm, "Job", jobname, "/:"));
  PetscCheck(ncol >= 1, comm, PETSC_ERR_ARG_OUTOFRANGE, "History needs at least one column, got %" PetscInt_FMT, ncol);
  /* Plain CSV without quoting: a column name must not need it. */
  for (PetscInt c = 0; c < ncol; c++) PetscCall(TslOutputCheckName(comm, "History column", names[c], ",\""));
  PetscCall(PetscNew(&h));
  h->comm = comm;
  h->ncol = ncol;
  PetscCallMPI(MPI_Comm_rank(comm, &h->rank));
  PetscCall(TslOutputPath(comm, dir, jobname, ".csv.part", h->part, sizeof(h->part)));
  PetscCall(TslOutputPath(comm, dir, jobname, ".csv", h->final, sizeof(h->final)));
  PetscCall(PetscStrncpy(h->dir, dir ? dir : "", sizeof(h->dir)));
  PetscCall(PetscStrncpy(h->job, jobname, sizeof(h->job)));
  if (h->rank == 0) {
    h->fp = fopen(h->part, "w");
    if (!h->fp)
      err = errno;
    else {
      for (PetscInt c = 0; c < ncol; c++) fprintf(h->fp, "%s%s", c ? "," : "", names[c]);
      fprintf(h->fp, "\n");
      if (fflush(h->fp) || ferror(h->fp)) err = errno ? errno : EIO;
    }
  }
  *hist = h;
  PetscCallMPI(MPI_Bcast(&err, 1, MPI_INT, 0, comm));
  if (err) {
    char path[PETSC_MAX_PATH_LEN];
    PetscCall(PetscStrncpy(path, h->part, sizeof(path)));
    PetscCall(TslHistoryDestroy(hist));
    SETERRQ(comm, PETSC_ERR_FILE_OPEN, "Cannot create history file %s: %s", path, strerror(err));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Collective: the values are taken from rank 0, and a write failure is raised on every rank. */
PetscErrorCode TslHistoryAppend(TslHistory hist, const PetscReal vals[])
{
  int err = 0;

  PetscFunctionBeginUser;
  PetscCheck(!hist->finalized, hist->comm, PETSC_ERR_ORDER, "History %s already finalized", hist->final);
  if (hist->rank == 0) {
    for (PetscInt c = 0; c < hist->ncol; c++) fprintf(hist->fp, "%s%.10e", c ? "," : "", (double)vals[c]);
    fprintf(hist->fp, "\n");
    if (fflush(hist->fp) || ferror(hist->fp)) err = errno ? errno : EIO;
  }
  PetscCall(TslOutputCheckRoot(hist->comm, err, "write history file", hist->part));
  hist->nrow++;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TslHistoryFinalize(TslHistory hist, const char *tag)
{
  int err = 0;

  PetscFunctionBeginUser;
  PetscCheck(!hist->finalized, hist->comm, PETSC_ERR_ORDER, "History %s already finalized", hist->final);
  if (tag) PetscCall(TslOutputFinalPath(hist->comm, hist->dir, hist->job, tag, ".csv", hist->final, sizeof(hist->final)));
  if (hist->rank == 0) {
    if (fclose(hist->fp)) err = errno;
    hist->fp = NULL;
  }
  PetscCall(TslOutputCheckRoot(hist->comm, err, "close history file", hist->part));
  if (hist->rank == 0 && rename(hist->part, hist->final)) err = errno;
  PetscCall(TslOutputCheckRoot(hist->comm, err, "rename the finished history to", hist->final));
  hist->finalized = PETSC_TRUE;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Collective. Without a Finalize the .csv.part goes and an earlier <job>.csv stays. */
PetscErrorCode TslHistoryDestroy(TslHistory *hist)
{
  TslHistory h;

  PetscFunctionBeginUser;
  if (!hist || !*hist) PetscFunctionReturn(PETSC_SUCCESS);
  h = *hist;
  if (h->fp) (void)fclose(h->fp);
  if (!h->finalized) {
    if (h->rank == 0) (void)unlink(h->part);
    PetscCallMPI(MPI_Barrier(h->comm));
  }
  PetscCall(PetscFree(h));
  *hist = NULL;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Collective: rank 0 copies the data rows 1..nrow of src (after its header) into this history. */
PetscErrorCode TslHistoryCopyRows(TslHistory hist, const char *src, PetscInt nrow)
{
  int      err = 0;
  PetscInt got = 0;

  PetscFunctionBeginUser;
  if (hist->rank == 0) {
    FILE *in = fopen(src, "r");
    if (!in) err = errno;
    else {
      char     buf[4096];
      PetscInt k = -1; /* the header's line first */
      while (k < nrow && fgets(buf, sizeof(buf), in)) {
        const PetscBool eol = strchr(buf, '\n') ? PETSC_TRUE : PETSC_FALSE;
        if (k >= 0) fputs(buf, hist->fp);
        if (eol) {
          if (k >= 0) got++;
          k++;
        }
      }
      fclose(in);
      if (fflush(hist->fp) || ferror(hist->fp)) err = errno ? errno : EIO;
    }
  }
  PetscCall(TslOutputCheckRoot(hist->comm, err, "copy the history rows of", src));
  PetscCallMPI(MPI_Bcast(&got, 1, MPIU_INT, 0, hist->comm));
  hist->nrow += got;
  PetscCheck(got == nrow, hist->comm, PETSC_ERR_FILE_UNEXPECTED, "%s has %" PetscInt_FMT " history rows, the restart point %" PetscInt_FMT, src, got, nrow);
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscInt TslHistoryRowCount(TslHistory hist)
{
  return hist->nrow;
}
