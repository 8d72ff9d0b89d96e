/* Printed tables in rank order with bounded memory (include/thermoslide/output.h). */
#include <thermoslide/output.h>
#include <thermoslide/sys.h>
#include <stdarg.h>
#include <stdio.h>

#define CHUNK 65536
enum { TAG_GO = 7101, TAG_TEXT = 7102 };

struct _p_TslPrintSink {
  MPI_Comm comm;
  int      rank;
  char     buf[CHUNK];
  size_t   len;
};

/* Rank 0 writes the chunk to stdout; any other rank sends it to rank 0 (an empty chunk ends a rank's text). */
static PetscErrorCode Flush(TslPrintSink s, PetscBool last)
{
  PetscFunctionBeginUser;
  if (s->rank == 0) {
    if (s->len) (void)fwrite(s->buf, 1, s->len, stdout);
  } else {
    if (s->len) PetscCallMPI(MPI_Send(s->buf, (int)s->len, MPI_CHAR, 0, TAG_TEXT, s->comm));
    if (last) PetscCallMPI(MPI_Send(s->buf, 0, MPI_CHAR, 0, TAG_TEXT, s->comm));
  }
  s->len = 0;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TslPrintLine(TslPrintSink s, const char *fmt, ...)
{
  va_list ap;
  int     n;

  PetscFunctionBeginUser;
  va_start(ap, fmt);
  n = vsnprintf(s->buf + s->len, CHUNK - s->len, fmt, ap);
  va_end(ap);
  PetscCheck(n >= 0 && n < CHUNK, PETSC_COMM_SELF, PETSC_ERR_ARG_SIZ, "printed line longer than %d characters", CHUNK);
  if (s->len + (size_t)n >= CHUNK) { /* did not fit: send what is there, then write the line again */
    PetscCall(Flush(s, PETSC_FALSE));
    va_start(ap, fmt);
    n = vsnprintf(s->buf, CHUNK, fmt, ap);
    va_end(ap);
  }
  s->len += (size_t)n;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TslPrintOrdered(MPI_Comm comm, PetscErrorCode (*emit)(TslPrintSink sink, void *ctx), void *ctx)
{
  TslPrintSink   s;
  PetscMPIInt    size;
  PetscErrorCode e = PETSC_SUCCESS;
  TslFailure     fail;

  PetscFunctionBeginUser;
  PetscCall(PetscNew(&s));
  s->comm = comm;
  PetscCallMPI(MPI_Comm_rank(comm, &s->rank));
  PetscCallMPI(MPI_Comm_size(comm, &size));
  PetscCall(TslCaptureBegin());
  if (s->rank == 0) {
    (void)fflush(stdout);
    e = emit(s, ctx);
    if (!e) e = Flush(s, PETSC_TRUE);
    for (PetscMPIInt r = 1; r < size; r++) {
      int go = 1;
      PetscCallMPI(MPI_Send(&go, 1, MPI_INT, r, TAG_GO, comm));
      for (;;) {
        MPI_Status st;
        int        n;
        PetscCallMPI(MPI_Probe(r, TAG_TEXT, comm, &st));
        PetscCallMPI(MPI_Get_count(&st, MPI_CHAR, &n));
        PetscCallMPI(MPI_Recv(s->buf, n, MPI_CHAR, r, TAG_TEXT, comm, MPI_STATUS_IGNORE));
        if (n == 0) break;
        (void)fwrite(s->buf, 1, (size_t)n, stdout);
      }
    }
    (void)fflush(stdout);
  } else {
    int go;
    PetscCallMPI(MPI_Recv(&go, 1, MPI_INT, 0, TAG_GO, comm, MPI_STATUS_IGNORE));
    e = emit(s, ctx);
    if (e) s->len = 0; /* a failed rank still ends its text, so that rank 0 moves on */
    PetscCall(Flush(s, PETSC_TRUE));
  }
  PetscCall(TslCaptureEnd());
  PetscCall(PetscFree(s));
  PetscCall(TslAgree(comm, e, &fail, NULL));
  PetscCheck(!fail, comm, PETSC_ERR_PLIB, "printing a table failed");
  PetscFunctionReturn(PETSC_SUCCESS);
}
