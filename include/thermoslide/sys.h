/* thermoslide system layer: failures decided by all ranks together.
 *
 * A piece of work that runs rank by rank (element and contact evaluation, a file operation) may fail on
 * some ranks only. If the failing rank simply returned, the others would wait for it for ever in their
 * next collective call. So such work runs under TslCaptureBegin/End, which collects its outcome without
 * printing, and TslAgree then decides on all ranks at once:
 *   - nothing failed anywhere: TSL_FAIL_NONE;
 *   - a convergence-type failure (PETSC_ERR_CONV_FAILED, PETSC_ERR_NOT_CONVERGED, PETSC_ERR_FP) and nothing
 *     worse: TSL_FAIL_CONVERGENCE on every rank, with the first failing rank's message in msg; the caller
 *     turns it into a failed increment (cutback);
 *   - anything else: the same error is raised on every rank with the first failing rank's message, which
 *     the job log prints once.
 */
#pragma once
#include <thermoslide/compat.h>
#include <petscvec.h> /* TslGhostUpdate */
#include <stdint.h>

typedef enum { TSL_FAIL_NONE = 0, TSL_FAIL_CONVERGENCE = 1, TSL_FAIL_FATAL = 2 } TslFailure;

#define TSL_FAIL_MSG_LEN 1024

/* Start collecting errors quietly (no message printed); every Begin needs its End. */
PetscErrorCode TslCaptureBegin(void);
PetscErrorCode TslCaptureEnd(void);

/* Collective. local: this rank's outcome (the error code of the captured work, 0 if none). Raises the
 * agreed error on all ranks for a fatal failure; otherwise sets *kind and, for a convergence failure,
 * msg (may be NULL; TSL_FAIL_MSG_LEN characters) to "rank R: <message>". */
PetscErrorCode TslAgree(MPI_Comm comm, PetscErrorCode local, TslFailure *kind, char msg[]);

/* Test aid: a failure injected on one rank, to prove that no failure on one rank hangs the others.
 * Options: -tsl_debug_fail_kind converge|internal|output|element -tsl_debug_fail_rank R -tsl_debug_fail_step S
 * [-tsl_debug_fail_count N]. Each object that injects keeps its own copy (no global state). */
typedef enum { TSL_INJECT_NONE, TSL_INJECT_CONVERGE, TSL_INJECT_INTERNAL, TSL_INJECT_OUTPUT, TSL_INJECT_ELEMENT } TslInjectKind;
typedef struct {
  PetscBool     mine; /* this rank injects */
  TslInjectKind kind;
  PetscInt      step, count;
} TslInject;

PetscErrorCode TslInjectSetFromOptions(MPI_Comm comm, TslInject *inj);
/* PETSC_TRUE when the calling rank should fail now with `kind` in `step` (1-based); counts down. */
PetscBool TslInjectNow(TslInject *inj, TslInjectKind kind, PetscInt step);

/* Options with a range, inside PetscOptionsBegin/End (pass PetscOptionsObject). A value that is not a
 * number, or lies outside [lo, hi], is a user error naming the option and the range; never a PETSc trace,
 * a silent clamp or an endless loop. open_lo / open_hi exclude the bound itself. */
PetscErrorCode TslOptionsReal(PetscOptionItems *PetscOptionsObject, const char *name, const char *help, PetscReal lo, PetscBool open_lo, PetscReal hi,
                              PetscBool open_hi, PetscReal *value);
PetscErrorCode TslOptionsInt(PetscOptionItems *PetscOptionsObject, const char *name, const char *help, PetscInt lo, PetscInt hi, PetscInt *value);
/* VecGhostUpdateBegin and End on a ghosted vector; nothing on one rank, where a vector has no ghosts (the
 * scatter's bookkeeping cost small explicit jobs 20 % of their time). Used by every ghost update of the
 * solution and residual vectors, implicit and explicit. */
PetscErrorCode TslGhostUpdate(Vec v, InsertMode mode, ScatterMode direction);

/* Faults in the pages of a large array just allocated (at least 4 MB; anything smaller is left alone) with one
 * system call (madvise MADV_POPULATE_WRITE, Linux 5.14), instead of one page fault per 4 kB page on first
 * touch: in a process of 1.5 GB on this machine 400 MB took 1.3 s of faults against 0.16 s. The contents are
 * unchanged; a kernel without the call leaves the pages to fault in as before. */
