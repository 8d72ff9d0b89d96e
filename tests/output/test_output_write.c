/* Writes two frames of a mixed quad/triangle mesh, distributed in a scrambled way over however many
 * ranks run it, then reads <job>.h5 back on rank 0 with the plain HDF5 API and checks every value
 * against the closed-form figures of mesh_fixture.h. Since those figures do not depend on the rank
 * count, passing on 1, 2 and 3 ranks proves the files are identical. Also writes and checks a
 * history CSV. With -quads the mesh is of quadrilaterals alone: /mesh/connectivity (M x 4) is written besides the
 * Mixed records and the .xmf names the Quadrilateral topology (a mixed mesh: Mixed, and no connectivity). Options:
 * -dir, -job, -nx, -ny, -quads. */
#include "mesh_fixture.h"
#include <hdf5.h>
#include <string.h>
#include <unistd.h>
#include <sys/stat.h>

typedef struct {
  const char *name;
  PetscInt    field, ncomp;
  PetscBool   on_cells;
  PetscInt    first_frame; /* written from this frame on */
} FieldSpec;

static const FieldSpec fields[] = {
    {"NT", 1, 1, PETSC_FALSE, 1},
    {"U", 2, 3, PETSC_FALSE, 1},
    {"S", 3, 6, PETSC_TRUE, 1},
    {"V", 4, 2, PETSC_FALSE, 2}, /* 2 components: written as an XDMF Matrix */
};
#define NFIELD ((PetscInt)(sizeof(fields) / sizeof(fields[0])))
#define NFRAME 2

static PetscReal FrameTime(PetscInt f)
{
  return 0.5 * f;
}

static int nfail = 0;
#define EXPECT(cond, ...)                                                                                                                            \
  do {                                                                                                                                               \
    if (!(cond)) {                                                                                                                                   \
      if (nfail++ < 20) {                                                                                                                            \
        printf("FAIL %s:%d: ", __FILE__, __LINE__);                                                                                                  \
        printf(__VA_ARGS__);                                                                                                                         \
        printf("\n");                                                                                                                                \
      }                                                                                                                                              \
    }                                                                                                                                                \
  } while (0)

/* Reads a whole dataset (test only: global size is fine here) after checking its shape. */
static PetscErrorCode ReadAll(hid_t file, const char *path, hid_t memtype, int rank, hsize_t d0, hsize_t d1, void **buf)
{
  hid_t   dset, space;
  hsize_t dims[2] = {0, 0};
  size_t  esize;

  PetscFunctionBeginUser;
  *buf = NULL;
  dset = H5Dopen2(file, path, H5P_DEFAULT);
  EXPECT(dset >= 0, "dataset %s missing", path);
  if (dset < 0) PetscFunctionReturn(PETSC_SUCCESS);
  space = H5Dget_space(dset);
  EXPECT(H5Sget_simple_extent_ndims(space) == rank, "%s: rank %d, expected %d", path, H5Sget_simple_extent_ndims(space), rank);
  H5Sget_simple_extent_dims(space, dims, NULL);
  EXPECT(dims[0] == d0 && (rank == 1 || dims[1] == d1), "%s: dims %llu x %llu, expected %llu x %llu", path, (unsigned long long)dims[0],
         (unsigned long long)dims[1], (unsigned long long)d0, (unsigned long long)d1);
  if (dims[0] == d0 && (rank == 1 || dims[1] == d1)) {
    esize = H5Tget_size(memtype);
    PetscCall(PetscMalloc(esize * d0 * (rank == 2 ? d1 : 1) + 1, buf));
    EXPECT(H5Dread(dset, memtype, H5S_ALL, H5S_ALL, H5P_DEFAULT, *buf) >= 0, "%s: read failed", path);
  }
  H5Sclose(space);
  H5Dclose(dset);
  PetscFunctionReturn(PETSC_SUCCESS);
}

static void ExpectAttr(hid_t grp, const char *gname, const char *name, hid_t memtype, double expect)
{
  hid_t   attr = H5Aopen(grp, name, H5P_DEFAULT);
  double  d    = -1;
  int64_t i    = -1;

  EXPECT(attr >= 0, "%s: attribute %s missing", gname, name);
  if (attr < 0) return;
  if (memtype == H5T_NATIVE_DOUBLE)
    H5Aread(attr, memtype, &d);
  else
    H5Aread(attr, memtype, &i), d = (double)i;
  EXPECT(d == expect, "%s: attribute %s = %g, expected %g", gname, name, d, expect);
  H5Aclose(attr);
}

