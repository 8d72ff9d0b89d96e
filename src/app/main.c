/* thermoslide: coupled temperature-displacement analysis of an Abaqus/CalculiX keyword deck.
 *
 *   mpirun -n N thermoslide job.inp [-o DIR] [PETSc options]
 */
#include <thermoslide/mesh.h>
#include <thermoslide/solve.h>
#include <thermoslide/problem.h>
#include <string.h>
#include <strings.h>
#include <sys/stat.h>
#include <errno.h>

static const char Usage[] = "usage: mpirun -n N thermoslide job.inp [-o DIR] [options]\n"
                            "\n"
                            "Runs the coupled temperature-displacement analysis of an Abaqus/CalculiX keyword deck and writes\n"
                            "DIR/<job>.h5 + DIR/<job>.xmf (ParaView) and DIR/<job>.csv (history), <job> being the deck's name\n"
                            "without .inp. DIR defaults to the current directory.\n"
                            "\n"
                            "options:\n"
                            "  -o DIR, -tsl_output_dir DIR   output directory (created if missing)\n"
                            "  -tsl_partition metis|axis_x|axis_y|axis_z   element partition (default metis)\n"
                            "  -tsl_rtol 1e-9                Newton: per-field residual reduction\n"
                            "  -tsl_atol_rel 1e-8            Newton: per-field floor, relative to the largest residual of the job\n"
                            "  -tsl_cutback 0.25             increment factor after a failed increment\n"
                            "  -tsl_growth 1.5               increment factor after an easy increment\n"
                            "  -tsl_easy_its 5               Newton iterations that count as easy\n"
                            "  -tsl_contact_max_its 8        solves of one increment while contact pairing changes\n"
                            "  -tsl_contact_augment_tol 1e-3 augmented Lagrange: multiplier change that ends the augmentations\n"
                            "  --help                        this text; -help lists every PETSc option as well\n"
                            "\n"
                            "Solver defaults: -snes_type newtonls -ksp_type fgmres -pc_type fieldsplit (T, u) with BoomerAMG per field;\n"
                            "a direct solve: -pc_type lu -pc_factor_mat_solver_type mumps. -snes_monitor, -ksp_monitor, -log_view work\n"
                            "as usual. See docs/ for the keyword reference, element table and outputs.\n";

/* Prints the first report of an error once: user errors as a plain message, others with their origin.
 * A blank message is the follow-up of an error already reported by another rank. */
static PetscErrorCode ErrorHandler(MPI_Comm comm, int line, const char *fun, const char *file, PetscErrorCode n, PetscErrorType p, const char *mess,
                                   void *ctx)
{
  PetscMPIInt rank = 0;

  (void)ctx;
  if (p != PETSC_ERROR_INITIAL || !mess || !strcmp(mess, " ")) return n;
  if (comm != PETSC_COMM_SELF) MPI_Comm_rank(comm, &rank);
  if (rank != 0) return n;
  if (n == PETSC_ERR_USER_INPUT || n == PETSC_ERR_NOT_CONVERGED)
    fprintf(stderr, "thermoslide: error: %s\n", mess);
  else
    fprintf(stderr, "thermoslide: error %d in %s() (%s:%d): %s\n", (int)n, fun, file, line, mess);
  fflush(stderr);
  return n;
}

/* Job name: the deck's base name without a trailing .inp. */
static void JobName(const char *deck, char *job, size_t len)
{
  const char *base = strrchr(deck, '/');
  size_t      n;

  base = base ? base + 1 : deck;
  PetscCallAbort(PETSC_COMM_SELF, PetscStrncpy(job, base, len));
  n = strlen(job);
  if (n > 4 && !strcasecmp(job + n - 4, ".inp")) job[n - 4] = 0;
}

