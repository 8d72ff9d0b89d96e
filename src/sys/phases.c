/* Where the wall time goes (include/thermoslide/sys.h): one PETSc event per phase, read back at the end. */
#include <thermoslide/sys.h>
#include <sys/resource.h>

static const char *const PhaseName[TSL_PHASE_COUNT] = {"TslRead", "TslPartition", "TslSetUp", "TslAssembly", "TslContact", "TslSolve", "TslOutput", "TslContactSearch"};
/* Process-wide like PETSc's own event table: the ids of our events and the start of the job. */
static PetscLogEvent  phase_event[TSL_PHASE_COUNT];
static PetscLogDouble job_start;
static PetscBool      phases_on;

PetscErrorCode TslPhasesInitialize(void)
{
  PetscClassId cls;
  PetscBool    active;

  PetscFunctionBeginUser;
  PetscCall(PetscTime(&job_start));
  PetscCall(PetscClassIdRegister("thermoslide", &cls));
  for (PetscInt i = 0; i < TSL_PHASE_COUNT; i++) PetscCall(PetscLogEventRegister(PhaseName[i], cls, &phase_event[i]));
  PetscCall(PetscLogIsActive(&active));
  if (!active) PetscCall(PetscLogDefaultBegin());
  phases_on = PETSC_TRUE;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TslPhaseBegin(TslPhase phase)
{
  PetscFunctionBeginUser;
  if (phases_on) PetscCall(PetscLogEventBegin(phase_event[phase], 0, 0, 0, 0));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TslPhaseEnd(TslPhase phase)
{
  PetscFunctionBeginUser;
  if (phases_on) PetscCall(PetscLogEventEnd(phase_event[phase], 0, 0, 0, 0));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Time of an event in the main stage on this rank (0 for an event never run). */
static PetscErrorCode EventTime(PetscLogEvent e, PetscLogDouble *t)
{
  PetscEventPerfInfo info;

  PetscFunctionBeginUser;
  PetscCall(PetscLogEventGetPerfInfo(0, e, &info));
  *t = info.time;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TslPhasesReport(MPI_Comm comm)
{
  enum { READ, PARTITION, SETUP, ASSEMBLY, CONTACT, PCSETUP, LINEAR, OUTPUT, OTHER, TOTAL, MEM, SEARCH, N };
  static const char *const label[] = {"read", "partition", "set-up", "assembly", "contact", "solver set-up", "linear solve", "output", "other"};
  PetscLogDouble           t[TSL_PHASE_COUNT], pc = 0, now, local[N], maxv[N], mem_sum;
  PetscLogEvent            pcsetup;
  struct rusage            ru;
  PetscMPIInt              size;

  PetscFunctionBeginUser;
  if (!phases_on) PetscFunctionReturn(PETSC_SUCCESS);
  for (PetscInt i = 0; i < TSL_PHASE_COUNT; i++) PetscCall(EventTime(phase_event[i], &t[i]));
  PetscCall(PetscLogEventGetId("PCSetUp", &pcsetup));
  PetscCall(EventTime(pcsetup, &pc));
  PetscCall(PetscTime(&now));
  getrusage(RUSAGE_SELF, &ru);
  local[READ]      = t[TSL_PHASE_READ];
  local[PARTITION] = t[TSL_PHASE_PARTITION];
  local[SETUP]     = t[TSL_PHASE_SETUP];
  local[ASSEMBLY]  = t[TSL_PHASE_ASSEMBLY];
  local[CONTACT]   = t[TSL_PHASE_CONTACT];
  local[PCSETUP]   = pc;
  /* the solves contain the assembly, part of the contact work and the preconditioner set-up */
  local[LINEAR] = PetscMax(0, t[TSL_PHASE_SOLVE] - t[TSL_PHASE_ASSEMBLY] - pc);
  local[OUTPUT] = t[TSL_PHASE_OUTPUT];
  local[SEARCH] = t[TSL_PHASE_SEARCH]; /* part of CONTACT, not a phase of its own in the sum */
  local[TOTAL]  = now - job_start;
  local[OTHER]  = local[TOTAL];
  for (PetscInt i = READ; i < OTHER; i++) local[OTHER] -= local[i];
  local[OTHER] = PetscMax(0, local[OTHER]);
  local[MEM]   = (PetscLogDouble)ru.ru_maxrss / 1024.0; /* kB on Linux */
  PetscCallMPI(MPI_Reduce(local, maxv, N, MPI_DOUBLE, MPI_MAX, 0, comm));
  PetscCallMPI(MPI_Reduce(&local[MEM], &mem_sum, 1, MPI_DOUBLE, MPI_SUM, 0, comm));
  PetscCallMPI(MPI_Comm_size(comm, &size));
  PetscCall(PetscPrintf(comm, "thermoslide: wall time %.3g s:", maxv[TOTAL]));
  for (PetscInt i = READ; i <= OTHER; i++) PetscCall(PetscPrintf(comm, "%s %s %.3g", i == READ ? "" : ",", label[i], maxv[i]));
  if (maxv[SEARCH] > 0) PetscCall(PetscPrintf(comm, " (contact search %.3g)", maxv[SEARCH]));
  PetscCall(PetscPrintf(comm, " (largest over %d ranks); peak memory %.0f MB per rank (largest), %.0f MB in all\n", size, maxv[MEM], mem_sum));
  PetscFunctionReturn(PETSC_SUCCESS);
}
