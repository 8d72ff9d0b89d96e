/* thermoslide: coupled temperature-displacement analysis of an Abaqus/CalculiX keyword deck.
 *
 *   mpirun -n N thermoslide job.inp [-o DIR] [PETSc options]
 */
#define _DEFAULT_SOURCE /* setenv, unsetenv */
#include <thermoslide/mesh.h>
#include <thermoslide/solve.h>
#include <thermoslide/problem.h>
#include <thermoslide/sys.h>
#include <string.h>
#include <strings.h>
#include <sys/stat.h>
#include <errno.h>
#include <stdlib.h>
#include <stdio.h>
#include <unistd.h>

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
                            "  -tsl_output_sync 1            seconds between syncs of the .h5 and .xmf.part during a run (0: every frame)\n"
                            "  -tsl_direct_max_dofs N        direct solver by default up to N unknowns (20000 in 2D, 2000 in 3D)\n"
                            "  --help                        this text; -help lists every PETSc option as well\n"
                            "\n"
                            "Solver defaults: -snes_type newtonls -ksp_type fgmres thermoslide's field split (T, then u) with BoomerAMG per field\n"
                            "(docs/running.md); models up to -tsl_direct_max_dofs unknowns, and on request for any model,\n"
                            "a direct solve: -pc_type lu -pc_factor_mat_solver_type mumps. -snes_monitor, -ksp_monitor, -log_view work\n"
                            "as usual. See docs/ for the keyword reference, element table and outputs.\n"
                            "\n"
                            "environment: TSL_HUGE_PAGES=0  do not ask for transparent huge pages (docs/running.md, \"Memory pages\")\n";

/* Prints the first report of an error once, on rank 0 of the communicator it was raised on: user errors
 * (deck, options, files) and convergence stops as a plain message, a stop asked for by a signal as such, anything else as an internal error with
 * its code, but never a stack trace or a source path (run with -info for the details). A blank message
 * is the follow-up of an error already reported (see TslAgree in sys.h). */
static PetscErrorCode ErrorHandler(MPI_Comm comm, int line, const char *fun, const char *file, PetscErrorCode n, PetscErrorType p, const char *mess,
                                   void *ctx)
{
  PetscMPIInt rank = 0;

  (void)ctx, (void)line, (void)fun, (void)file;
  if (p != PETSC_ERROR_INITIAL || !mess || !strcmp(mess, " ")) return n;
  if (comm != PETSC_COMM_SELF) MPI_Comm_rank(comm, &rank);
  if (rank != 0) return n;
  if (n == PETSC_ERR_USER_INPUT || n == PETSC_ERR_NOT_CONVERGED || n == PETSC_ERR_FILE_OPEN || n == PETSC_ERR_FILE_READ ||
      n == PETSC_ERR_FILE_WRITE || n == PETSC_ERR_FILE_UNEXPECTED)
    fprintf(stderr, "thermoslide: error: %s\n", mess);
  else if (n == PETSC_ERR_SIG) /* asked to stop (src/sys/stop.c): not an error of the job's */
    fprintf(stderr, "thermoslide: stopped: %s\n", mess);
  else if (n == PETSC_ERR_ARG_UNKNOWN_TYPE) /* this code names its types itself: an unknown one came from an option */
    fprintf(stderr, "thermoslide: error: a command-line option names an unknown type: %s\n", mess);
  else
    fprintf(stderr, "thermoslide: internal error (code %d): %s\n", (int)n, mess);
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
  char        buf[PETSC_MAX_PATH_LEN];
  size_t      n = strlen(path);
  struct stat st;

  if (n == 0) return ENOENT;
  if (n >= sizeof(buf)) return ENAMETOOLONG;
  memcpy(buf, path, n + 1);
  for (char *c = buf + 1; *c; c++) {
    if (*c != '/') continue;
    *c = 0;
    if (mkdir(buf, 0777) && errno != EEXIST) return errno;
    *c = '/';
  }
  if (mkdir(buf, 0777) && errno != EEXIST) return errno;
  if (stat(buf, &st)) return errno;
  if (!S_ISDIR(st.st_mode)) return ENOTDIR;
  return 0;
}

/* Rank 0: a deck with *RESTART, WRITE keeps a copy of itself as read beside its points, DIR/JOB.restart.inp, from
 * which a restart deck (*RESTART, READ with -oldjob DIR/JOB) takes the model and the steps it continues (written
 * under a scratch name and renamed: a crash leaves the earlier copy whole). */