/* mkdir -p: creates the directory and any missing parents; 0 or an errno. */
static int MakeDirectories(const char *path)
{
  char   buf[PETSC_MAX_PATH_LEN];
  size_t n = strlen(path);

  if (n == 0 || n >= sizeof(buf)) return ENAMETOOLONG;
  memcpy(buf, path, n + 1);
  for (char *c = buf + 1; *c; c++) {
    if (*c != '/') continue;
    *c = 0;
    if (mkdir(buf, 0777) && errno != EEXIST) return errno;
    *c = '/';
  }
  if (mkdir(buf, 0777) && errno != EEXIST) return errno;
  return 0;
}

static PetscErrorCode Run(const char *deck)
{
  MPI_Comm       comm = PETSC_COMM_WORLD;
  PetscMPIInt    rank;
  TslModel      *global = NULL, *local = NULL;
  TslProblem     prob;
  char           dir[PETSC_MAX_PATH_LEN] = ".", job[256];
  PetscBool      set;
  PetscErrorCode ierr = PETSC_SUCCESS;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  PetscCall(PetscOptionsGetString(NULL, NULL, "-o", dir, sizeof(dir), &set));
  if (!set) PetscCall(PetscOptionsGetString(NULL, NULL, "-tsl_output_dir", dir, sizeof(dir), NULL));
  JobName(deck, job, sizeof(job));
  if (rank == 0) {
    ierr = TslDeckRead(deck, &global);
    if (!ierr) ierr = TslModelCheckSupports(global);
    if (!ierr) {
      int e = MakeDirectories(dir);
      if (e) {
        fprintf(stderr, "thermoslide: error: cannot create the output directory %s: %s\n", dir, strerror(e));
        ierr = PETSC_ERR_FILE_OPEN;
      }
    }
    if (ierr) PetscCall(TslModelDestroy(&global));
  }
  TslCallCollective(comm, ierr);
  PetscCall(PetscPrintf(comm, "thermoslide: %s -> %s/%s.{h5,xmf,csv}\n", deck, dir, job));
  PetscCall(TslMeshDistribute(comm, &global, &local));
  TslCallCollective(comm, TslProblemCreate(comm, local, &prob));
  ierr = TslAnalysisRun(prob, dir, job);
  PetscCall(TslProblemDestroy(&prob));
  PetscCheck(!ierr, comm, ierr, " ");
  PetscCall(PetscPrintf(comm, "thermoslide: completed\n"));
  PetscFunctionReturn(PETSC_SUCCESS);
}

int main(int argc, char **argv)
{
  const char    *deck = NULL;
  PetscErrorCode ierr;

  for (int i = 1; i < argc; i++) {
    if (!strcmp(argv[i], "--help") || !strcmp(argv[i], "-h")) {
      fputs(Usage, stdout);
      return 0;
    }
  }
  PetscCall(PetscInitialize(&argc, &argv, NULL, Usage));
  PetscCall(PetscPushErrorHandler(ErrorHandler, NULL));
  /* the deck is the first argument that is neither an option nor an option's value */
  for (int i = 1; i < argc; i++) {
    if (argv[i][0] == '-') {
      if (i + 1 < argc && argv[i + 1][0] != '-' && strcmp(argv[i], "-help")) i++;
      continue;
    }
    deck = argv[i];
    break;
  }
  if (!deck) {
    PetscBool help;
    PetscCall(PetscOptionsHasHelp(NULL, &help));
    if (!help) PetscCall(PetscFPrintf(PETSC_COMM_WORLD, stderr, "%s", Usage));
    PetscCall(PetscPopErrorHandler());
    PetscCall(PetscFinalize());
    return help ? 0 : 2;
  }
  ierr = Run(deck);
  PetscCall(PetscPopErrorHandler());
  if (ierr && ierr != PETSC_ERR_USER_INPUT && ierr != PETSC_ERR_NOT_CONVERGED && ierr != PETSC_ERR_FILE_OPEN) {
    /* an internal error may have hit one rank only: do not wait for the others */
    PetscMPIInt size;
    MPI_Comm_size(PETSC_COMM_WORLD, &size);
    if (size > 1) MPI_Abort(PETSC_COMM_WORLD, 1);
  }
  PetscCall(PetscFinalize());
  return ierr ? 1 : 0;
}
