/* Reading a job's results back (include/thermoslide/output.h, "Reading a job's results back"): the layout that
 * xdmf.c writes, opened read-only by one rank for itself (the serial driver: every rank reads only its own nodes'
 * rows, by point selection). The HDF5 library's own error printing is off while reading; each failure says what
 * was looked for in which file. */
#include <string.h>

#include <hdf5.h>

#include "output_impl.h"

struct _p_TslResults {
  hid_t            file;
  char             path[PETSC_MAX_PATH_LEN];
  PetscInt         nnode, nframe;
  TslResultsFrame *frames;
};

#define READ_ERR(...) SETERRQ(PETSC_COMM_SELF, PETSC_ERR_FILE_READ, __VA_ARGS__)

/* the library's error stack silent while reading (a missing dataset is our message, not its trace) */
typedef struct {
  H5E_auto2_t func;
  void       *data;
} Quiet;

static void QuietBegin(Quiet *q)
{
  (void)H5Eget_auto2(H5E_DEFAULT, &q->func, &q->data);
  (void)H5Eset_auto2(H5E_DEFAULT, NULL, NULL);
}

static void QuietEnd(const Quiet *q) { (void)H5Eset_auto2(H5E_DEFAULT, q->func, q->data); }

/* rows of a dataset [N][ncomp] (or [N] for ncomp 1) as native type mtype into buf (n * ncomp values) */
static PetscErrorCode ReadRows(TslResults r, const char *name, PetscInt n, const PetscInt rows[], PetscInt ncomp, hid_t mtype, void *buf)
{
  hid_t    ds, fs, ms;
  hsize_t  dims[2] = {0, 1}, *coord, mdim = (hsize_t)(n * ncomp);
  int      rank;
  herr_t   rc = 0;
  Quiet    q;

  PetscFunctionBeginUser;
  QuietBegin(&q);
  ds = H5Dopen2(r->file, name, H5P_DEFAULT);
  QuietEnd(&q);
  if (ds < 0) READ_ERR("%s has no dataset %s", r->path, name);
  fs   = H5Dget_space(ds);
  rank = H5Sget_simple_extent_ndims(fs);
  if (rank < 1 || rank > 2 || H5Sget_simple_extent_dims(fs, dims, NULL) < 0 || dims[0] != (hsize_t)r->nnode || dims[1] != (hsize_t)ncomp) {
    (void)H5Sclose(fs), (void)H5Dclose(ds);
    READ_ERR("%s: dataset %s is not [%" PetscInt_FMT "][%" PetscInt_FMT "] (a value per node of the file)", r->path, name, r->nnode, ncomp);
  }
  if (n > 0) {
    PetscCall(PetscMalloc1((size_t)(n * ncomp * rank), &coord));
    for (PetscInt i = 0; i < n; i++)
      for (PetscInt c = 0; c < ncomp; c++) {
        hsize_t *x = coord + (i * ncomp + c) * rank;
        x[0]       = (hsize_t)rows[i];
        if (rank == 2) x[1] = (hsize_t)c;
      }
    ms = H5Screate_simple(1, &mdim, NULL);
    QuietBegin(&q);
    rc = H5Sselect_elements(fs, H5S_SELECT_SET, (size_t)(n * ncomp), coord);
    if (rc >= 0) rc = H5Dread(ds, mtype, ms, fs, H5P_DEFAULT, buf);
    QuietEnd(&q);
    (void)H5Sclose(ms);
    PetscCall(PetscFree(coord));
  }
  (void)H5Sclose(fs), (void)H5Dclose(ds);
  if (rc < 0) READ_ERR("%s: reading %s failed (a damaged file?)", r->path, name);
  PetscFunctionReturn(PETSC_SUCCESS);
}

static herr_t ReadAttr(hid_t g, const char *name, hid_t mtype, void *val)
{
  hid_t  a = H5Aopen(g, name, H5P_DEFAULT);
  herr_t rc;
  if (a < 0) return -1;
  rc = H5Aread(a, mtype, val);
  (void)H5Aclose(a);
  return rc;
}