static PetscErrorCode CheckH5(const TestMesh *m, PetscBool quads, const char *path)
{
  hid_t      file;
  PetscReal *xyz;
  int64_t   *ids, *topo;
  PetscInt   L = 0;

  PetscFunctionBeginUser;
  file = H5Fopen(path, H5F_ACC_RDONLY, H5P_DEFAULT);
  EXPECT(file >= 0, "cannot open %s", path);
  if (file < 0) PetscFunctionReturn(PETSC_SUCCESS);

  PetscCall(ReadAll(file, "/mesh/coordinates", H5T_NATIVE_DOUBLE, 2, m->N, 3, (void **)&xyz));
  for (PetscInt k = 0; xyz && k < 3 * m->N; k++) EXPECT(xyz[k] == m->xyz[k], "coordinates[%d]", (int)k);
  PetscCall(PetscFree(xyz));
  PetscCall(ReadAll(file, "/mesh/node_ids", H5T_NATIVE_INT64, 1, m->N, 0, (void **)&ids));
  for (PetscInt n = 0; ids && n < m->N; n++) EXPECT(ids[n] == TestNodeId(n), "node_ids[%d] = %lld", (int)n, (long long)ids[n]);
  PetscCall(PetscFree(ids));
  PetscCall(ReadAll(file, "/mesh/element_ids", H5T_NATIVE_INT64, 1, m->M, 0, (void **)&ids));
  for (PetscInt e = 0; ids && e < m->M; e++) EXPECT(ids[e] == TestElemId(e), "element_ids[%d]", (int)e);
  PetscCall(PetscFree(ids));

  for (PetscInt e = 0; e < m->M; e++) L += 1 + m->ptr[e + 1] - m->ptr[e];
  PetscCall(ReadAll(file, "/mesh/topology", H5T_NATIVE_INT64, 1, L, 0, (void **)&topo));
  for (PetscInt e = 0, r = 0; topo && e < m->M; e++) {
    EXPECT(topo[r] == m->type[e], "topology record %d: type %lld, expected %d", (int)e, (long long)topo[r], (int)m->type[e]);
    r++;
    for (PetscInt j = m->ptr[e]; j < m->ptr[e + 1]; j++, r++)
      EXPECT(topo[r] == m->conn[j], "topology record %d: node %lld, expected %d", (int)e, (long long)topo[r], (int)m->conn[j]);
  }
  PetscCall(PetscFree(topo));
  if (quads) {
    int64_t *conn;
    PetscCall(ReadAll(file, "/mesh/connectivity", H5T_NATIVE_INT64, 2, m->M, 4, (void **)&conn));
    for (PetscInt e = 0; conn && e < m->M; e++)
      for (PetscInt j = 0; j < 4; j++)
        EXPECT(conn[4 * e + j] == m->conn[m->ptr[e] + j], "connectivity[%d][%d] = %lld, expected %d", (int)e, (int)j, (long long)conn[4 * e + j],
               (int)m->conn[m->ptr[e] + j]);
    PetscCall(PetscFree(conn));
  } else
    EXPECT(H5Lexists(file, "/mesh/connectivity", H5P_DEFAULT) == 0, "a mixed mesh has no /mesh/connectivity");

  for (PetscInt f = 1; f <= NFRAME; f++) {
    char  gname[64];
    hid_t grp;
    snprintf(gname, sizeof(gname), "/frames/%06d", (int)f);
    grp = H5Gopen2(file, gname, H5P_DEFAULT);
    EXPECT(grp >= 0, "group %s missing", gname);
    if (grp < 0) continue;
    ExpectAttr(grp, gname, "time", H5T_NATIVE_DOUBLE, FrameTime(f));
    ExpectAttr(grp, gname, "step", H5T_NATIVE_INT64, 1);
    ExpectAttr(grp, gname, "increment", H5T_NATIVE_INT64, f);
    H5Gclose(grp);
    for (PetscInt i = 0; i < NFIELD; i++) {
      const FieldSpec *s = &fields[i];
      const PetscInt   n = s->on_cells ? m->M : m->N;
      char             dname[128];
      PetscReal       *v;
      snprintf(dname, sizeof(dname), "%s/%s", gname, s->name);
      if (f < s->first_frame) {
        EXPECT(H5Lexists(file, dname, H5P_DEFAULT) == 0, "%s should not exist", dname);
        continue;
      }
      PetscCall(ReadAll(file, dname, H5T_NATIVE_DOUBLE, 2, n, s->ncomp, (void **)&v));
      for (PetscInt k = 0; v && k < n; k++)
        for (PetscInt c = 0; c < s->ncomp; c++)
          EXPECT(v[k * s->ncomp + c] == TestValue(f, s->field, k, c), "%s[%d][%d] = %g, expected %g", dname, (int)k, (int)c, v[k * s->ncomp + c],
                 TestValue(f, s->field, k, c));
      PetscCall(PetscFree(v));
    }
  }
  H5Fclose(file);
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode ReadText(const char *path, char **text)
{
  FILE *fp = fopen(path, "rb");
  long  len;

  PetscFunctionBeginUser;
  *text = NULL;
  EXPECT(fp, "cannot open %s", path);
  if (!fp) PetscFunctionReturn(PETSC_SUCCESS);
  fseek(fp, 0, SEEK_END);
  len = ftell(fp);
  fseek(fp, 0, SEEK_SET);
  PetscCall(PetscCalloc1(len + 1, text));
  EXPECT(fread(*text, 1, len, fp) == (size_t)len, "short read of %s", path);
  fclose(fp);
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode CheckXmf(const char *dir, const char *job, const TestMesh *m, PetscBool quads)
{
  char path[PETSC_MAX_PATH_LEN], want[512], *text;

  PetscFunctionBeginUser;
  snprintf(path, sizeof(path), "%s/%s.xmf", dir, job);
  PetscCall(ReadText(path, &text));
  if (!text) PetscFunctionReturn(PETSC_SUCCESS);
  EXPECT(strstr(text, "CollectionType=\"Temporal\""), "%s: no temporal collection", path);
  if (quads) {
    snprintf(want, sizeof(want), "TopologyType=\"Quadrilateral\" NumberOfElements=\"%d\" NodesPerElement=\"4\"", (int)m->M);
    EXPECT(strstr(text, want), "%s: does not mention %s", path, want);
    EXPECT(!strstr(text, "Mixed"), "%s: a Mixed topology for a mesh of one cell type", path);
    snprintf(want, sizeof(want), "Dimensions=\"%d 4\" NumberType=\"Int\" Precision=\"8\" Format=\"HDF\">%s.h5:/mesh/connectivity<", (int)m->M, job);
  } else {
    EXPECT(strstr(text, "TopologyType=\"Mixed\""), "%s: no Mixed topology", path);
    snprintf(want, sizeof(want), ">%s.h5:/mesh/topology<", job);
  }
  EXPECT(strstr(text, want), "%s: does not mention %s", path, want);
  snprintf(want, sizeof(want), ">%s.h5:/mesh/coordinates<", job);
  EXPECT(strstr(text, want), "%s: does not mention %s", path, want);
  for (PetscInt f = 1; f <= NFRAME; f++) {
    snprintf(want, sizeof(want), "<Time Value=\"%.17g\"/>", FrameTime(f));
    EXPECT(strstr(text, want), "%s: does not mention %s", path, want);
    for (PetscInt i = 0; i < NFIELD; i++) {
      if (f < fields[i].first_frame) continue;
      snprintf(want, sizeof(want), ">%s.h5:/frames/%06d/%s<", job, (int)f, fields[i].name);
      EXPECT(strstr(text, want), "%s: does not mention %s", path, want);
    }
  }
  EXPECT(strstr(text, "AttributeType=\"Matrix\" Center=\"Cell\""), "%s: S not a cell Matrix", path);
  EXPECT(strstr(text, "AttributeType=\"Matrix\" Center=\"Node\""), "%s: V not a node Matrix", path);
  EXPECT(!strstr(text, ".part"), "%s mentions a .part file", path);
  PetscCall(PetscFree(text));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode CheckCsv(const char *dir, const char *job)
{
  char        path[PETSC_MAX_PATH_LEN], *text;
  const char *want = "time,increment,heat_in\n"
                     "5.0000000000e-01,1.0000000000e+00,-1.2345678901e-03\n"
                     "1.0000000000e+00,2.0000000000e+00,-2.4691357802e-03\n";

  PetscFunctionBeginUser;
  snprintf(path, sizeof(path), "%s/%s.csv", dir, job);
  PetscCall(ReadText(path, &text));
  if (!text) PetscFunctionReturn(PETSC_SUCCESS);
  EXPECT(!strcmp(text, want), "%s reads\n%s\nexpected\n%s", path, text, want);
  PetscCall(PetscFree(text));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static void ExpectAbsent(const char *dir, const char *job, const char *suffix)
{
  char path[PETSC_MAX_PATH_LEN];
  snprintf(path, sizeof(path), "%s/%s%s", dir, job, suffix);
  EXPECT(access(path, F_OK) != 0, "%s still exists", path);
}

int main(int argc, char **argv)
{
  char        dir[PETSC_MAX_PATH_LEN] = ".", job[64] = "write", path[PETSC_MAX_PATH_LEN];
  PetscInt    nx = 7, ny = 5;
  PetscBool   quads = PETSC_FALSE;
  PetscMPIInt rank, size;
  TestMesh    m;
  TestLocal   l;
  TslOutput   out;
  TslHistory  hist;
  const char *cols[] = {"time", "increment", "heat_in"};

  PetscCall(PetscInitialize(&argc, &argv, NULL, NULL));
  PetscCallMPI(MPI_Comm_rank(PETSC_COMM_WORLD, &rank));
  PetscCallMPI(MPI_Comm_size(PETSC_COMM_WORLD, &size));
  PetscCall(PetscOptionsGetString(NULL, NULL, "-dir", dir, sizeof(dir), NULL));
  PetscCall(PetscOptionsGetString(NULL, NULL, "-job", job, sizeof(job), NULL));
  PetscCall(PetscOptionsGetInt(NULL, NULL, "-nx", &nx, NULL));
  PetscCall(PetscOptionsGetInt(NULL, NULL, "-ny", &ny, NULL));
  PetscCall(PetscOptionsGetBool(NULL, NULL, "-quads", &quads, NULL));
  if (rank == 0) (void)mkdir(dir, 0777);
  PetscCallMPI(MPI_Barrier(PETSC_COMM_WORLD));

  PetscCall(TestMeshCreate(nx, ny, quads, &m));
  PetscCall(TestLocalCreate(&m, rank, size, &l));
  PetscCall(TslOutputCreate(PETSC_COMM_WORLD, dir, job, &out));
  PetscCall(TslHistoryCreate(PETSC_COMM_WORLD, dir, job, 3, cols, &hist));
  PetscCall(TestSetMesh(out, &m, &l));
  for (PetscInt f = 1; f <= NFRAME; f++) {
    const PetscReal row[3] = {FrameTime(f), (PetscReal)f, -1.2345678901e-3 * f};
    PetscCall(TslOutputBeginFrame(out, 1, f, FrameTime(f)));
    for (PetscInt i = 0; i < NFIELD; i++) {
      PetscReal *v;
      if (f < fields[i].first_frame) continue;
      PetscCall(TestFieldValues(&l, fields[i].on_cells, f, fields[i].field, fields[i].ncomp, &v));
      if (fields[i].on_cells)
        PetscCall(TslOutputElementField(out, fields[i].name, fields[i].ncomp, v));
      else
        PetscCall(TslOutputNodeField(out, fields[i].name, fields[i].ncomp, v));
      PetscCall(PetscFree(v));
    }
    PetscCall(TslOutputEndFrame(out));
    PetscCall(TslHistoryAppend(hist, row));
    if (rank == 0) { /* between frames only the temporary files exist, and the .xmf.part is whole */
      snprintf(path, sizeof(path), "%s/%s.xmf.part", dir, job);
      EXPECT(access(path, F_OK) == 0, "%s missing after EndFrame", path);
      snprintf(path, sizeof(path), "%s/%s.h5.part", dir, job);
      EXPECT(access(path, F_OK) == 0, "%s missing after EndFrame", path);
    }
  }
  PetscCall(TslOutputFinalize(out, NULL));
  PetscCall(TslOutputDestroy(&out));
  PetscCall(TslHistoryFinalize(hist, NULL));
  PetscCall(TslHistoryDestroy(&hist));
  EXPECT(!out && !hist, "Destroy did not null the handles");

  if (rank == 0) {
    snprintf(path, sizeof(path), "%s/%s.h5", dir, job);
    PetscCall(CheckH5(&m, quads, path));
    PetscCall(CheckXmf(dir, job, &m, quads));
    PetscCall(CheckCsv(dir, job));
    ExpectAbsent(dir, job, ".h5.part");
    ExpectAbsent(dir, job, ".xmf.part");
    ExpectAbsent(dir, job, ".xmf.part.tmp");
    ExpectAbsent(dir, job, ".csv.part");
    printf("%s: %d ranks, %d nodes, %d elements: %s\n", job, (int)size, (int)m.N, (int)m.M, nfail ? "FAIL" : "PASS");
  }
  PetscCallMPI(MPI_Bcast(&nfail, 1, MPI_INT, 0, PETSC_COMM_WORLD));
  PetscCall(TestLocalDestroy(&l));
  PetscCall(TestMeshDestroy(&m));
  PetscCall(PetscFinalize());
  return nfail ? 1 : 0;
}
