/* Range-checked options (see include/thermoslide/sys.h). */
#include <thermoslide/sys.h>
#include <string.h>

/* The option's text must parse as a number before PETSc reads it, so that a typo is reported with the
 * option's name rather than as a trace from inside PETSc. */
static PetscErrorCode CheckNumber(const char *name, PetscBool integer)
{
  char           buf[256];
  PetscBool      set;
  PetscReal      r;
  PetscInt       i;
  PetscErrorCode e;

  PetscFunctionBeginUser;
  PetscCall(PetscOptionsGetString(NULL, NULL, name, buf, sizeof(buf), &set));
  if (!set) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(TslCaptureBegin());
  e = buf[0] ? (integer ? PetscOptionsStringToInt(buf, &i) : PetscOptionsStringToReal(buf, &r)) : PETSC_ERR_ARG_WRONG;
  PetscCall(TslCaptureEnd());
  PetscCheck(!e, PETSC_COMM_WORLD, PETSC_ERR_USER_INPUT, "option %s %s: expected %s", name, buf[0] ? buf : "(no value)",
             integer ? "a whole number" : "a number");
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TslOptionsReal(PetscOptionItems *PetscOptionsObject, const char *name, const char *help, PetscReal lo, PetscBool open_lo, PetscReal hi,
                              PetscBool open_hi, PetscReal *value)
{
  PetscBool set;

  PetscFunctionBeginUser;
  PetscCall(CheckNumber(name, PETSC_FALSE));
  PetscCall(PetscOptionsReal(name, help, NULL, *value, value, &set));
  PetscCheck(!set || ((open_lo ? *value > lo : *value >= lo) && (open_hi ? *value < hi : *value <= hi)), PETSC_COMM_WORLD, PETSC_ERR_USER_INPUT,
             "option %s %g: expected a value in %s%g, %g%s", name, (double)*value, open_lo ? "(" : "[", (double)lo, (double)hi, open_hi ? ")" : "]");
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TslOptionsInt(PetscOptionItems *PetscOptionsObject, const char *name, const char *help, PetscInt lo, PetscInt hi, PetscInt *value)
{
  PetscBool set;

  PetscFunctionBeginUser;
  PetscCall(CheckNumber(name, PETSC_TRUE));
  PetscCall(PetscOptionsInt(name, help, NULL, *value, value, &set));
  PetscCheck(!set || (*value >= lo && *value <= hi), PETSC_COMM_WORLD, PETSC_ERR_USER_INPUT,
             "option %s %" PetscInt_FMT ": expected a whole number in [%" PetscInt_FMT ", %" PetscInt_FMT "]", name, *value, lo, hi);
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TslOptionsBool(PetscOptionItems *PetscOptionsObject, const char *name, const char *help, PetscBool *value)
{
  char           buf[256];
  PetscBool      set, b;
  PetscErrorCode e;

  PetscFunctionBeginUser;
  PetscCall(PetscOptionsGetString(NULL, NULL, name, buf, sizeof(buf), &set));
  if (set && buf[0]) { /* a bare flag means true */
    PetscCall(TslCaptureBegin());
    e = PetscOptionsStringToBool(buf, &b);
    PetscCall(TslCaptureEnd());
    PetscCheck(!e, PETSC_COMM_WORLD, PETSC_ERR_USER_INPUT, "option %s %s: expected true or false (1 or 0, yes or no)", name, buf);
  }
  PetscCall(PetscOptionsBool(name, help, NULL, *value, value, NULL));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Options PETSc itself reads at start-up or in PetscFinalize: never "unused". */
static PetscBool ReadByPetsc(const char *name)
{
  static const char *const prefixes[] = {"log_",
                                         "malloc",
                                         "memory_",
                                         "options_",
                                         "info",
                                         "help",
                                         "version",
                                         "history",
                                         "on_error",
                                         "no_signal",
                                         "fp_trap",
                                         "objects_",
                                         "display",
                                         "debugger",
                                         "start_in_debugger",
                                         "stop_for_debugger",
                                         "check_pointer",
                                         "use_gpu_aware_mpi",
                                         "skip_petscrc",
                                         "mpi_linear_solver_server",
                                         NULL};
  for (const char *const *p = prefixes; *p; p++)
    if (!strncmp(name, *p, strlen(*p))) return PETSC_TRUE;
  return PETSC_FALSE;
}

/* An option is unused when no rank read it (some are read by rank 0 only, e.g. the partitioner's):
 * rank 0's unused options are checked against the others'. */
PetscErrorCode TslOptionsCheckUnused(MPI_Comm comm, PetscBool fail)
{
  PetscInt    n, n0;
  char      **names, **values;
  PetscMPIInt rank;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  PetscCall(PetscOptionsLeftGet(NULL, &n, &names, &values));
  n0 = n;
  PetscCallMPI(MPI_Bcast(&n0, 1, MPIU_INT, 0, comm));
  for (PetscInt i = 0; i < n0; i++) {
    char      name[256] = "";
    PetscBool here      = PETSC_TRUE, everywhere, ours;
    if (rank == 0) PetscCall(PetscSNPrintf(name, sizeof(name), "%s", names[i][0] == '-' ? names[i] + 1 : names[i]));
    PetscCallMPI(MPI_Bcast(name, (int)sizeof(name), MPI_CHAR, 0, comm));
    if (rank != 0) {
      here = PETSC_FALSE;
      for (PetscInt j = 0; j < n && !here; j++) here = (PetscBool)!strcmp(names[j][0] == '-' ? names[j] + 1 : names[j], name);
    }
    PetscCallMPI(MPI_Allreduce(&here, &everywhere, 1, MPIU_BOOL, MPI_LAND, comm));
    if (!everywhere) continue;
    ours = (PetscBool)!strncmp(name, "tsl_", 4);
    if (fail && ours) {
      PetscCall(PetscOptionsLeftRestore(NULL, &n, &names, &values));
      SETERRQ(comm, PETSC_ERR_USER_INPUT, "unknown option -%s (thermoslide --help lists the -tsl_ options)", name);
    }
    if (!fail && !ours && !ReadByPetsc(name)) PetscCall(PetscPrintf(comm, "warning: option -%s was given but not used (misspelt?)\n", name));
  }
  PetscCall(PetscOptionsLeftRestore(NULL, &n, &names, &values));
  PetscFunctionReturn(PETSC_SUCCESS);
}