void TslPrefault(void *p, size_t bytes);

/* A true/false option (a bare flag is true); any other text is an error naming the option. */
PetscErrorCode TslOptionsBool(PetscOptionItems *PetscOptionsObject, const char *name, const char *help, PetscBool *value);

/* Options given but not read. fail: a -tsl_ option nobody read is a user error (a misspelt option of ours
 * must not silently leave a default in place); otherwise each unused option is a warning in the log
 * (PETSc's own start-up and finalize-time options excepted). Collective. */
PetscErrorCode TslOptionsCheckUnused(MPI_Comm comm, PetscBool fail);

/* Where the wall time goes: phases of a job, each also a PETSc log event (so -log_view lists them). The
 * report at the end of a job prints the largest time over the ranks per phase and the peak memory.
 * Assembly (the SNES callbacks) and PETSc's PCSetUp run inside the solve phase; the report subtracts them
 * from it ("linear solve"), so the printed parts add up to the whole. */
typedef enum {
  TSL_PHASE_READ,      /* deck read and checks (rank 0) */
  TSL_PHASE_PARTITION, /* METIS and distribution */
  TSL_PHASE_SETUP,     /* problem set-up: dof maps, ghosts, preallocation */
  TSL_PHASE_ASSEMBLY,  /* residual and Jacobian evaluation */
  TSL_PHASE_CONTACT,   /* contact search and update between the solves */
  TSL_PHASE_SOLVE,     /* the nonlinear solves (SNESSolve: contains assembly and solver set-up) */
  TSL_PHASE_OUTPUT,    /* field frames, history, prints */
  TSL_PHASE_SEARCH,    /* within TSL_PHASE_CONTACT: the pairing itself (held-region check and search, not the
                          matrix pattern rebuilt after it), printed as "contact search" */
  TSL_PHASE_COUNT
} TslPhase;

/* Registers the events and starts PETSc's default logging if nothing else did. Call once. */
PetscErrorCode TslPhasesInitialize(void);
PetscErrorCode TslPhaseBegin(TslPhase phase);
PetscErrorCode TslPhaseEnd(TslPhase phase);
/* Collective: one line "time ...; memory ..." on rank 0 (total: wall time since TslPhasesInitialize). */
PetscErrorCode TslPhasesReport(MPI_Comm comm);

/* Largest eigenvalue of the symmetric n x n matrix S (row-major, n <= TSL_EIGEN_MAX_N, overwritten), from
 * above: within a relative 1e-12 and never below it (src/sys/eigen.c). */
#define TSL_EIGEN_MAX_N 64
PetscReal TslLargestEigenvalue(PetscInt n, PetscReal S[]);

/* Asked to stop (src/sys/stop.c): SIGUSR1 (what mpirun forwards to its ranks, and what a batch system sends ahead
 * of the wall-time limit when told to, e.g. Slurm's --signal=USR1@300), SIGTERM, SIGINT or SIGXCPU reaching a
 * rank makes the job stop at the next check, between Newton iterations or explicit increments, as a failed run
 * does: the last converged state saved, the exit status 128 + the signal. A second such signal ends the process
 * at once. TslStopInstall after PetscInitialize (it replaces PETSc's handlers of those signals). */
PetscErrorCode TslStopInstall(void);
/* The signal this rank received, or the one agreed by TslStopRequested (0: none); async-signal-safe to read. */
int TslStopLocal(void);
/* Collective: the signal any rank received (the largest number), 0 if none; from then on TslStopLocal gives it on
 * every rank. */
PetscErrorCode TslStopRequested(MPI_Comm comm, int *sig);
/* "SIGTERM", ... */
const char *TslStopName(int sig);

/* Collective rendezvous by key (src/sys/rendezvous.c): every rank offers na answers (keys akey[kl*i..], w reals
 * aval[w*i..] each) and asks nq questions (keys qkey[kl*q..]); each question gets the values of the answer with its
 * key in qval[w*q..] and found[q] true, or found[q] false when no rank offered that key (of equal keys the first
 * offered is taken). The answers and questions meet on the rank their key hashes to, so nothing of global size is
 * held anywhere. */
PetscErrorCode TslRendezvous(MPI_Comm comm, PetscInt kl, PetscInt w, PetscInt na, const int64_t akey[], const PetscReal aval[], PetscInt nq, const int64_t qkey[],
                             PetscReal qval[], PetscBool found[]);
