/* Restart points and the continuation from one (docs/running.md, "Restart").
 *
 * A point is one HDF5 file, <job>.restart.<step>.<increment>.h5 in the output directory, written through PETSc's
 * HDF5 viewer (parallel, collective) under a scratch name and renamed over when complete, so that a crash while
 * writing leaves the points before it valid. It holds
 *   header   the increment loop's variables (TslRestartLoop), the driver's sums, the output's frame and history
 *            row counts and its run identity, and each step's total time at its start;
 *   layout   per rank: a digest of its nodes, elements and contact nodes (a continuation on the same rank count
 *            must have the same partition: it reads the vectors as they stand);
 *   X, Xprev the solution at the point and the one before it (the extrapolation of the next increment's start);
 *   start_k  the solution at the start of each step k up to the point's (TslProblemSetStep reads the values reached
 *            there: ramps from them, FIXED holds them), replayed by the continuation step by step;
 *   extra_j  in an explicit step's point, the procedure's own vectors (TslRestartExtra, explicit.c: velocity,
 *            masses, forces);
 *   natnode  the natural index of each node block of the vectors (a point read on another rank count: NaturalMap);
 *   blobs    the problem's state (contact nodes, plastic points, surface-to-surface points: TslProblemStateBlobs) and
 *            an explicit step's scalars, in natural terms: records of keys and reals (LoadState);
 *   xelem    in an explicit step's point, each element's reals under its natural index (ElemRecords);
 *   checksum one order-independent checksum per dataset above (the sum of its values' bits modulo 2^64), verified
 *            before a point is used, so that a corrupted point is passed over for the one before it.
 * The vectors are in PETSc's parallel layout: on the rank count and partition the point was written with they are read
 * as they stand, on another they are scattered to this run's layout through natnode. The state is in natural terms
 * whatever the count, one form for both: blobs and xelem are read by rendezvous on their keys (TslRendezvous), which
 * gives each record back bit for bit. */
#include "solve_impl.h"
#include <petscviewerhdf5.h>
#include <dirent.h>
#include <errno.h>
#include <hdf5.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

#define RS_VERSION 6
enum {
  H_VERSION = 0,
  H_NRANKS,
  H_NSTEP,
  H_STEP,
  H_INC,
  H_ITS_PREV,
  H_CUTBACKS,
  H_T,
  H_DT,
  H_TOTAL,
  H_H_PREV,
  H_FRAMES_NEXT,
  H_FELL_BACK,
  H_NFRAME,
  H_NROW,
  H_RUN_ID,
  H_HAS_XPREV,
  H_MODEL,  /* TslProblemModelDigest: materials, sections, interactions */
  H_NEXTRA, /* the procedure's own datasets (TslRestartExtra): its vectors and its reals, 0 when none */
  H_PTIME,  /* the problem's step time as set (the last increment's start plus its length: the period to a rounding) */
  H_MESH,   /* TslProblemMeshDigest: the mesh and contact nodes, whatever the rank count */
  H_NBLOB,  /* records of the dataset blobs (the state in natural terms) */
  H_XELEM,  /* an explicit step's point: the width of the records of the dataset xelem (ElemRecords); 0 none */
  H_SUMS,
  H_TSTART = H_SUMS + 24 /* then 2 per step: total time at its start, step time the step before ended at */
};

static PetscInt HeaderLength(PetscInt nstep)
{
  return H_TSTART + 2 * nstep;
}

/* The driver's sums that carry across increments and steps, in and out of a header. */
static void SaveSums(const Driver *d, PetscReal v[24])
{
  PetscInt k = 0;
  v[k++]     = d->dissipated;
  v[k++]     = d->absorbed;
  v[k++]     = d->plastic_dissipated;
  for (PetscInt i = 0; i < 7; i++) v[k++] = d->energy[i];
  for (PetscInt i = 0; i < 2; i++) v[k++] = d->q_sum[i], v[k++] = d->q_before[i];
  v[k++] = (PetscReal)d->q_n;
  v[k++] = d->scale_u;
  v[k++] = d->scale_theta;
  v[k++] = d->done_time;
  v[k++] = d->done_step_time;
  v[k++] = d->done_dt;
  v[k++] = (PetscReal)d->done_step;
  v[k++] = (PetscReal)d->done_inc;
  v[k++] = (PetscReal)d->frame_step;
  v[k++] = (PetscReal)d->frame_inc;
}

static void RestoreSums(Driver *d, const PetscReal v[24])
{
  PetscInt k            = 0;
  d->dissipated         = v[k++];
  d->absorbed           = v[k++];
  d->plastic_dissipated = v[k++];
  for (PetscInt i = 0; i < 7; i++) d->energy[i] = v[k++];
  for (PetscInt i = 0; i < 2; i++) d->q_sum[i] = v[k++], d->q_before[i] = v[k++];
  d->q_n            = (PetscInt)v[k++];
  d->scale_u        = v[k++];
  d->scale_theta    = v[k++];
  d->done_time      = v[k++];
  d->done_step_time = v[k++];
  d->done_dt        = v[k++];
  d->done_step      = (PetscInt)v[k++];
  d->done_inc       = (PetscInt)v[k++];
  d->frame_step     = (PetscInt)v[k++];
  d->frame_inc      = (PetscInt)v[k++];
}

static PetscReal Bits(uint64_t u)
{
  PetscReal r;
  memcpy(&r, &u, sizeof(r));
  return r;
}

static uint64_t Unbits(PetscReal r)
{
  uint64_t u;
  memcpy(&u, &r, sizeof(u));
  return u;
}