/* the frames' step, increment and time attributes */
static PetscErrorCode ReadFrames(TslResults r)
{
  hid_t    g;
  PetscInt count = 0;
  herr_t   rc    = 0;
  Quiet    q;

  PetscFunctionBeginUser;
  QuietBegin(&q);
  g = H5Gopen2(r->file, "/frames", H5P_DEFAULT);
  if (g >= 0) {
    H5G_info_t info;
    rc    = H5Gget_info(g, &info); /* /frames holds the frames alone, 000001, 000002, ... (xdmf.c) */
    count = rc < 0 ? 0 : (PetscInt)info.nlinks;
  }
  QuietEnd(&q);
  if (g < 0 || rc < 0) {
    if (g >= 0) (void)H5Gclose(g);
    READ_ERR("%s has no /frames: not a thermoslide result", r->path);
  }
  PetscCall(PetscCalloc1(count, &r->frames));
  r->nframe = count;
  for (PetscInt k = 0; k < count; k++) {
    char    name[16];
    hid_t   f;
    int64_t step = 0, inc = 0;
    double  t    = 0;
    PetscCall(PetscSNPrintf(name, sizeof(name), "%06d", (int)(k + 1)));
    QuietBegin(&q);
    f  = H5Gopen2(g, name, H5P_DEFAULT);
    rc = f < 0 ? -1 : 0;
    if (rc >= 0) rc = ReadAttr(f, "step", H5T_NATIVE_INT64, &step);
    if (rc >= 0) rc = ReadAttr(f, "increment", H5T_NATIVE_INT64, &inc);
    if (rc >= 0) rc = ReadAttr(f, "time", H5T_NATIVE_DOUBLE, &t);
    QuietEnd(&q);
    if (f >= 0) (void)H5Gclose(f);
    if (rc < 0) {
      (void)H5Gclose(g);
      READ_ERR("%s: frame %s is missing or has no step, increment and time (frames must be numbered 1, 2, ...; a damaged file?)", r->path, name);
    }
    r->frames[k] = (TslResultsFrame){(PetscInt)step, (PetscInt)inc, (PetscReal)t};
  }
  (void)H5Gclose(g);
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TslResultsOpen(const char *path, TslResults *out)
{
  TslResults r;
  hid_t      ds, fs;
  hsize_t    dims[2] = {0, 0};
  Quiet      q;

  PetscFunctionBeginUser;
  *out = NULL;
  PetscCall(PetscNew(&r));
  r->file = -1;
  PetscCall(PetscStrncpy(r->path, path, sizeof(r->path)));
  QuietBegin(&q);
  r->file = H5Fopen(path, H5F_ACC_RDONLY, H5P_DEFAULT);
  ds      = r->file >= 0 ? H5Dopen2(r->file, "/mesh/node_ids", H5P_DEFAULT) : -1;
  QuietEnd(&q);
  if (ds < 0) {
    PetscBool hdf5 = r->file >= 0 ? PETSC_TRUE : PETSC_FALSE;
    PetscCall(TslResultsClose(&r));
    READ_ERR("%s %s", path, hdf5 ? "has no /mesh/node_ids: not a thermoslide result" : "is not a readable HDF5 file (not a thermoslide result, or damaged)");
  }
  fs = H5Dget_space(ds);
  (void)H5Sget_simple_extent_dims(fs, dims, NULL);
  r->nnode = (PetscInt)dims[0];
  (void)H5Sclose(fs), (void)H5Dclose(ds);
  {
    PetscErrorCode ierr = ReadFrames(r);
    if (ierr) {
      (void)TslResultsClose(&r);
      PetscCall(ierr);
    }
  }
  *out = r;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TslResultsInfo(TslResults r, PetscInt *nnode, PetscInt *nframe, const TslResultsFrame **frames)
{
  PetscFunctionBeginUser;
  if (nnode) *nnode = r->nnode;
  if (nframe) *nframe = r->nframe;
  if (frames) *frames = r->frames;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TslResultsReadRows(TslResults r, const char *dataset, PetscInt n, const PetscInt rows[], PetscInt ncomp, PetscReal vals[])
{
  double *buf;

  PetscFunctionBeginUser;
  PetscCall(PetscMalloc1(n * ncomp, &buf));
  PetscErrorCode ierr = ReadRows(r, dataset, n, rows, ncomp, H5T_NATIVE_DOUBLE, buf);
  for (PetscInt i = 0; !ierr && i < n * ncomp; i++) vals[i] = (PetscReal)buf[i];
  PetscCall(PetscFree(buf));
  PetscCall(ierr);
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TslResultsReadNodeIds(TslResults r, PetscInt n, const PetscInt rows[], PetscInt ids[])
{
  int64_t *buf;

  PetscFunctionBeginUser;
  PetscCall(PetscMalloc1(n, &buf));
  PetscErrorCode ierr = ReadRows(r, "/mesh/node_ids", n, rows, 1, H5T_NATIVE_INT64, buf);
  for (PetscInt i = 0; !ierr && i < n; i++) ids[i] = (PetscInt)buf[i];
  PetscCall(PetscFree(buf));
  PetscCall(ierr);
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TslResultsClose(TslResults *r)
{
  PetscFunctionBeginUser;
  if (!*r) PetscFunctionReturn(PETSC_SUCCESS);
  if ((*r)->file >= 0) (void)H5Fclose((*r)->file);
  PetscCall(PetscFree((*r)->frames));
  PetscCall(PetscFree(*r));
  PetscFunctionReturn(PETSC_SUCCESS);
}