static PetscErrorCode KeepDeckCopy(const TslModel *m, const char *flat, const char *dir, const char *job)
{
  PetscBool writes = PETSC_FALSE;
  char      path[PETSC_MAX_PATH_LEN + 300], tmp[PETSC_MAX_PATH_LEN + 310];
  FILE     *fp;
  size_t    n;
  int       ok;

  PetscFunctionBeginUser;
  for (PetscInt k = 0; k < m->nstep; k++) writes = (PetscBool)(writes || m->steps[k].restart_frequency || m->steps[k].restart_interval > 0);
  if (!writes || !flat || m->post_output) PetscFunctionReturn(PETSC_SUCCESS); /* a POST OUTPUT job writes no points */
  PetscCall(PetscSNPrintf(path, sizeof(path), "%s/%s.restart.inp", dir, job));
  PetscCall(PetscSNPrintf(tmp, sizeof(tmp), "%s.tmp", path));
  fp = fopen(tmp, "w");
  n  = strlen(flat);
  ok = fp && fwrite(flat, 1, n, fp) == n;
  if (fp && fclose(fp)) ok = 0;
  if (ok && rename(tmp, path)) ok = 0;
  if (!ok) {
    fprintf(stderr, "thermoslide: error: cannot write the deck copy %s: %s\n", path, strerror(errno));
    (void)remove(tmp);
    PetscFunctionReturn(PETSC_ERR_FILE_WRITE);
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* One attempt at the job: read, distribute, set up, run. *margin_rerun > 0 when it stopped because a contact
 * node left its rank's held region of the main surface and the job is to restart with that margin. */
static PetscErrorCode Attempt(const char *deck, const char *dir, const char *job, PetscReal *margin_rerun)
{
  MPI_Comm       comm = PETSC_COMM_WORLD;
  PetscMPIInt    rank;
  TslModel      *global = NULL, *local = NULL;
  TslProblem     prob;
  PetscErrorCode ierr = PETSC_SUCCESS;

  PetscFunctionBeginUser;
  *margin_rerun = 0;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  PetscCall(TslPhaseBegin(TSL_PHASE_READ));
  if (rank == 0) {
    char *flat = NULL;
    ierr       = TslDeckReadFlat(deck, &global, &flat);
    if (!ierr) ierr = TslModelCheckSupports(global);
    if (!ierr) {
      int e = MakeDirectories(dir);
      if (e) {
        fprintf(stderr, "thermoslide: error: cannot create the output directory '%s': %s\n", dir,
                e == ENOTDIR  ? "a file of that name is in the way"
                : e == ENOENT ? "empty name"
                              : strerror(e));
        ierr = PETSC_ERR_FILE_OPEN;
      }
    }
    if (!ierr) ierr = KeepDeckCopy(global, flat, dir, job);
    PetscCall(PetscFree(flat));
    if (ierr) PetscCall(TslModelDestroy(&global));
  }
  TslCallCollective(comm, ierr);
  PetscCall(TslPhaseEnd(TSL_PHASE_READ));
  PetscCall(PetscPrintf(comm, "thermoslide: %s -> %s/%s.{h5,xmf,csv}\n", deck, dir, job));
  PetscCall(TslPhaseBegin(TSL_PHASE_PARTITION));
  PetscCall(TslMeshDistribute(comm, &global, &local));
  PetscCall(TslPhaseEnd(TSL_PHASE_PARTITION));
  PetscCall(TslPhaseBegin(TSL_PHASE_SETUP));
  TslCallCollective(comm, TslProblemCreate(comm, local, &prob));
  PetscCall(TslPhaseEnd(TSL_PHASE_SETUP));
  ierr = TslAnalysisRun(prob, dir, job);
  PetscCall(TslProblemGetMarginRerun(prob, margin_rerun));
  PetscCall(TslProblemDestroy(&prob));
  if (*margin_rerun > 0) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCheck(!ierr, comm, ierr, " ");
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The job. Each rank holds the part of a contact pair's main surface its secondary nodes can reach,
 * chosen when the model is distributed (docs/contact.md, "Parallel exchange"); a node that leaves it stops
 * the attempt (never a silent miss), and the job restarts from the deck with a larger margin, up to
 * -tsl_contact_rebuild times: the held part is rebuilt at the cost of the increments redone. Result files
 * of the job's own failed attempts (name.failed.*) are removed once it completes. */
static PetscErrorCode Run(const char *deck)
{
  MPI_Comm  comm = PETSC_COMM_WORLD;
  char      dir[PETSC_MAX_PATH_LEN] = ".", job[256], failed[3][PETSC_MAX_PATH_LEN + 300];
  PetscBool set, alt_set, had_failed[3];
  PetscInt  rebuilds = 8, attempts = 0;
  PetscReal margin;

  PetscFunctionBeginUser;
  PetscCall(PetscOptionsGetString(NULL, NULL, "-o", dir, sizeof(dir), &set));
  {
    /* both spellings are read (so neither is "unknown"); -o wins */
    char alt[PETSC_MAX_PATH_LEN] = "";
    PetscCall(PetscOptionsGetString(NULL, NULL, "-tsl_output_dir", alt, sizeof(alt), &alt_set));
    if (!set && alt_set) PetscCall(PetscStrncpy(dir, alt, sizeof(dir)));
  }
  PetscOptionsBegin(comm, NULL, "thermoslide job", NULL);
  PetscCall(TslOptionsInt(PetscOptionsObject, "-tsl_contact_rebuild",
                          "contact: restarts of the job with a larger -tsl_contact_margin when a secondary node leaves its rank's held region of "
                          "the main surface (0: stop instead, naming the margin to rerun with)",
                          0, 100, &rebuilds));
  PetscOptionsEnd();
  JobName(deck, job, sizeof(job));
  for (PetscInt i = 0; i < 3; i++) {
    PetscCall(PetscSNPrintf(failed[i], sizeof(failed[i]), "%s/%s.failed.%s", dir, job, (const char *[]){"h5", "xmf", "csv"}[i]));
    PetscCall(PetscTestFile(failed[i], 'r', &had_failed[i]));
    PetscCallMPI(MPI_Bcast(&had_failed[i], 1, MPIU_BOOL, 0, comm));
  }
  for (;;) {
    char value[64];
    PetscCall(PetscSNPrintf(value, sizeof(value), "%" PetscInt_FMT, rebuilds - attempts));
    PetscCall(PetscOptionsSetValue(NULL, "-tsl_contact_rebuild", value));
    PetscCall(PetscOptionsHasName(NULL, NULL, "-tsl_contact_rebuild", &set)); /* read here: a set value counts as unread */
    PetscCall(Attempt(deck, dir, job, &margin));
    if (margin <= 0) break;
    attempts++;
    PetscCall(PetscSNPrintf(value, sizeof(value), "%.17g", (double)margin));
    PetscCall(PetscOptionsSetValue(NULL, "-tsl_contact_margin", value));
    PetscCall(PetscPrintf(comm, "thermoslide: restart %" PetscInt_FMT " of at most %" PetscInt_FMT " (-tsl_contact_rebuild) with -tsl_contact_margin %g\n",
                          attempts, rebuilds, (double)margin));
  }
  if (attempts) {
    PetscMPIInt rank;
    PetscCallMPI(MPI_Comm_rank(comm, &rank));
    for (PetscInt i = 0; i < 3 && rank == 0; i++)
      if (!had_failed[i]) (void)remove(failed[i]);
  }
  PetscCall(TslOptionsCheckUnused(comm, PETSC_FALSE));
  PetscCall(TslPhasesReport(comm));
  PetscCall(PetscPrintf(comm, "thermoslide: completed\n"));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* True for an argument that names a deck: a non-option that is not the value of the option before it,
 * or, wherever it stands, a name ending in .inp (so "-snes_monitor job.inp" cannot make PETSc take the
 * deck for the monitor's output file and overwrite it). */
static PetscBool IsDeck(int argc, char **argv, int i)
{
  size_t n = strlen(argv[i]);

  const char *prev = i > 1 ? argv[i - 1] : "";

  (void)argc;
  if (argv[i][0] == '-') return PETSC_FALSE;
  /* options whose value is a path */
  if (!strcmp(prev, "-o") || !strcmp(prev, "-tsl_output_dir") || !strcmp(prev, "-options_file") || !strcmp(prev, "-oldjob")) return PETSC_FALSE;
  if (n > 4 && !strcasecmp(argv[i] + n - 4, ".inp")) return PETSC_TRUE;
  return (PetscBool)(prev[0] != '-' || !strcmp(prev, "-help"));
}

/* After an error: do all ranks stop too? Failures are decided by all ranks together (sys.h), so they
 * should; this is the safety net for one that was not. Waits up to 30 s for the others. */
static PetscBool AllRanksStopped(void)
{
  MPI_Request req;
  int         done = 0;
  double      t0   = MPI_Wtime();

  if (MPI_Ibarrier(PETSC_COMM_WORLD, &req)) return PETSC_FALSE;
  while (!done && MPI_Wtime() - t0 < 30) {
    if (MPI_Test(&req, &done, MPI_STATUS_IGNORE)) return PETSC_FALSE;
    if (!done) (void)PetscSleep(0.01);
  }
  return (PetscBool)done;
}

/* Transparent huge pages for the heap (docs/running.md, "Memory pages"): when the kernel offers them on request
 * (THP "madvise", Debian's default) and the environment has not set it, the process runs itself again at once
 * with glibc's malloc tunable glibc.malloc.hugetlb=1 added to GLIBC_TUNABLES (read by the loader only, so it
 * cannot be set from inside), before anything else is done: the same process id, arguments and environment
 * otherwise, so mpirun and batch systems see nothing. Then malloc asks for 2 MB pages for its large blocks (the
 * matrices, hypre's hierarchy, the element records): a page fault per 2 MB instead of per 4 kB, and fewer TLB
 * misses. TSL_HUGE_PAGES=0 turns it off; it is skipped under valgrind and wherever the exec fails (the job then
 * runs as it is). */
static void HugePages(char **argv)
{
  const char *off = getenv("TSL_HUGE_PAGES"), *t = getenv("GLIBC_TUNABLES"), *pre = getenv("LD_PRELOAD");
  char        mode[128] = "", value[1024], old[1024], self[4096];
  ssize_t     n;
  FILE       *f;

  if ((off && !strcmp(off, "0")) || (t && strstr(t, "glibc.malloc.hugetlb")) || (pre && strstr(pre, "vgpreload"))) return;
  f = fopen("/sys/kernel/mm/transparent_hugepage/enabled", "r");
  if (!f) return;
  if (!fgets(mode, sizeof(mode), f)) mode[0] = 0;
  fclose(f);
  if (!strstr(mode, "[madvise]")) return; /* "always" needs no request, "never" grants none */
  if (snprintf(value, sizeof(value), "%s%sglibc.malloc.hugetlb=1", t ? t : "", t ? ":" : "") >= (int)sizeof(value)) return;
  if (t) { /* the old value kept for a failed exec: setenv may replace the string t points to */
    if (snprintf(old, sizeof(old), "%s", t) >= (int)sizeof(old)) return;
    t = old;
  }
  /* the binary's own path, not /proc/self/exe: the process keeps its name (ps, top, pkill thermoslide) */
  n = readlink("/proc/self/exe", self, sizeof(self) - 1);
  if (n <= 0 || n >= (ssize_t)sizeof(self) - 1) return;
  self[n] = 0;
  if (setenv("GLIBC_TUNABLES", value, 1)) return;
  execv(self, argv);
  if (t)
    setenv("GLIBC_TUNABLES", t, 1); /* the exec failed: run as we are */
  else
    unsetenv("GLIBC_TUNABLES");
}

int main(int argc, char **argv)
{
  const char    *deck = NULL;
  char           decks[2][PETSC_MAX_PATH_LEN], inp[PETSC_MAX_PATH_LEN];
  int            ndeck = 0;
  PetscErrorCode ierr;

  HugePages(argv);
  for (int i = 1; i < argc; i++) {
    if (!strcmp(argv[i], "--help") || !strcmp(argv[i], "-h")) {
      fputs(Usage, stdout);
      return 0;
    }
  }
  /* decks first, options after: PETSc then sees the options only */
  {
    char **sorted = (char **)malloc((size_t)argc * sizeof(char *));
    int    n      = 1;
    if (!sorted) return 1;
    sorted[0] = argv[0];
    for (int i = 1; i < argc; i++)
      if (IsDeck(argc, argv, i)) {
        if (ndeck < 2) snprintf(decks[ndeck], sizeof(decks[ndeck]), "%s", argv[i]);
        ndeck++;
        sorted[n++] = argv[i];
      }
    for (int i = 1; i < argc; i++)
      if (!IsDeck(argc, argv, i)) sorted[n++] = argv[i];
    memcpy(argv, sorted, (size_t)argc * sizeof(char *));
    free(sorted);
  }
  PetscCall(PetscInitialize(&argc, &argv, NULL, Usage));
  PetscCall(PetscPushErrorHandler(ErrorHandler, NULL));
  PetscCall(TslStopInstall());
  PetscCall(TslPhasesInitialize());
  if (ndeck > 1) {
    PetscCall(PetscFPrintf(PETSC_COMM_WORLD, stderr, "thermoslide: error: more than one deck given (%s, %s): one job per run\n", decks[0], decks[1]));
    PetscCall(PetscPopErrorHandler());
    PetscCall(PetscFinalize());
    return 2;
  }
  if (ndeck == 1) {
    /* "job" for "job.inp", as CalculiX and Abaqus users type it */
    struct stat st;
    deck = decks[0];
    if (stat(deck, &st) && errno == ENOENT && snprintf(inp, sizeof(inp), "%s.inp", deck) < (int)sizeof(inp) && !stat(inp, &st)) deck = inp;
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
  if (ierr && !AllRanksStopped()) MPI_Abort(PETSC_COMM_WORLD, 1); /* a rank still busy elsewhere would never finish */
  {
    const int sig = ierr ? TslStopLocal() : 0; /* stopped as asked: the status a shell gives a signal's end */
    PetscCall(PetscFinalize());
    return sig ? 128 + sig : ierr ? 1 : 0;
  }
}
