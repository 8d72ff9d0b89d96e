/* A run that stops before Finalize (TslOutputDestroy / TslHistoryDestroy without Finalize) must leave
 * the previous <job>.h5, .xmf and .csv byte for byte as they were and remove every .part file; and a
 * writer asked to create files in a missing directory must fail with an error, not crash.
 * Options: -dir. */
#include "mesh_fixture.h"
#include <string.h>
#include <unistd.h>
#include <sys/stat.h>

static int nfail = 0;
#define EXPECT(cond, ...)                                                                                                                            \
  do {                                                                                                                                               \
    if (!(cond)) {                                                                                                                                   \
      nfail++;                                                                                                                                       \
      printf("FAIL %s:%d: ", __FILE__, __LINE__);                                                                                                    \
      printf(__VA_ARGS__);                                                                                                                           \
      printf("\n");                                                                                                                                  \
    }                                                                                                                                                \
  } while (0)

static const char *old_text = "previous good result\n";

static void PathOf(const char *dir, const char *suffix, char path[PETSC_MAX_PATH_LEN])
{
  snprintf(path, PETSC_MAX_PATH_LEN, "%s/abort%s", dir, suffix);
}

static void WriteOld(const char *dir, const char *suffix)
{
  char  path[PETSC_MAX_PATH_LEN];
  FILE *fp;
  PathOf(dir, suffix, path);
  fp = fopen(path, "w");
  EXPECT(fp, "cannot create %s", path);
  if (fp) fputs(old_text, fp), fclose(fp);
}

static void ExpectOld(const char *dir, const char *suffix)
{
  char  path[PETSC_MAX_PATH_LEN], buf[256] = "";
  FILE *fp;
  PathOf(dir, suffix, path);
  fp = fopen(path, "r");
  EXPECT(fp, "%s is gone", path);
  if (!fp) return;
  buf[fread(buf, 1, sizeof(buf) - 1, fp)] = 0;
  fclose(fp);
  EXPECT(!strcmp(buf, old_text), "%s was changed", path);
}

static void ExpectExists(const char *dir, const char *suffix, PetscBool exists)
{
  char path[PETSC_MAX_PATH_LEN];
  PathOf(dir, suffix, path);
  EXPECT((access(path, F_OK) == 0) == exists, "%s %s", path, exists ? "missing" : "still exists");
}

/* Rows must reach the .csv.part as they are appended, so that a crash leaves them readable. */
static void ExpectLines(const char *dir, const char *suffix, int want)
{
  char  path[PETSC_MAX_PATH_LEN];
  int   lines = 0, ch;
  FILE *fp;
  PathOf(dir, suffix, path);
  fp = fopen(path, "r");
  EXPECT(fp, "cannot open %s", path);
  if (!fp) return;
  while ((ch = fgetc(fp)) != EOF) lines += ch == '\n';
  fclose(fp);
  EXPECT(lines == want, "%s has %d lines, expected %d", path, lines, want);
}

int main(int argc, char **argv)
{
  char            dir[PETSC_MAX_PATH_LEN] = "out_abort", missing[PETSC_MAX_PATH_LEN];
  PetscMPIInt     rank, size;
  TestMesh        m;
  TestLocal       l;
  TslOutput       out;
  TslHistory      hist;
  const char     *cols[] = {"time", "heat"};
  const PetscReal row[]  = {1.0, 2.0};
  PetscReal      *v;
  PetscErrorCode  ierr;

  PetscCall(PetscInitialize(&argc, &argv, NULL, NULL));
  PetscCallMPI(MPI_Comm_rank(PETSC_COMM_WORLD, &rank));
  PetscCallMPI(MPI_Comm_size(PETSC_COMM_WORLD, &size));
  PetscCall(PetscOptionsGetString(NULL, NULL, "-dir", dir, sizeof(dir), NULL));
  if (rank == 0) {
    (void)mkdir(dir, 0777);
    WriteOld(dir, ".h5");
    WriteOld(dir, ".xmf");
    WriteOld(dir, ".csv");
  }
  PetscCallMPI(MPI_Barrier(PETSC_COMM_WORLD));

  PetscCall(TestMeshCreate(4, 3, PETSC_FALSE, &m));
  PetscCall(TestLocalCreate(&m, rank, size, &l));
  PetscCall(TslOutputCreate(PETSC_COMM_WORLD, dir, "abort", &out));
  PetscCall(TslHistoryCreate(PETSC_COMM_WORLD, dir, "abort", 2, cols, &hist));
  PetscCall(TestSetMesh(out, &m, &l));
  PetscCall(TslOutputBeginFrame(out, 1, 1, 0.25));
  PetscCall(TestFieldValues(&l, PETSC_FALSE, 1, 1, 3, &v));
  PetscCall(TslOutputNodeField(out, "U", 3, v));
  PetscCall(PetscFree(v));
  PetscCall(TslOutputEndFrame(out));
  PetscCall(TslHistoryAppend(hist, row));
  PetscCall(TslHistoryAppend(hist, row));
  PetscCallMPI(MPI_Barrier(PETSC_COMM_WORLD));
  if (rank == 0) {
    ExpectExists(dir, ".h5.part", PETSC_TRUE);
    ExpectExists(dir, ".xmf.part", PETSC_TRUE);
    ExpectLines(dir, ".csv.part", 3);
  }
  /* A second frame left open, as when a run dies in the middle of writing one. */
  PetscCall(TslOutputBeginFrame(out, 1, 2, 0.5));
  PetscCall(TslOutputDestroy(&out));
  PetscCall(TslHistoryDestroy(&hist));
  EXPECT(!out && !hist, "Destroy did not null the handles");
  if (rank == 0) {
    ExpectOld(dir, ".h5");
    ExpectOld(dir, ".xmf");
    ExpectOld(dir, ".csv");
    ExpectExists(dir, ".h5.part", PETSC_FALSE);
    ExpectExists(dir, ".xmf.part", PETSC_FALSE);
    ExpectExists(dir, ".xmf.part.tmp", PETSC_FALSE);
    ExpectExists(dir, ".csv.part", PETSC_FALSE);
  }

  /* Errors come back as PETSc errors naming the path, on every rank, with no handle left behind. */
  snprintf(missing, sizeof(missing), "%s/no/such/dir", dir);
  PetscCall(PetscPushErrorHandler(PetscReturnErrorHandler, NULL));
  ierr = TslOutputCreate(PETSC_COMM_WORLD, missing, "abort", &out);
  EXPECT(ierr == PETSC_ERR_FILE_OPEN && !out, "TslOutputCreate in a missing directory gave %d", (int)ierr);
  ierr = TslHistoryCreate(PETSC_COMM_WORLD, missing, "abort", 2, cols, &hist);
  EXPECT(ierr == PETSC_ERR_FILE_OPEN && !hist, "TslHistoryCreate in a missing directory gave %d", (int)ierr);
  ierr = TslOutputCreate(PETSC_COMM_WORLD, dir, "bad/name", &out);
  EXPECT(ierr == PETSC_ERR_ARG_WRONG && !out, "a job name with '/' gave %d", (int)ierr);
  PetscCall(PetscPopErrorHandler());

  if (rank == 0) printf("abort: %d ranks: %s\n", (int)size, nfail ? "FAIL" : "PASS");
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &nfail, 1, MPI_INT, MPI_MAX, PETSC_COMM_WORLD));
  PetscCall(TestLocalDestroy(&l));
  PetscCall(TestMeshDestroy(&m));
  PetscCall(PetscFinalize());
  return nfail ? 1 : 0;
}