/* The point of step (1-based) and increment inc of job, given as DIR/JOB (or JOB in the working directory). */
static PetscErrorCode JobPointPath(const char *job, PetscInt step, PetscInt inc, char buf[], size_t len)
{
  PetscFunctionBeginUser;
  PetscCall(PetscSNPrintf(buf, len, "%s.restart.%" PetscInt_FMT ".%" PetscInt_FMT ".h5", job, step, inc));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* ... of this run's job */
static PetscErrorCode PointPath(Driver *d, PetscInt step, PetscInt inc, char buf[], size_t len)
{
  char job[PETSC_MAX_PATH_LEN + 300];

  PetscFunctionBeginUser;
  PetscCall(PetscSNPrintf(job, sizeof(job), "%s%s%s", d->rs_dir, d->rs_dir[0] ? "/" : "", d->rs_job));
  PetscCall(JobPointPath(job, step, inc, buf, len));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* DIR/JOB into its directory (".": none given) and *base, the job's name in it */
static void SplitJob(const char *job, char dir[], size_t len, const char **base)
{
  const char *slash = strrchr(job, '/');
  snprintf(dir, len, "%.*s", slash ? (int)(slash - job) + (slash == job) : 1, slash ? job : ".");
  *base = slash ? slash + 1 : job;
}

/* A vector of n local reals (a header on rank 0 only, one digest a rank, the state's bytes) */
static PetscErrorCode LocalVec(MPI_Comm comm, PetscInt n, const char *name, Vec *v)
{
  PetscFunctionBeginUser;
  PetscCall(VecCreateMPI(comm, n, PETSC_DETERMINE, v));
  PetscCall(PetscObjectSetName((PetscObject)*v, name));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode ViewNamed(Vec v, const char *name, PetscViewer vw)
{
  const char *old;

  PetscFunctionBeginUser;
  PetscCall(PetscObjectGetName((PetscObject)v, &old));
  {
    char keep[256];
    PetscCall(PetscStrncpy(keep, old ? old : "", sizeof(keep)));
    PetscCall(PetscObjectSetName((PetscObject)v, name));
    PetscCall(VecView(v, vw));
    PetscCall(PetscObjectSetName((PetscObject)v, keep));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* VecLoad replaces a vector's array, which a ghosted vector's local form shares: the values go through a plain
 * vector of the same layout */
static PetscErrorCode LoadNamed(Vec v, const char *name, PetscViewer vw)
{
  Vec      tmp;
  PetscInt n;

  PetscFunctionBeginUser;
  PetscCall(VecGetLocalSize(v, &n));
  PetscCall(LocalVec(PetscObjectComm((PetscObject)v), n, name, &tmp));
  PetscCall(VecLoad(tmp, vw));
  PetscCall(VecCopy(tmp, v));
  PetscCall(VecDestroy(&tmp));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The sum of the bits of v's values modulo 2^64, with its length: independent of the order and the ranks */
static PetscErrorCode Checksum(Vec v, uint64_t *ck)
{
  const PetscScalar *a;
  PetscInt           n, N;
  uint64_t           c = 0;

  PetscFunctionBeginUser;
  PetscCall(VecGetLocalSize(v, &n));
  PetscCall(VecGetSize(v, &N));
  PetscCall(VecGetArrayRead(v, &a));
  for (PetscInt i = 0; i < n; i++) {
    uint64_t u;
    memcpy(&u, &a[i], sizeof(u));
    c += u;
  }
  PetscCall(VecRestoreArrayRead(v, &a));
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &c, 1, MPI_UINT64_T, MPI_SUM, PetscObjectComm((PetscObject)v)));
  *ck = c + (uint64_t)N * 0x9e3779b97f4a7c15ull;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The checksums' places: layout, state, X, Xprev, natnode, blobs (with xelem's added), then start_k, then the extra
 * datasets */
enum { CK_LAYOUT = 0, CK_X, CK_XPREV, CK_NATNODE, CK_BLOBS, CK_START };

/* The state in natural terms (TslProblemStateBlobs) as records of BLOB_KL keys (the blob's, then the chunk's number)
 * and BLOB_W reals, a blob cut into chunks of BLOB_W reals (at least one) */
#define BLOB_KL  (TSL_BLOB_KEY + 1)
#define BLOB_W   16
#define BLOB_REC (BLOB_KL + BLOB_W)
static PetscInt BlobChunks(PetscInt len)
{
  return PetscMax(1, (len + BLOB_W - 1) / BLOB_W);
}

/* An explicit step's reals in natural terms (TslRestartExtra's parts): its scalars, the same on every rank, as the
 * blob (7, 0, 0, 0, its length) written by rank 0 (ExtraScalars: the key into key[], the values into val if not
 * NULL); each local element's reals as a record of the dataset xelem, [its natural index, its nearr values, its
 * carried real], XelemWidth reals (ElemRecords). */
enum { B_EXPLICIT_SCALARS = 7 };
static void ExtraScalars(const TslRestartExtra *e, int64_t key[], PetscInt *len, PetscReal *val)
{
  key[0] = B_EXPLICIT_SCALARS, key[1] = key[2] = key[3] = 0, key[4] = e->nglobal;
  *len = e->nglobal;
  if (val) (void)PetscArraycpy(val, e->real, e->nglobal);
}

static PetscInt XelemWidth(const TslRestartExtra *e)
{
  return e->nearr + 2;
}

static PetscErrorCode ElemRecords(Driver *d, const TslRestartExtra *e, Vec *xv)
{
  const TslModel *m;
  const PetscInt  w = XelemWidth(e);
  PetscScalar    *a;

  PetscFunctionBeginUser;
  PetscCall(TslProblemGetModel(d->prob, &m));
  PetscCall(LocalVec(d->comm, m->nelem * w, "xelem", xv));
  PetscCall(VecGetArray(*xv, &a));
  for (PetscInt el = 0; el < m->nelem; el++) {
    PetscScalar *r = &a[el * w];
    r[0]           = (PetscReal)m->elem_nat[el];
    for (PetscInt j = 0; j < e->nearr; j++) r[1 + j] = e->real[e->nglobal + j * m->nelem + el];
    r[w - 1] = e->lane && e->lane[el] >= 0 ? e->real[e->carried_off + e->lane[el]] : 0;
  }
  PetscCall(VecRestoreArray(*xv, &a));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* This rank's share of the points' datasets in natural terms: natnode, the natural index of each owned node (the
 * blocks of X in order), and blobs, the state's records and an explicit step's scalars (*nrec of them) */
static PetscErrorCode NaturalData(Driver *d, const TslRestartExtra *extra, Vec *nv, Vec *bv, PetscInt *nrec)
{
  const TslModel *m;
  PetscInt        n, *len, nown, ndof;
  int64_t        *key;
  PetscReal      *val;
  PetscScalar    *a;
  Vec             X;

  PetscFunctionBeginUser;
  PetscCall(TslProblemGetModel(d->prob, &m));
  PetscCall(TslProblemGetSolution(d->prob, &X));
  PetscCall(VecGetLocalSize(X, &nown));
  PetscCall(VecGetBlockSize(X, &ndof));
  nown /= ndof;
  PetscCall(LocalVec(d->comm, nown, "natnode", nv));
  PetscCall(VecGetArray(*nv, &a));
  for (PetscInt l = 0; l < nown; l++) a[l] = (PetscReal)m->node_nat[l];
  PetscCall(VecRestoreArray(*nv, &a));
  PetscCall(TslProblemStateBlobs(d->prob, &n, &key, &len, &val));
  if (extra) { /* the explicit step's scalars appended to the state's, by rank 0 */
    PetscMPIInt rank;
    PetscInt    nv_ = 0;
    PetscCallMPI(MPI_Comm_rank(d->comm, &rank));
    if (!rank) {
      for (PetscInt i = 0; i < n; i++) nv_ += len[i];
      PetscCall(PetscRealloc(sizeof(int64_t) * TSL_BLOB_KEY * (n + 2), &key));
      PetscCall(PetscRealloc(sizeof(PetscInt) * (n + 2), &len));
      PetscCall(PetscRealloc(sizeof(PetscReal) * (nv_ + extra->nglobal + 1), &val));
      ExtraScalars(extra, &key[TSL_BLOB_KEY * n], &len[n], &val[nv_]);
      n++;
    }
  }
  *nrec = 0;
  for (PetscInt i = 0; i < n; i++) *nrec += BlobChunks(len[i]);
  PetscCall(LocalVec(d->comm, *nrec * BLOB_REC, "blobs", bv));
  PetscCall(VecGetArray(*bv, &a));
  for (PetscInt i = 0, r = 0, off = 0; i < n; off += len[i++])
    for (PetscInt c = 0; c < BlobChunks(len[i]); c++, r++) {
      PetscScalar *rec = &a[r * BLOB_REC];
      for (PetscInt k = 0; k < TSL_BLOB_KEY; k++) rec[k] = (PetscReal)key[TSL_BLOB_KEY * i + k];
      rec[TSL_BLOB_KEY] = (PetscReal)c;
      for (PetscInt j = 0; j < BLOB_W; j++) rec[BLOB_KL + j] = c * BLOB_W + j < len[i] ? val[off + c * BLOB_W + j] : 0;
    }
  PetscCall(VecRestoreArray(*bv, &a));
  PetscCall(PetscFree(key));
  PetscCall(PetscFree(len));
  PetscCall(PetscFree(val));
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, nrec, 1, MPIU_INT, MPI_SUM, d->comm));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static void ExtraName(PetscInt j, char name[], size_t len)
{
  snprintf(name, len, "extra_%d", (int)j);
}

PetscBool TslRestartDue(const TslStep *step, PetscInt inc, PetscReal t_old, PetscReal t_new, PetscBool last, char why[], size_t len)
{
  PetscInt freq = step->restart_frequency, nint = step->restart_interval;

  if (freq < 0) { /* neither FREQUENCY nor NUMBER INTERVAL: the dialect's defaults */
    freq = step->explicit_dynamics ? 0 : 1;
    if (step->explicit_dynamics) nint = 1;
  }
  if (freq <= 0 && nint <= 0) return PETSC_FALSE;
  if (last) {
    snprintf(why, len, "end of step");
    return PETSC_TRUE;
  }
  if (freq > 0 && inc % freq == 0) {
    snprintf(why, len, "FREQUENCY=%d", (int)freq);
    return PETSC_TRUE;
  }
  if (nint > 0 && step->period > 0) {
    /* the first increment that reaches each of the n times k period / n */
    const PetscReal a = PetscFloorReal(t_old * nint / step->period + 1e-9), b = PetscFloorReal(t_new * nint / step->period + 1e-9);
    if (b > a) {
      snprintf(why, len, "NUMBER INTERVAL=%d", (int)nint);
      return PETSC_TRUE;
    }
  }
  return PETSC_FALSE;
}

PetscErrorCode TslRestartWrite(Driver *d, const TslRestartLoop *loop, const char *why, const TslRestartExtra *extra)
{
  const TslModel *m;
  PetscMPIInt     size, rank;
  PetscInt        nh, ns;
  char            tmp[PETSC_MAX_PATH_LEN + 8], path[PETSC_MAX_PATH_LEN];
  PetscViewer     vw;
  Vec             hv, dv, cv, X, nv, bv, xv = NULL;
  double          t0 = MPI_Wtime();
  uint64_t        digest, model, mesh, *ck;
  PetscInt        nrec;
  int             err = 0;
  const PetscInt  nextra = extra ? extra->nvec : 0;

  PetscFunctionBeginUser;
  PetscCall(TslProblemGetModel(d->prob, &m));
  PetscCallMPI(MPI_Comm_size(d->comm, &size));
  PetscCallMPI(MPI_Comm_rank(d->comm, &rank));
  PetscCall(PointPath(d, loop->step + 1, loop->inc, path, sizeof(path)));
  PetscCall(TslOutputSync(d->out)); /* the frames the point counts are on disk, should the job be killed after it */
  PetscCall(PetscSNPrintf(tmp, sizeof(tmp), "%s.tmp", path));
  ns = loop->step + 1;
  nh = HeaderLength(m->nstep);
  PetscCall(TslProblemModelDigest(d->prob, &model));
  PetscCall(TslProblemMeshDigest(d->prob, &mesh));
  PetscCall(NaturalData(d, extra, &nv, &bv, &nrec));

  PetscCall(LocalVec(d->comm, rank ? 0 : nh, "header", &hv));
  if (!rank) {
    PetscScalar *h;
    PetscCall(VecGetArray(hv, &h));
    for (PetscInt i = 0; i < nh; i++) h[i] = 0;
    h[H_VERSION]     = RS_VERSION;
    h[H_NRANKS]      = size;
    h[H_NSTEP]       = (PetscReal)m->nstep;
    h[H_STEP]        = (PetscReal)loop->step;
    h[H_INC]         = (PetscReal)loop->inc;
    h[H_ITS_PREV]    = (PetscReal)PetscMin(loop->its_prev, 1000000000);
    h[H_CUTBACKS]    = (PetscReal)loop->cutbacks;
    h[H_T]           = loop->t;
    h[H_DT]          = loop->dt;
    h[H_TOTAL]       = loop->total;
    h[H_H_PREV]      = loop->h_prev;
    h[H_FRAMES_NEXT] = loop->frames_next;
    h[H_FELL_BACK]   = d->fell_back ? 1 : 0;
    {
      PetscInt nf;
      PetscCall(TslOutputFrameCount(d->out, &nf));
      h[H_NFRAME] = (PetscReal)nf;
    }
    h[H_NROW]      = (PetscReal)TslHistoryRowCount(d->hist);
    h[H_RUN_ID]    = Bits(TslOutputRunId(d->out));
    h[H_HAS_XPREV] = loop->h_prev > 0 && d->Xprev ? 1 : 0;
    h[H_MODEL]     = Bits(model);
    h[H_NEXTRA]    = (PetscReal)nextra;
    h[H_PTIME]     = TslProblemGetStepTime(d->prob);
    h[H_MESH]      = Bits(mesh);
    h[H_NBLOB]     = (PetscReal)nrec;
    h[H_XELEM]     = extra ? (PetscReal)XelemWidth(extra) : 0;
    SaveSums(d, &h[H_SUMS]);
    for (PetscInt k = 0; k < 2 * ns; k++) h[H_TSTART + k] = d->rs_tstart[k];
    PetscCall(VecRestoreArray(hv, &h));
  } else {
    /* the output's counts are needed on rank 0 only; every rank takes part in nothing here */
  }
  PetscCall(TslProblemLayoutDigest(d->prob, &digest));
  PetscCall(LocalVec(d->comm, 1, "layout", &dv));
  PetscCall(VecSetValue(dv, rank, Bits(digest), INSERT_VALUES));
  PetscCall(VecAssemblyBegin(dv));
  PetscCall(VecAssemblyEnd(dv));
  PetscCall(TslProblemGetSolution(d->prob, &X));
  PetscCall(PetscMalloc1(CK_START + ns + nextra, &ck));
  PetscCall(Checksum(dv, &ck[CK_LAYOUT]));
  PetscCall(Checksum(X, &ck[CK_X]));
  ck[CK_XPREV] = 0;
  if (loop->h_prev > 0 && d->Xprev) PetscCall(Checksum(d->Xprev, &ck[CK_XPREV]));
  PetscCall(Checksum(nv, &ck[CK_NATNODE]));
  PetscCall(Checksum(bv, &ck[CK_BLOBS]));
  if (extra) {
    uint64_t cx;
    PetscCall(ElemRecords(d, extra, &xv));
    PetscCall(Checksum(xv, &cx));
    ck[CK_BLOBS] += cx;
  }
  for (PetscInt k = 0; k < ns; k++) PetscCall(Checksum(d->rs_xstart[k], &ck[CK_START + k]));
  for (PetscInt j = 0; j < nextra; j++) PetscCall(Checksum(extra->vec[j], &ck[CK_START + ns + j]));
  PetscCall(LocalVec(d->comm, rank ? 0 : CK_START + ns + nextra, "checksum", &cv));
  if (!rank) {
    PetscScalar *c;
    PetscCall(VecGetArray(cv, &c));
    for (PetscInt k = 0; k < CK_START + ns + nextra; k++) c[k] = Bits(ck[k]);
    PetscCall(VecRestoreArray(cv, &c));
  }
  PetscCall(PetscFree(ck));

  PetscCall(PetscViewerHDF5Open(d->comm, tmp, FILE_MODE_WRITE, &vw));
  PetscCall(VecView(hv, vw));
  PetscCall(VecView(dv, vw));
  PetscCall(VecView(cv, vw));
  PetscCall(VecView(nv, vw));
  PetscCall(VecView(bv, vw));
  if (xv) PetscCall(VecView(xv, vw));
  PetscCall(ViewNamed(X, "X", vw));
  if (loop->h_prev > 0 && d->Xprev) PetscCall(ViewNamed(d->Xprev, "Xprev", vw));
  for (PetscInt k = 0; k < ns; k++) {
    char name[32];
    PetscCall(PetscSNPrintf(name, sizeof(name), "start_%" PetscInt_FMT, k));
    PetscCall(ViewNamed(d->rs_xstart[k], name, vw));
  }
  for (PetscInt j = 0; j < nextra; j++) {
    char name[32];
    ExtraName(j, name, sizeof(name));
    PetscCall(ViewNamed(extra->vec[j], name, vw));
  }
  {
    PetscInt one = 1;
    PetscCall(PetscViewerHDF5WriteAttribute(vw, "/header", "complete", PETSC_INT, &one));
  }
  PetscCall(PetscViewerDestroy(&vw));
  PetscCall(VecDestroy(&hv));
  PetscCall(VecDestroy(&dv));
  PetscCall(VecDestroy(&cv));
  PetscCall(VecDestroy(&nv));
  PetscCall(VecDestroy(&bv));
  PetscCall(VecDestroy(&xv));
  if (!rank && rename(tmp, path)) err = errno;
  PetscCallMPI(MPI_Bcast(&err, 1, MPI_INT, 0, d->comm));
  PetscCheck(!err, d->comm, PETSC_ERR_FILE_WRITE, "Cannot rename the restart point %s to %s: %s", tmp, path, strerror(err));
  /* OVERLAY: only the latest point is kept, the one before it removed once this one is in place */
  if (m->steps[loop->step].restart_overlay && d->rs_last[0] && strcmp(d->rs_last, path) && !rank) (void)unlink(d->rs_last);
  PetscCall(PetscStrncpy(d->rs_last, path, sizeof(d->rs_last)));
  {
    double   dt = MPI_Wtime() - t0, b;
    PetscInt N, bs;
    PetscCall(VecGetSize(X, &N));
    PetscCall(VecGetBlockSize(X, &bs));
    b = 8.0 * N * (1 + ns + (loop->h_prev > 0 && d->Xprev) + nextra);   /* the vectors */
    b += 8.0 * ((double)N / bs + (double)nrec * BLOB_REC);               /* natnode, blobs */
    if (extra) b += 8.0 * (double)m->nelem_global * XelemWidth(extra); /* xelem */
    PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &dt, 1, MPI_DOUBLE, MPI_MAX, d->comm));
    d->rs_count++;
    d->rs_seconds += dt;
    d->rs_bytes = b;
    PetscCall(PetscPrintf(d->comm, "  restart point %s (%s): step %" PetscInt_FMT " increment %" PetscInt_FMT ", step time %g, %.2f s\n", path, why,
                          loop->step + 1, loop->inc, (double)loop->t, dt));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* What a continuation expects of a point: the header's length, the rank count, the model and mesh digests, the global
 * lengths of X, its block size and the element count */
typedef struct {
  PetscInt    nh, nx, bs, nelem;
  PetscMPIInt size;
  uint64_t    model, mesh;
  PetscInt    any_steps; /* > 0: a point of another deck with at least this many steps (-oldjob), its header of any length */
} Expect;

/* Rank 0, HDF5 quiet: whether dataset name of f is there with n entries */
static PetscBool HasDataset(hid_t f, const char *name, PetscInt n)
{
  hid_t     ds = H5Dopen2(f, name, H5P_DEFAULT), sp = -1;
  hsize_t   dims[4] = {0, 0, 0, 0};
  int       nd      = 0;
  PetscBool ok      = PETSC_FALSE;

  /* a vector of block size bs is written as [N / bs, bs] */
  if (ds >= 0 && (sp = H5Dget_space(ds)) >= 0 && (nd = H5Sget_simple_extent_ndims(sp)) >= 1 && nd <= 4 && H5Sget_simple_extent_dims(sp, dims, NULL) >= 0) {
    hsize_t total = 1;
    for (int i = 0; i < nd; i++) total *= dims[i];
    ok = (PetscBool)((PetscInt)total == n);
  }
  if (sp >= 0) H5Sclose(sp);
  if (ds >= 0) H5Dclose(ds);
  return ok;
}

/* Rank 0: whether path is a complete point for this job (1), one to pass over for an earlier one (0: incomplete,
 * truncated, unreadable) or one that cannot be continued with this deck and rank count at all (-1: another rank count,
 * model or mesh); the reason in why, the point's step, whether it holds Xprev and its extra datasets in h_step,
 * h_xprev, h_nextra, its header's length in h_len. */
static int PointValid(const char *path, const Expect *e, char why[], size_t len, PetscInt *h_step, PetscInt *h_xprev, PetscInt *h_nextra, PetscInt *h_len, PetscInt *h_nranks,
                      PetscInt *h_nblob, PetscInt *h_xelem)
{
  H5E_auto2_t efunc;
  void       *edata;
  hid_t       f, ds = -1, sp = -1, at = -1;
  hsize_t     dims[2] = {0, 0};
  int64_t     complete = 0;
  double      h[H_SUMS];
  int         ok = 0;

  (void)H5Eget_auto2(H5E_DEFAULT, &efunc, &edata);
  (void)H5Eset_auto2(H5E_DEFAULT, NULL, NULL);
  f = H5Fopen(path, H5F_ACC_RDONLY, H5P_DEFAULT);
  if (f < 0) {
    snprintf(why, len, "not a readable HDF5 file (truncated or corrupted?)");
    goto done;
  }
  ds = H5Dopen2(f, "/header", H5P_DEFAULT);
  if (ds < 0 || (at = H5Aopen(ds, "complete", H5P_DEFAULT)) < 0 || H5Aread(at, H5T_NATIVE_INT64, &complete) < 0 || complete != 1) {
    snprintf(why, len, "incomplete (no header marked complete)");
    goto done;
  }
  sp = H5Dget_space(ds);
  if (sp < 0 || H5Sget_simple_extent_ndims(sp) < 1 || H5Sget_simple_extent_dims(sp, dims, NULL) < 0 ||
      (e->any_steps ? (PetscInt)dims[0] < HeaderLength(e->any_steps) : (PetscInt)dims[0] != e->nh)) {
    snprintf(why, len, "written for a deck of another number of steps");
    ok = -1;
    goto done;
  }
  {
    hid_t   ms  = H5Screate_simple(1, (hsize_t[]){H_SUMS}, NULL);
    hsize_t off = 0, cnt = H_SUMS;
    H5Sselect_hyperslab(sp, H5S_SELECT_SET, &off, NULL, &cnt, NULL);
    if (H5Dread(ds, H5T_NATIVE_DOUBLE, ms, sp, H5P_DEFAULT, h) < 0) {
      H5Sclose(ms);
      snprintf(why, len, "its header cannot be read");
      goto done;
    }
    H5Sclose(ms);
  }
  if (h[H_VERSION] != RS_VERSION) {
    snprintf(why, len, "written by another version of thermoslide (format %g, this one reads %d)", h[H_VERSION], RS_VERSION);
    ok = -1;
    goto done;
  }
  if (Unbits(h[H_MODEL]) != e->model) {
    snprintf(why, len, "written for a model with other materials, sections or contact interactions than this deck's");
    ok = -1;
    goto done;
  }
  if (!HasDataset(f, "X", e->nx) || Unbits(h[H_MESH]) != e->mesh) {
    snprintf(why, len, "written for another mesh (its nodes, elements or contact nodes differ from this deck's)");
    ok = -1;
    goto done;
  }
  *h_nranks = (PetscInt)h[H_NRANKS];
  *h_nblob  = (PetscInt)h[H_NBLOB];
  *h_xelem  = (PetscInt)h[H_XELEM];
  if (*h_nranks < 1 || *h_nblob < 0 || *h_xelem < 0 || !HasDataset(f, "layout", *h_nranks) || !HasDataset(f, "natnode", e->nx / e->bs) ||
      !HasDataset(f, "blobs", *h_nblob * BLOB_REC) || (*h_xelem && !HasDataset(f, "xelem", e->nelem * *h_xelem))) {
    snprintf(why, len, "some of its data are missing (truncated or corrupted?)");
    goto done;
  }
  *h_len    = (PetscInt)dims[0];
  *h_step   = (PetscInt)h[H_STEP];
  *h_xprev  = h[H_HAS_XPREV] > 0;
  *h_nextra = (PetscInt)h[H_NEXTRA];
  if (*h_step < 0 || (PetscInt)(2 * *h_step + H_TSTART) >= *h_len || *h_nextra < 0 || *h_nextra > TSL_RESTART_MAXVEC ||
      !HasDataset(f, "checksum", CK_START + *h_step + 1 + *h_nextra) || (*h_xprev && !HasDataset(f, "Xprev", e->nx))) {
    snprintf(why, len, "some of its data are missing (truncated or corrupted?)");
    goto done;
  }
  for (PetscInt k = 0; k <= *h_step; k++) {
    char name[32];
    snprintf(name, sizeof(name), "start_%d", (int)k);
    if (!HasDataset(f, name, e->nx)) {
      snprintf(why, len, "some of its data are missing (truncated or corrupted?)");
      goto done;
    }
  }
  for (PetscInt j = 0; j < *h_nextra; j++) {
    char name[32];
    ExtraName(j, name, sizeof(name));
    if (!HasDataset(f, name, e->nx)) {
      snprintf(why, len, "some of its data are missing (truncated or corrupted?)");
      goto done;
    }
  }
  ok = 1;
done:
  if (at >= 0) H5Aclose(at);
  if (sp >= 0) H5Sclose(sp);
  if (ds >= 0) H5Dclose(ds);
  if (f >= 0) H5Fclose(f);
  (void)H5Eset_auto2(H5E_DEFAULT, efunc, edata);
  return ok;
}

/* Collective: every dataset of the point read and checked against its checksum, and this rank's layout against the
 * one written. *status: 1 sound, 0 corrupted (why), -1 another model or partition (why). */
static PetscErrorCode VerifyData(Driver *d, const char *path, PetscInt step, PetscInt xprev, PetscInt nextra, PetscBool portable, PetscBool xelem, int *status, char why[],
                                 size_t len)
{
  PetscViewer vw;
  Vec         cv, v;
  PetscMPIInt rank;
  PetscInt    nck = CK_START + step + 1 + nextra;
  uint64_t   *want, got, digest;
  PetscBool   bad = PETSC_FALSE;
  const char *which = NULL;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(d->comm, &rank));
  PetscCall(PetscMalloc1(nck, &want));
  PetscCall(PetscViewerHDF5Open(d->comm, path, FILE_MODE_READ, &vw));
  PetscCall(LocalVec(d->comm, rank ? 0 : nck, "checksum", &cv));
  PetscCall(VecLoad(cv, vw));
  if (!rank) {
    const PetscScalar *c;
    PetscCall(VecGetArrayRead(cv, &c));
    for (PetscInt k = 0; k < nck; k++) want[k] = Unbits(PetscRealPart(c[k]));
    PetscCall(VecRestoreArrayRead(cv, &c));
  }
  PetscCall(VecDestroy(&cv));
  PetscCallMPI(MPI_Bcast(want, (PetscMPIInt)nck, MPI_UINT64_T, 0, d->comm));
  *status = 1;
  /* the layout: on the rank count the point was written on, this rank's digest against the one its rank wrote (the
   * vectors are read as they stand); on another, only checked (they are read in natural terms) */
  if (portable) {
    PetscCall(VecCreate(d->comm, &v));
    PetscCall(VecSetType(v, VECMPI));
    PetscCall(PetscObjectSetName((PetscObject)v, "layout"));
  } else PetscCall(LocalVec(d->comm, 1, "layout", &v));
  PetscCall(VecLoad(v, vw));
  PetscCall(Checksum(v, &got));
  if (got != want[CK_LAYOUT]) *status = 0, which = "layout";
  else if (!portable) {
    const PetscScalar *a;
    PetscCall(TslProblemLayoutDigest(d->prob, &digest));
    PetscCall(VecGetArrayRead(v, &a));
    bad = (PetscBool)(Unbits(PetscRealPart(a[0])) != digest);
    PetscCall(VecRestoreArrayRead(v, &a));
    PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &bad, 1, MPIU_BOOL, MPI_LOR, d->comm));
    if (bad) {
      *status = -1;
      snprintf(why, len, "written for another model or partition (the nodes, elements or contact nodes of a rank differ): continue it with the deck and options it was written with");
    }
  }
  PetscCall(VecDestroy(&v));
  for (PetscInt k = CK_X; k < nck && *status == 1; k++) {
    char           name[32];
    const PetscInt j = k - (CK_START + step + 1); /* an extra dataset's index */
    const char    *names[CK_START] = {"layout", "X", "Xprev", "natnode", "blobs"};
    if (k == CK_XPREV && !xprev) continue;
    if (k < CK_START) PetscCall(PetscStrncpy(name, names[k], sizeof(name)));
    else if (j < 0) PetscCall(PetscSNPrintf(name, sizeof(name), "start_%" PetscInt_FMT, k - CK_START));
    else ExtraName(j, name, sizeof(name));
    /* in PETSc's split: the checksum is independent of the ranks' shares */
    PetscCall(VecCreate(d->comm, &v));
    PetscCall(VecSetType(v, VECMPI));
    PetscCall(PetscObjectSetName((PetscObject)v, name));
    PetscCall(VecLoad(v, vw));
    PetscCall(Checksum(v, &got));
    PetscCall(VecDestroy(&v));
    if (k == CK_BLOBS && xelem) { /* with the explicit step's element records */
      uint64_t cx;
      PetscCall(VecCreate(d->comm, &v));
      PetscCall(VecSetType(v, VECMPI));
      PetscCall(PetscObjectSetName((PetscObject)v, "xelem"));
      PetscCall(VecLoad(v, vw));
      PetscCall(Checksum(v, &cx));
      PetscCall(VecDestroy(&v));
      got += cx;
    }
    if (got != want[k]) *status = 0, which = k < CK_START ? names[k] : j < 0 ? "start" : "explicit";
  }
  PetscCall(PetscViewerDestroy(&vw));
  PetscCall(PetscFree(want));
  if (*status == 0) snprintf(why, len, "corrupted (its %s data do not match their checksum)", which);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Rank 0: the earlier run's output (results and history) with this run id: the file of a run killed (.part,
 * renamed here so that this run's output does not overwrite it), of a run stopped (.h5, or .failed.h5 beside
 * earlier results), or the one an earlier continuation moved aside. readonly (another job's output, -oldjob): a
 * killed run's files are read where they are. */
static PetscBool RunId(const char *path, uint64_t *id)
{
  H5E_auto2_t efunc;
  void       *edata;
  hid_t       f, at;
  PetscBool   ok = PETSC_FALSE;

  (void)H5Eget_auto2(H5E_DEFAULT, &efunc, &edata);
  (void)H5Eset_auto2(H5E_DEFAULT, NULL, NULL);
  f = H5Fopen(path, H5F_ACC_RDONLY, H5P_DEFAULT);
  if (f >= 0) {
    at = H5Aopen(f, "run_id", H5P_DEFAULT);
    if (at >= 0) {
      ok = H5Aread(at, H5T_NATIVE_UINT64, id) >= 0;
      H5Aclose(at);
    }
    H5Fclose(f);
  }
  (void)H5Eset_auto2(H5E_DEFAULT, efunc, edata);
  return ok;
}

static int FindOutput(const char *dir, const char *job, PetscBool readonly, uint64_t run_id, char h5[], char csv[], size_t len)
{
  const char *tags[][2] = {
    {".interrupted.h5", ".interrupted.csv"},
    {".h5.part",        ".csv.part"       },
    {".failed.h5",      ".failed.csv"     },
    {".h5",             ".csv"            }
  };
  const char *sep = dir[0] ? "/" : "";
  for (size_t k = 0; k < sizeof(tags) / sizeof(tags[0]); k++) {
    uint64_t id;
    if (snprintf(h5, len, "%s%s%s%s", dir, sep, job, tags[k][0]) >= (int)len) return ENAMETOOLONG;
    if (snprintf(csv, len, "%s%s%s%s", dir, sep, job, tags[k][1]) >= (int)len) return ENAMETOOLONG;
    if (!RunId(h5, &id) || id != run_id) continue;
    if (k == 1 && !readonly) { /* a killed run's files: moved aside, as this run's .part names are about to be created */
      char to_h5[PETSC_MAX_PATH_LEN], to_csv[PETSC_MAX_PATH_LEN];
      if (snprintf(to_h5, sizeof(to_h5), "%s%s%s%s", dir, sep, job, tags[0][0]) >= (int)sizeof(to_h5)) return ENAMETOOLONG;
      if (snprintf(to_csv, sizeof(to_csv), "%s%s%s%s", dir, sep, job, tags[0][1]) >= (int)sizeof(to_csv)) return ENAMETOOLONG;
      if (rename(h5, to_h5) || rename(csv, to_csv)) return errno ? errno : EIO;
      if (snprintf(h5, len, "%s", to_h5) >= (int)len || snprintf(csv, len, "%s", to_csv) >= (int)len) return ENAMETOOLONG;
    }
    return 0;
  }
  return -1;
}

/* Rank 0: the points of job (DIR/JOB), into *pts (malloc'd), *np of them. */
static void ListPoints(const char *job, PetscInt (**pts)[2], PetscInt *np)
{
  const char    *base;
  char           dir[PETSC_MAX_PATH_LEN], pfx[300];
  DIR           *dp;
  struct dirent *e;
  PetscInt       cap = 0;

  *np = 0, *pts = NULL;
  SplitJob(job, dir, sizeof(dir), &base);
  snprintf(pfx, sizeof(pfx), "%s.restart.", base);
  dp = opendir(dir);
  while (dp && (e = readdir(dp))) {
    long long s, i;
    int       n = 0;
    if (strncmp(e->d_name, pfx, strlen(pfx))) continue;
    if (sscanf(e->d_name + strlen(pfx), "%lld.%lld.h5%n", &s, &i, &n) != 2 || e->d_name[strlen(pfx) + n] != 0) continue;
    if (*np == cap) {
      cap  = PetscMax(16, 2 * cap);
      *pts = realloc(*pts, sizeof(**pts) * cap);
    }
    (*pts)[*np][0] = (PetscInt)s, (*pts)[*np][1] = (PetscInt)i, (*np)++;
  }
  if (dp) closedir(dp);
}

/* Points in order of step, then increment (ascending, or descending when latest_first). */
static void SortPoints(PetscInt (*pts)[2], PetscInt np, PetscBool latest_first)
{
  for (PetscInt a = 0; a < np; a++)
    for (PetscInt b = a + 1; b < np; b++) {
      PetscBool later = (PetscBool)(pts[b][0] > pts[a][0] || (pts[b][0] == pts[a][0] && pts[b][1] > pts[a][1]));
      if (later == latest_first) {
        PetscInt t0 = pts[a][0], t1 = pts[a][1];
        pts[a][0] = pts[b][0], pts[a][1] = pts[b][1], pts[b][0] = t0, pts[b][1] = t1;
      }
    }
}

/* What this run expects of a point (any_steps: see Expect). Collective. */
static PetscErrorCode ExpectFor(Driver *d, PetscInt any_steps, Expect *ex)
{
  const TslModel *m;
  Vec             X;

  PetscFunctionBeginUser;
  PetscCall(TslProblemGetModel(d->prob, &m));
  PetscCall(TslProblemGetSolution(d->prob, &X));
  PetscCall(VecGetSize(X, &ex->nx));
  PetscCall(VecGetBlockSize(X, &ex->bs));
  ex->nelem = m->nelem_global;
  PetscCallMPI(MPI_Comm_size(d->comm, &ex->size));
  PetscCall(TslProblemMeshDigest(d->prob, &ex->mesh));
  ex->nh        = HeaderLength(m->nstep);
  ex->any_steps = any_steps;
  PetscCall(TslProblemModelDigest(d->prob, &ex->model));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Collective: the point d->rs_point (checked by CheckPoint) sound (*st 1), to pass over (0) or not to be used at all (-1,
 * why); its extra datasets, this rank's state length and its header's length (*nh_file) into d. */
static PetscErrorCode CheckPoint(Driver *d, const Expect *ex, int *st, char why[], size_t len, PetscInt *nh_file)
{
  PetscMPIInt rank;
  PetscInt    hs[7] = {0, 0, 0, 0, 0, 0, 0};

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(d->comm, &rank));
  if (!rank) *st = PointValid(d->rs_point, ex, why, len, &hs[0], &hs[1], &hs[2], &hs[3], &hs[4], &hs[5], &hs[6]);
  PetscCallMPI(MPI_Bcast(st, 1, MPI_INT, 0, d->comm));
  PetscCallMPI(MPI_Bcast(hs, 7, MPIU_INT, 0, d->comm));
  PetscCallMPI(MPI_Bcast(why, (PetscMPIInt)len, MPI_CHAR, 0, d->comm));
  if (*st == 1) PetscCall(VerifyData(d, d->rs_point, hs[0], hs[1], hs[2], (PetscBool)(hs[4] != ex->size), hs[6] > 0, st, why, len));
  if (*st == 1) {
    d->rs_nextra = hs[2], *nh_file = hs[3];
    d->rs_portable = (PetscBool)(hs[4] != ex->size), d->rs_nblob = hs[5], d->rs_nranks = hs[4], d->rs_xelem = hs[6];
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Collective: the header of the point d->rs_point (nh entries) into d: the loop's state, the sums, each step's start
 * times. */
static PetscErrorCode LoadHeader(Driver *d, PetscInt nh)
{
  const TslModel *m;
  PetscMPIInt     rank;

  PetscFunctionBeginUser;
  PetscCall(TslProblemGetModel(d->prob, &m));
  PetscCallMPI(MPI_Comm_rank(d->comm, &rank));
  {
    PetscViewer  vw;
    Vec          hv;
    PetscScalar *h;
    PetscReal    hb[H_SUMS + 24];
    PetscCall(PetscViewerHDF5Open(d->comm, d->rs_point, FILE_MODE_READ, &vw));
    PetscCall(LocalVec(d->comm, rank ? 0 : nh, "header", &hv));
    PetscCall(VecLoad(hv, vw));
    PetscCall(PetscViewerDestroy(&vw));
    PetscCall(VecGetArray(hv, &h));
    if (!rank) {
      for (PetscInt i = 0; i < H_SUMS + 24; i++) hb[i] = PetscRealPart(h[i]);
      for (PetscInt k = 0; k < PetscMin(2 * m->nstep, nh - H_TSTART); k++) d->rs_tstart[k] = PetscRealPart(h[H_TSTART + k]);
    }
    PetscCall(VecRestoreArray(hv, &h));
    PetscCall(VecDestroy(&hv));
    PetscCallMPI(MPI_Bcast(hb, H_SUMS + 24, MPIU_REAL, 0, d->comm));
    PetscCallMPI(MPI_Bcast(d->rs_tstart, 2 * m->nstep, MPIU_REAL, 0, d->comm));
    d->rs_loop.step        = (PetscInt)hb[H_STEP];
    d->rs_loop.inc         = (PetscInt)hb[H_INC];
    d->rs_loop.its_prev    = (PetscInt)hb[H_ITS_PREV];
    d->rs_loop.cutbacks    = (PetscInt)hb[H_CUTBACKS];
    d->rs_loop.t           = hb[H_T];
    d->rs_loop.dt          = hb[H_DT];
    d->rs_loop.total       = hb[H_TOTAL];
    d->rs_loop.h_prev      = hb[H_HAS_XPREV] > 0 ? hb[H_H_PREV] : 0;
    d->rs_loop.frames_next = hb[H_FRAMES_NEXT];
    d->rs_ptime            = hb[H_PTIME];
    d->rs_fell_back        = (PetscInt)hb[H_FELL_BACK];
    d->rs_nframe           = (PetscInt)hb[H_NFRAME];
    d->rs_nrow             = (PetscInt)hb[H_NROW];
    d->rs_run_id           = Unbits(hb[H_RUN_ID]);
    PetscCall(PetscArraycpy(d->rs_sums, &hb[H_SUMS], 24));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The log's line for a point read on another rank count */
static PetscErrorCode SayPortable(Driver *d)
{
  PetscFunctionBeginUser;
  if (d->rs_portable)
    PetscCall(PetscPrintf(d->comm, "thermoslide: the point was written on %" PetscInt_FMT " ranks: its solution and state are read by node, element and face\n", d->rs_nranks));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TslRestartSetUp(Driver *d, const char *dir, const char *jobname)
{
  const TslModel *m;
  PetscMPIInt     rank;
  char            msg[PETSC_MAX_PATH_LEN + 400] = "";
  int             found                         = 0;
  Expect          ex;
  PetscInt        np = 0, (*pts)[2] = NULL, nh_file = 0;
  char            odir[PETSC_MAX_PATH_LEN] = "", where[PETSC_MAX_PATH_LEN + 64] = "";
  const char     *ojob                     = "";

  PetscFunctionBeginUser;
  PetscCall(TslProblemGetModel(d->prob, &m));
  PetscCall(PetscStrncpy(d->rs_dir, dir ? dir : "", sizeof(d->rs_dir)));
  PetscCall(PetscStrncpy(d->rs_job, jobname, sizeof(d->rs_job)));
  PetscCall(PetscCalloc2(m->nstep, &d->rs_xstart, 2 * m->nstep, &d->rs_tstart));
  /* d->rs_resume: -tsl_restart, read with the implicit procedure's options (driver.c), which continues this job's own
   * points; else a restart deck (*RESTART, READ with -oldjob) continues the old job's point it names */
  if (!d->rs_resume && m->restart_read_step) {
    char        loc[PETSC_MAX_PATH_LEN];
    d->rs_resume   = PETSC_TRUE;
    d->rs_oldjob   = PETSC_TRUE;
    d->rs_end_step = m->restart_read_end_step;
    SplitJob(m->restart_read_job, odir, sizeof(odir), &ojob);
    PetscCall(PetscSNPrintf(where, sizeof(where), "%s: *RESTART, READ: ", TslLocString(m, m->restart_read_loc, loc, sizeof(loc))));
  }
  if (!d->rs_resume) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCallMPI(MPI_Comm_rank(d->comm, &rank));
  PetscCall(ExpectFor(d, d->rs_oldjob ? m->restart_read_step : 0, &ex));
  if (d->rs_oldjob) { /* the one point the deck names (its existence checked when the deck was read) */
    np  = 1;
    pts = malloc(sizeof(*pts));
    pts[0][0] = m->restart_read_step, pts[0][1] = m->restart_read_inc;
  } else if (!rank) { /* the points of this job, latest first */
    char job[PETSC_MAX_PATH_LEN + 300];
    PetscCall(PetscSNPrintf(job, sizeof(job), "%s%s%s", d->rs_dir, d->rs_dir[0] ? "/" : "", jobname));
    ListPoints(job, &pts, &np);
    SortPoints(pts, np, PETSC_TRUE);
  }
  if (!d->rs_oldjob) {
    PetscCallMPI(MPI_Bcast(&np, 1, MPIU_INT, 0, d->comm));
    if (rank) pts = malloc(sizeof(*pts) * (np ? np : 1));
    if (np) PetscCallMPI(MPI_Bcast(pts, (PetscMPIInt)(2 * np), MPIU_INT, 0, d->comm));
  }
  /* the first sound one is taken, the later ones passed over named */
  for (PetscInt k = 0; k < np && !found; k++) {
    char why[300] = "";
    int  st       = 0;
    if (d->rs_oldjob) PetscCall(JobPointPath(m->restart_read_job, pts[k][0], pts[k][1], d->rs_point, sizeof(d->rs_point)));
    else PetscCall(PointPath(d, pts[k][0], pts[k][1], d->rs_point, sizeof(d->rs_point)));
    PetscCall(CheckPoint(d, &ex, &st, why, sizeof(why), &nh_file));
    if (st == 1) found = 1;
    else if (st < 0 || d->rs_oldjob) { /* the point a restart deck names cannot be passed over for another */
      snprintf(msg, sizeof(msg), "%srestart point %s %s %s", where, d->rs_point, st < 0 ? "was" : "is not usable:", why);
      found = -1;
    } else PetscCall(PetscPrintf(d->comm, "thermoslide: warning: restart point %s is not used: %s\n", d->rs_point, why));
  }
  free(pts);
  if (!found) snprintf(msg, sizeof(msg), "-tsl_restart: no valid restart point of job %s in %s", jobname, d->rs_dir[0] ? d->rs_dir : ".");
  PetscCheck(found == 1, d->comm, PETSC_ERR_FILE_OPEN, "%s", msg);
  PetscCall(LoadHeader(d, nh_file));
  PetscCheck(d->rs_loop.step >= 0 && d->rs_loop.step < m->nstep && (m->steps[d->rs_loop.step].explicit_dynamics ? d->rs_nextra > 0 : d->rs_nextra == 0), d->comm,
             PETSC_ERR_FILE_UNEXPECTED, "%srestart point %s names step %" PetscInt_FMT ", which is of another procedure in this deck", where, d->rs_point,
             d->rs_loop.step + 1);
  PetscCheck(!d->rs_oldjob || (d->rs_loop.step + 1 == m->restart_read_step && d->rs_loop.inc == m->restart_read_inc), d->comm, PETSC_ERR_FILE_UNEXPECTED,
             "%srestart point %s holds step %" PetscInt_FMT " increment %" PetscInt_FMT ", not the one its name says", where, d->rs_point, d->rs_loop.step + 1,
             d->rs_loop.inc);
  /* the earlier run's output, which this run's extends */
  {
    int err = 0;
    if (!rank)
      err = d->rs_oldjob ? FindOutput(odir, ojob, PETSC_TRUE, d->rs_run_id, d->rs_src_h5, d->rs_src_csv, sizeof(d->rs_src_h5))
                         : FindOutput(d->rs_dir, d->rs_job, PETSC_FALSE, d->rs_run_id, d->rs_src_h5, d->rs_src_csv, sizeof(d->rs_src_h5));
    PetscCallMPI(MPI_Bcast(&err, 1, MPI_INT, 0, d->comm));
    PetscCheck(err >= 0, d->comm, PETSC_ERR_FILE_OPEN,
               "%srestart point %s: the output of the run that wrote it (%s.h5, .h5.part, .failed.h5 or .interrupted.h5 in %s, run %llx) is not there or not readable",
               where, d->rs_point, d->rs_oldjob ? ojob : jobname, d->rs_oldjob ? odir : (d->rs_dir[0] ? d->rs_dir : "."),
               (unsigned long long)d->rs_run_id);
    PetscCheck(!err, d->comm, PETSC_ERR_FILE_WRITE, "restart: cannot move the interrupted run's output aside: %s", strerror(err));
    PetscCallMPI(MPI_Bcast(d->rs_src_h5, sizeof(d->rs_src_h5), MPI_CHAR, 0, d->comm));
    PetscCallMPI(MPI_Bcast(d->rs_src_csv, sizeof(d->rs_src_csv), MPI_CHAR, 0, d->comm));
  }
  PetscCall(PetscPrintf(d->comm, "thermoslide: continuing from restart point %s: step %" PetscInt_FMT " increment %" PetscInt_FMT ", step time %g (%" PetscInt_FMT " frames and %" PetscInt_FMT " history rows of %s kept)\n",
                        d->rs_point, d->rs_loop.step + 1, d->rs_loop.inc, (double)d->rs_loop.t, d->rs_nframe, d->rs_nrow, d->rs_src_h5));
  PetscCall(SayPortable(d));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Another rank count: the scatter from a point's vector as this run reads it (PETSc's split of the file's node
 * blocks) to this run's layout, found through the natural index of each block (natnode) */
static PetscErrorCode NaturalMap(Driver *d, PetscViewer vw)
{
  const TslModel *m;
  Vec             X, nv;
  PetscInt        bs, N, ns = PETSC_DECIDE, nn, s0, nown, bad = 0, *from, *to;
  int64_t        *akey, *qkey;
  PetscReal      *aval, *qval;
  PetscBool      *found;
  IS              isf, ist;

  PetscFunctionBeginUser;
  if (d->rs_map) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(TslProblemGetModel(d->prob, &m));
  PetscCall(TslProblemGetSolution(d->prob, &X));
  PetscCall(VecGetBlockSize(X, &bs));
  PetscCall(VecGetSize(X, &N));
  PetscCall(VecGetLocalSize(X, &nown));
  nn = N / bs, nown /= bs;
  PetscCall(PetscSplitOwnership(d->comm, &ns, &nn));
  PetscCall(LocalVec(d->comm, ns, "natnode", &nv));
  PetscCall(VecLoad(nv, vw));
  PetscCall(VecGetOwnershipRange(nv, &s0, NULL));
  PetscCall(PetscMalloc6(nown + 1, &akey, nown + 1, &aval, ns + 1, &qkey, ns + 1, &qval, ns + 1, &found, 2 * (ns * bs + 1), &from));
  to = from + ns * bs + 1;
  for (PetscInt l = 0; l < nown; l++) akey[l] = m->node_nat[l], aval[l] = (PetscReal)m->node_gnum[l];
  {
    const PetscScalar *a;
    PetscCall(VecGetArrayRead(nv, &a));
    for (PetscInt i = 0; i < ns; i++) qkey[i] = (int64_t)PetscRealPart(a[i]);
    PetscCall(VecRestoreArrayRead(nv, &a));
  }
  PetscCall(TslRendezvous(d->comm, 1, 1, nown, akey, aval, ns, qkey, qval, found));
  for (PetscInt i = 0; i < ns; i++) {
    if (!found[i]) bad++;
    for (PetscInt c = 0; c < bs; c++) from[i * bs + c] = (s0 + i) * bs + c, to[i * bs + c] = found[i] ? (PetscInt)qval[i] * bs + c : -1;
  }
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &bad, 1, MPIU_INT, MPI_SUM, d->comm));
  PetscCheck(!bad, d->comm, PETSC_ERR_FILE_UNEXPECTED, "restart point %s: %" PetscInt_FMT " of its nodes are not this model's", d->rs_point, bad);
  PetscCall(ISCreateGeneral(d->comm, ns * bs, from, PETSC_COPY_VALUES, &isf));
  PetscCall(ISCreateGeneral(d->comm, ns * bs, to, PETSC_COPY_VALUES, &ist));
  PetscCall(VecCreate(d->comm, &d->rs_fvec));
  PetscCall(VecSetSizes(d->rs_fvec, ns * bs, PETSC_DETERMINE));
  PetscCall(VecSetBlockSize(d->rs_fvec, bs));
  PetscCall(VecSetType(d->rs_fvec, VECMPI));
  PetscCall(VecScatterCreate(d->rs_fvec, isf, X, ist, &d->rs_map));
  PetscCall(ISDestroy(&isf));
  PetscCall(ISDestroy(&ist));
  PetscCall(PetscFree6(akey, aval, qkey, qval, found, from));
  PetscCall(VecDestroy(&nv));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Vector name of the point into v: as written (the same rank count) or through the natural map */
static PetscErrorCode LoadVector(Driver *d, PetscViewer vw, const char *name, Vec v)
{
  Vec f;

  PetscFunctionBeginUser;
  if (!d->rs_portable) {
    PetscCall(LoadNamed(v, name, vw));
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  PetscCall(NaturalMap(d, vw));
  PetscCall(VecDuplicate(d->rs_fvec, &f));
  PetscCall(PetscObjectSetName((PetscObject)f, name));
  PetscCall(VecLoad(f, vw));
  PetscCall(VecScatterBegin(d->rs_map, f, v, INSERT_VALUES, SCATTER_FORWARD));
  PetscCall(VecScatterEnd(d->rs_map, f, v, INSERT_VALUES, SCATTER_FORWARD));
  PetscCall(VecDestroy(&f));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The point's state records, this rank's share of them, as the answers of FetchBlobs */
typedef struct {
  MPI_Comm   comm;
  PetscInt   na;
  int64_t   *akey;
  PetscReal *aval;
} PointBlobs;

static PetscErrorCode FetchBlobs(void *ctx, PetscInt n, const int64_t key[], const PetscInt len[], PetscReal val[], PetscBool found[])
{
  PointBlobs *pb = ctx;
  PetscInt    nq = 0, q = 0, off = 0;
  int64_t    *qkey;
  PetscReal  *qval;
  PetscBool  *qf;

  PetscFunctionBeginUser;
  for (PetscInt i = 0; i < n; i++) nq += BlobChunks(len[i]);
  PetscCall(PetscMalloc3(nq * BLOB_KL + 1, &qkey, nq * BLOB_W + 1, &qval, nq + 1, &qf));
  for (PetscInt i = 0; i < n; i++)
    for (PetscInt c = 0; c < BlobChunks(len[i]); c++, q++) {
      for (PetscInt k = 0; k < TSL_BLOB_KEY; k++) qkey[q * BLOB_KL + k] = key[TSL_BLOB_KEY * i + k];
      qkey[q * BLOB_KL + TSL_BLOB_KEY] = c;
    }
  PetscCall(TslRendezvous(pb->comm, BLOB_KL, BLOB_W, pb->na, pb->akey, pb->aval, nq, qkey, qval, qf));
  q = 0;
  for (PetscInt i = 0; i < n; off += len[i++]) {
    found[i] = PETSC_TRUE;
    for (PetscInt c = 0; c < BlobChunks(len[i]); c++, q++) {
      found[i] = (PetscBool)(found[i] && qf[q]);
      for (PetscInt j = 0; j < BLOB_W && c * BLOB_W + j < len[i]; j++) val[off + c * BLOB_W + j] = qval[q * BLOB_W + j];
    }
  }
  PetscCall(PetscFree3(qkey, qval, qf));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Another rank count: this rank's share of the point's records into pb (PetscFree2(pb->akey, pb->aval)) */
static PetscErrorCode LoadBlobs(Driver *d, PetscViewer vw, PointBlobs *pb_)
{
  PointBlobs         pb = {d->comm, PETSC_DECIDE, NULL, NULL};
  PetscInt           nrec = d->rs_nblob;
  Vec                bv;
  const PetscScalar *a;

  PetscFunctionBeginUser;
  PetscCall(PetscSplitOwnership(d->comm, &pb.na, &nrec));
  PetscCall(LocalVec(d->comm, pb.na * BLOB_REC, "blobs", &bv));
  PetscCall(VecLoad(bv, vw));
  PetscCall(PetscMalloc2(pb.na * BLOB_KL + 1, &pb.akey, pb.na * BLOB_W + 1, &pb.aval));
  PetscCall(VecGetArrayRead(bv, &a));
  for (PetscInt r = 0; r < pb.na; r++) {
    for (PetscInt k = 0; k < BLOB_KL; k++) pb.akey[r * BLOB_KL + k] = (int64_t)PetscRealPart(a[r * BLOB_REC + k]);
    for (PetscInt j = 0; j < BLOB_W; j++) pb.aval[r * BLOB_W + j] = PetscRealPart(a[r * BLOB_REC + BLOB_KL + j]);
  }
  PetscCall(VecRestoreArrayRead(bv, &a));
  PetscCall(VecDestroy(&bv));
  *pb_ = pb;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Another rank count: the state from the point's records (the solution already in place) */
static PetscErrorCode LoadState(Driver *d, PetscViewer vw)
{
  PointBlobs pb;

  PetscFunctionBeginUser;
  PetscCall(LoadBlobs(d, vw, &pb));
  PetscCall(TslProblemStateFromBlobs(d->prob, FetchBlobs, &pb));
  PetscCall(PetscFree2(pb.akey, pb.aval));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Another rank count: an explicit step's reals from the point (its scalars' blob, its elements' records), into this
 * run's layout of them */
static PetscErrorCode LoadExtraNatural(Driver *d, PetscViewer vw, TslRestartExtra *e)
{
  const TslModel *m;
  const PetscInt  w = XelemWidth(e);
  PointBlobs      pb;
  PetscInt        len, ns = PETSC_DECIDE, nel, missing = 0;
  int64_t         key[TSL_BLOB_KEY], *akey, *qkey;
  PetscReal      *aval, *qval;
  PetscBool       found, *qf;
  Vec             xv;

  PetscFunctionBeginUser;
  PetscCall(TslProblemGetModel(d->prob, &m));
  PetscCheck(d->rs_xelem == w, d->comm, PETSC_ERR_FILE_UNEXPECTED,
             "restart point %s: its explicit step's element state has another size than this run's (another bulk viscosity set-up?)", d->rs_point);
  PetscCall(LoadBlobs(d, vw, &pb));
  ExtraScalars(e, key, &len, NULL);
  PetscCall(FetchBlobs(&pb, 1, key, &len, e->real, &found));
  PetscCall(PetscFree2(pb.akey, pb.aval));
  missing = !found;
  /* the elements' records in PETSc's split of the file, answered by element */
  nel = m->nelem_global;
  PetscCall(PetscSplitOwnership(d->comm, &ns, &nel));
  PetscCall(LocalVec(d->comm, ns * w, "xelem", &xv));
  PetscCall(VecLoad(xv, vw));
  PetscCall(PetscMalloc5(ns + 1, &akey, ns * (w - 1) + 1, &aval, m->nelem + 1, &qkey, m->nelem * (w - 1) + 1, &qval, m->nelem + 1, &qf));
  {
    const PetscScalar *a;
    PetscCall(VecGetArrayRead(xv, &a));
    for (PetscInt r = 0; r < ns; r++) {
      akey[r] = (int64_t)PetscRealPart(a[r * w]);
      for (PetscInt j = 1; j < w; j++) aval[r * (w - 1) + j - 1] = PetscRealPart(a[r * w + j]);
    }
    PetscCall(VecRestoreArrayRead(xv, &a));
  }
  PetscCall(VecDestroy(&xv));
  for (PetscInt el = 0; el < m->nelem; el++) qkey[el] = m->elem_nat[el];
  PetscCall(TslRendezvous(d->comm, 1, w - 1, ns, akey, aval, m->nelem, qkey, qval, qf));
  for (PetscInt el = 0; el < m->nelem; el++) {
    const PetscReal *v = &qval[el * (w - 1)];
    if (!qf[el]) {
      missing++;
      continue;
    }
    for (PetscInt j = 0; j < e->nearr; j++) e->real[e->nglobal + j * m->nelem + el] = v[j];
    if (e->lane && e->lane[el] >= 0) e->real[e->carried_off + e->lane[el]] = v[e->nearr];
  }
  PetscCall(PetscFree5(akey, aval, qkey, qval, qf));
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &missing, 1, MPIU_INT, MPI_SUM, d->comm));
  PetscCheck(!missing, d->comm, PETSC_ERR_FILE_UNEXPECTED, "restart point %s holds no explicit state for %" PetscInt_FMT " of this model's elements (or its scalars)", d->rs_point, missing);
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TslRestartCopyOutput(Driver *d)
{
  PetscFunctionBeginUser;
  if (!d->rs_resume) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(TslOutputCopyFrames(d->out, d->rs_src_h5, d->rs_run_id, d->rs_nframe));
  PetscCall(TslHistoryCopyRows(d->hist, d->rs_src_csv, d->rs_nrow));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TslRestartStepStartLoad(Driver *d, PetscInt s, Vec X)
{
  PetscViewer vw;
  char        name[32];

  PetscFunctionBeginUser;
  if (!d->rs_xstart[s]) PetscCall(VecDuplicate(X, &d->rs_xstart[s]));
  PetscCall(PetscSNPrintf(name, sizeof(name), "start_%" PetscInt_FMT, s));
  PetscCall(PetscViewerHDF5Open(d->comm, d->rs_point, FILE_MODE_READ, &vw));
  PetscCall(LoadVector(d, vw, name, d->rs_xstart[s]));
  PetscCall(PetscViewerDestroy(&vw));
  PetscCall(VecCopy(d->rs_xstart[s], X));
  PetscCall(TslProblemSetTime(d->prob, d->rs_tstart[2 * s + 1], 0, d->rs_tstart[2 * s]));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TslRestartStepStart(Driver *d, PetscInt s, PetscReal *total_time)
{
  Vec X;

  PetscFunctionBeginUser;
  PetscCall(TslProblemGetSolution(d->prob, &X));
  if (!d->rs_xstart[s]) PetscCall(VecDuplicate(X, &d->rs_xstart[s]));
  if (d->rs_resume && s <= d->rs_loop.step) {
    /* the continuation: the step starts from the state the original run started it from */
    PetscCall(TslRestartStepStartLoad(d, s, X));
    *total_time = d->rs_tstart[2 * s];
  } else {
    PetscCall(VecCopy(X, d->rs_xstart[s]));
    d->rs_tstart[2 * s]     = *total_time;
    d->rs_tstart[2 * s + 1] = TslProblemGetStepTime(d->prob);
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TslRestartLoad(Driver *d, TslRestartLoop *loop)
{
  PetscViewer vw;
  Vec         X;

  PetscFunctionBeginUser;
  PetscCall(TslProblemGetSolution(d->prob, &X));
  /* the layout and the checksums were verified when the point was chosen (TslRestartSetUp) */
  PetscCall(PetscViewerHDF5Open(d->comm, d->rs_point, FILE_MODE_READ, &vw));
  PetscCall(LoadVector(d, vw, "X", X));
  if (d->rs_loop.h_prev > 0) {
    if (!d->Xprev) PetscCall(VecDuplicate(X, &d->Xprev));
    PetscCall(LoadVector(d, vw, "Xprev", d->Xprev));
  }
  PetscCall(TslGhostUpdate(X, INSERT_VALUES, SCATTER_FORWARD));
  PetscCall(LoadState(d, vw)); /* after the solution: the 3D nodal normals are computed from it */
  PetscCall(PetscViewerDestroy(&vw));
  RestoreSums(d, d->rs_sums);
  *loop       = d->rs_loop;
  d->rs_resume = PETSC_FALSE; /* from here on the run is an ordinary one */
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TslRestartLoadExtra(Driver *d, TslRestartExtra *extra)
{
  PetscViewer vw;

  PetscFunctionBeginUser;
  PetscCheck(d->rs_nextra == extra->nvec, d->comm, PETSC_ERR_FILE_UNEXPECTED,
             "restart point %s holds %" PetscInt_FMT " vectors of the explicit step's state, this run's step has %" PetscInt_FMT " (another contact set-up?)", d->rs_point,
             d->rs_nextra, extra->nvec);
  PetscCall(PetscViewerHDF5Open(d->comm, d->rs_point, FILE_MODE_READ, &vw));
  for (PetscInt j = 0; j < extra->nvec; j++) {
    char name[32];
    ExtraName(j, name, sizeof(name));
    PetscCall(LoadVector(d, vw, name, extra->vec[j]));
  }
  PetscCall(LoadExtraNatural(d, vw, extra));
  PetscCall(PetscViewerDestroy(&vw));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TslRestartPostOutput(Driver *d)
{
  const TslModel *m;
  PetscMPIInt     rank;
  PetscInt        np = 0, (*pts)[2] = NULL, done_steps = 0;
  Expect          ex;
  char            where[PETSC_MAX_PATH_LEN + 64], loc[PETSC_MAX_PATH_LEN];
  Vec             X, Xold;

  PetscFunctionBeginUser;
  PetscCall(TslProblemGetModel(d->prob, &m));
  PetscCallMPI(MPI_Comm_rank(d->comm, &rank));
  PetscCall(TslProblemGetSolution(d->prob, &X));
  PetscCall(TslProblemGetOldSolution(d->prob, &Xold));
  PetscCall(PetscSNPrintf(where, sizeof(where), "%s: *POST OUTPUT: ", TslLocString(m, m->restart_read_loc, loc, sizeof(loc))));
  if (m->post_output == 2) {
    if (!rank) ListPoints(m->restart_read_job, &pts, &np);
    PetscCallMPI(MPI_Bcast(&np, 1, MPIU_INT, 0, d->comm));
    if (rank) pts = malloc(sizeof(*pts) * (np ? np : 1));
    if (np) PetscCallMPI(MPI_Bcast(pts, (PetscMPIInt)(2 * np), MPIU_INT, 0, d->comm));
    PetscCheck(np, d->comm, PETSC_ERR_FILE_OPEN, "%sthe old job %s has no restart points", where, m->restart_read_job);
  } else {
    np  = m->npost;
    pts = malloc(sizeof(*pts) * np);
    for (PetscInt k = 0; k < np; k++) pts[k][0] = m->post[2 * k], pts[k][1] = m->post[2 * k + 1];
  }
  SortPoints(pts, np, PETSC_FALSE); /* the frames in time order */
  PetscCall(ExpectFor(d, 0, &ex));
  PetscCall(PetscPrintf(d->comm, "thermoslide: POST OUTPUT of %" PetscInt_FMT " restart points of %s\n", np, m->restart_read_job));
  for (PetscInt k = 0; k < np; k++) {
    char      why[300] = "";
    int       st       = 0;
    PetscInt  nh, s;
    PetscReal h;
    PetscCall(JobPointPath(m->restart_read_job, pts[k][0], pts[k][1], d->rs_point, sizeof(d->rs_point)));
    PetscCall(CheckPoint(d, &ex, &st, why, sizeof(why), &nh));
    if (st != 1) free(pts);
    PetscCheck(st == 1, d->comm, PETSC_ERR_FILE_UNEXPECTED, "%srestart point %s %s %s", where, d->rs_point, st < 0 ? "was" : "is not usable:", why);
    PetscCall(LoadHeader(d, nh));
    if (!k) PetscCall(SayPortable(d));
    s = d->rs_loop.step;
    /* the steps up to the point's: each one's loads and boundary conditions from the state it started with */
    for (; done_steps <= s; done_steps++) {
      PetscCall(TslRestartStepStartLoad(d, done_steps, X));
      PetscCall(TslProblemSetStep(d->prob, done_steps));
    }
    d->rs_resume = PETSC_TRUE;
    PetscCall(TslRestartLoad(d, &d->rs_loop)); /* the state, the solution (and the one before it), the sums */
    if (d->rs_loop.h_prev > 0) PetscCall(VecCopy(d->Xprev, Xold));
    else PetscCall(VecCopy(X, Xold));
    h = d->done_dt;
    PetscCall(TslProblemSetTime(d->prob, d->rs_ptime, h, d->done_time));
    PetscCall(TslProblemSetCapacityRate(d->prob, m->steps[s].steady || !(h > 0) ? 0.0 : 1.0 / h));
    if (m->npost_out) { /* the POST OUTPUT deck's own requests, in place of the step's */
      TslStep own = m->steps[s];
      own.out = m->post_out, own.nout = m->npost_out;
      PetscCall(TslFramesSetRequests(d, &own));
    } else PetscCall(TslFramesSetRequests(d, &m->steps[s]));
    {
      TslHeatBalance hb;
      PetscCall(TslProblemHeatBalance(d->prob, &hb)); /* the contact outputs at that state */
    }
    PetscCall(TslFramesWrite(d, s + 1, d->rs_loop.inc, d->done_time));
    PetscCall(PetscPrintf(d->comm, "  frame of step %" PetscInt_FMT " increment %" PetscInt_FMT " (step time %g) from %s\n", s + 1, d->rs_loop.inc, (double)d->rs_loop.t,
                          d->rs_point));
  }
  free(pts);
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TslRestartEndStep(Driver *d, PetscInt s, PetscReal *t, PetscReal period)
{
  PetscFunctionBeginUser;
  if (!d->rs_end_step) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(PetscPrintf(d->comm, "  step %" PetscInt_FMT " ends at the restart point, step time %g of %g (*RESTART, READ, END STEP)\n", s + 1, (double)*t, (double)period));
  *t             = period;
  d->rs_end_step = PETSC_FALSE;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TslRestartFinish(Driver *d, PetscBool completed)
{
  const TslModel *m;

  PetscFunctionBeginUser;
  PetscCall(TslProblemGetModel(d->prob, &m));
  if (d->rs_count)
    PetscCall(PetscPrintf(d->comm, "thermoslide: %" PetscInt_FMT " restart points written, %.2f s in all (%.1f MB each)\n", d->rs_count, d->rs_seconds,
                          d->rs_bytes / 1048576.0));
  if (completed && !d->rs_oldjob && d->rs_src_h5[0] && strstr(d->rs_src_h5, ".interrupted.h5")) {
    /* the interrupted run's frames are in this run's output now */
    PetscMPIInt rank;
    PetscCallMPI(MPI_Comm_rank(d->comm, &rank));
    if (!rank) (void)unlink(d->rs_src_h5), (void)unlink(d->rs_src_csv);
  }
  for (PetscInt s = 0; s < m->nstep; s++) PetscCall(VecDestroy(&d->rs_xstart[s]));
  PetscCall(VecScatterDestroy(&d->rs_map));
  PetscCall(VecDestroy(&d->rs_fvec));
  PetscCall(PetscFree2(d->rs_xstart, d->rs_tstart));
  PetscFunctionReturn(PETSC_SUCCESS);
}
