/* Field output: one parallel HDF5 file written collectively through MPI-IO, in natural order, and the
 * XDMF text that lets ParaView/VisIt/meshio read it as a time series. See output.h for the layout. */
#include "output_impl.h"
#include <errno.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>
#include <time.h>
#include <math.h>

PetscErrorCode TslOutputPath(MPI_Comm comm, const char *dir, const char *name, const char *suffix, char buf[], size_t len)
{
  int n;

  PetscFunctionBeginUser;
  n = snprintf(buf, len, "%s%s%s%s", dir ? dir : "", dir && dir[0] ? "/" : "", name, suffix);
  PetscCheck(n >= 0 && (size_t)n < len, comm, PETSC_ERR_ARG_SIZ, "Output path %s/%s%s is too long", dir, name, suffix);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Names end up in HDF5 paths ("/" separates groups), in "file.h5:/path" references (":" splits them)
 * and in XML attributes; reject what would break any of them rather than escaping it three ways. */
PetscErrorCode TslOutputCheckName(MPI_Comm comm, const char *kind, const char *name, const char *forbidden)
{
  size_t len;

  PetscFunctionBeginUser;
  PetscCheck(name, comm, PETSC_ERR_ARG_NULL, "%s name is NULL", kind);
  len = strlen(name);
  PetscCheck(len > 0 && len < TSL_NAME_LEN, comm, PETSC_ERR_ARG_WRONG, "%s name \"%s\" must have 1 to %d characters", kind, name, TSL_NAME_LEN - 1);
  PetscCheck(strcmp(name, ".") && strcmp(name, ".."), comm, PETSC_ERR_ARG_WRONG, "%s name \"%s\" is not allowed", kind, name);
  for (size_t i = 0; i < len; i++)
    PetscCheck(!strchr(forbidden, name[i]) && (unsigned char)name[i] >= 32, comm, PETSC_ERR_ARG_WRONG,
               "%s name \"%s\" contains a forbidden character (any of \"%s\" or a control character)", kind, name, forbidden);
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TslH5Agree(MPI_Comm comm, PetscBool failed, const char *call, const char *path)
{
  PetscBool any;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Allreduce(&failed, &any, 1, MPIU_BOOL, MPI_LOR, comm));
  if (failed) PetscCall(PetscInfo(NULL, "HDF5 call failed: %s\n", call));
  PetscCheck(!any, comm, PETSC_ERR_FILE_WRITE, "writing %s failed (HDF5 error; -info names the call)", path);
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TslOutputFinalPath(MPI_Comm comm, const char *dir, const char *job, const char *tag, const char *suffix, char buf[], size_t len)
{
  char name[TSL_NAME_LEN + 32];

  PetscFunctionBeginUser;
  PetscCall(PetscSNPrintf(name, sizeof(name), "%s%s%s", job, tag ? "." : "", tag ? tag : ""));
  PetscCall(TslOutputPath(comm, dir, name, suffix, buf, len));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TslOutputCheckRoot(MPI_Comm comm, int err, const char *action, const char *path)
{
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Bcast(&err, 1, MPI_INT, 0, comm));
  PetscCheck(!err, comm, PETSC_ERR_FILE_WRITE, "Cannot %s %s: %s", action, path, strerror(err));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode WriteAttribute(TslOutput out, hid_t loc, const char *name, hid_t filetype, hid_t memtype, const void *val);

PetscErrorCode TslOutputCreate(MPI_Comm comm, const char *dir, const char *jobname, TslOutput *out)
{
  TslOutput   o;
  hid_t       fapl, grp;
  H5E_auto2_t efunc;
  void       *edata;

  PetscFunctionBeginUser;
  PetscCheck(out, comm, PETSC_ERR_ARG_NULL, "TslOutputCreate(): out is NULL");
  *out = NULL;
  /* ":" would split the "file.h5:/path" references of the .xmf; XML-special characters are escaped there */
  PetscCall(TslOutputCheckName(comm, "Job", jobname, "/:"));
  PetscCall(PetscNew(&o));
  o->comm        = comm;
  o->file        = H5I_INVALID_HID;
  o->dxpl        = H5I_INVALID_HID;
  o->frame_group   = H5I_INVALID_HID;
  o->sync_interval = 1.0;
  o->last_sync     = -1e300;
  PetscCallMPI(MPI_Comm_rank(comm, &o->rank));
  PetscCall(PetscStrncpy(o->job, jobname, sizeof(o->job)));
  PetscCall(PetscStrncpy(o->dir, dir ? dir : "", sizeof(o->dir)));
  PetscCall(TslInjectSetFromOptions(comm, &o->inject));
  PetscCall(TslOutputPath(comm, NULL, jobname, ".h5", o->h5_base, sizeof(o->h5_base)));
  PetscCall(TslOutputPath(comm, dir, jobname, ".h5.part", o->h5_part, sizeof(o->h5_part)));
  PetscCall(TslOutputPath(comm, dir, jobname, ".h5", o->h5_final, sizeof(o->h5_final)));
  PetscCall(TslOutputPath(comm, dir, jobname, ".xmf.part", o->xmf_part, sizeof(o->xmf_part)));
  PetscCall(TslOutputPath(comm, dir, jobname, ".xmf.part.tmp", o->xmf_tmp, sizeof(o->xmf_tmp)));
  PetscCall(TslOutputPath(comm, dir, jobname, ".xmf", o->xmf_final, sizeof(o->xmf_final)));
  *out = o; /* from here on Destroy cleans up whatever exists */

  TslH5Check(comm, fapl = H5Pcreate(H5P_FILE_ACCESS), o->h5_part);
  TslH5Check(comm, H5Pset_fapl_mpio(fapl, comm, MPI_INFO_NULL), o->h5_part);
  /* Collective metadata avoids every rank reading the same metadata block at scale. */
  TslH5Check(comm, H5Pset_all_coll_metadata_ops(fapl, 1), o->h5_part);
  /* closing the file closes whatever a failed write left open */
  TslH5Check(comm, H5Pset_fclose_degree(fapl, H5F_CLOSE_STRONG), o->h5_part);
  TslH5Check(comm, H5Pset_coll_metadata_write(fapl, 1), o->h5_part);
  /* A missing or read-only directory is a user error: report it as such, without HDF5's stack dump. */
  TslH5Check(comm, H5Eget_auto2(H5E_DEFAULT, &efunc, &edata), o->h5_part);
  TslH5Check(comm, H5Eset_auto2(H5E_DEFAULT, NULL, NULL), o->h5_part);
  o->file = H5Fcreate(o->h5_part, H5F_ACC_TRUNC, H5P_DEFAULT, fapl);
  TslH5Check(comm, H5Eset_auto2(H5E_DEFAULT, efunc, edata), o->h5_part);
  TslH5Check(comm, H5Pclose(fapl), o->h5_part);
  if (o->file < 0) {
    char path[PETSC_MAX_PATH_LEN];
    PetscCall(PetscStrncpy(path, o->h5_part, sizeof(path)));
    PetscCall(PetscFree(o));
    *out = NULL;
    SETERRQ(comm, PETSC_ERR_FILE_OPEN, "Cannot create output file %s (does the directory exist and is it writable?)", path);
  }

  TslH5Check(comm, o->dxpl = H5Pcreate(H5P_DATASET_XFER), o->h5_part);
  TslH5Check(comm, H5Pset_dxpl_mpio(o->dxpl, H5FD_MPIO_COLLECTIVE), o->h5_part);
  {
    /* this run's identity, so that a continuation (-tsl_restart) copies the frames of the run its restart point
     * belongs to and no other file of the same name */
    uint64_t id = 0;
    if (o->rank == 0) id = ((uint64_t)time(NULL) << 20) ^ ((uint64_t)getpid() << 1) ^ (uint64_t)(1e6 * fmod(MPI_Wtime(), 1.0));
    PetscCallMPI(MPI_Bcast(&id, 1, MPI_UINT64_T, 0, comm));
    o->run_id = id;
    PetscCall(WriteAttribute(o, o->file, "run_id", H5T_STD_U64LE, H5T_NATIVE_UINT64, &id));
  }
  TslH5Check(comm, grp = H5Gcreate2(o->file, "/mesh", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), o->h5_part);
  TslH5Check(comm, H5Gclose(grp), o->h5_part);
  TslH5Check(comm, grp = H5Gcreate2(o->file, "/frames", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), o->h5_part);
  TslH5Check(comm, H5Gclose(grp), o->h5_part);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Creates dataset name under loc with global shape [gdim0] (dim1 == 0) or [gdim0][dim1] and writes
 * rows [start, start+count) from buf collectively. Every rank calls it, possibly with count 0. */
static PetscErrorCode WriteRows(TslOutput out, hid_t loc, const char *name, hid_t filetype, hid_t memtype, hsize_t gdim0, hsize_t dim1, hsize_t start,
                                hsize_t count, const void *buf)
{
  const int rank     = dim1 ? 2 : 1;
  hsize_t   gdims[2] = {gdim0, dim1}, mdims[2] = {count ? count : 1, dim1}, off[2] = {start, 0}, cnt[2] = {count, dim1};
  hid_t     fspace, mspace, dset;
  double    dummy = 0; /* HDF5 rejects a NULL buffer even for an empty selection */

  PetscFunctionBeginUser;
  TslH5Check(out->comm, fspace = H5Screate_simple(rank, gdims, NULL), out->h5_part);
  TslH5Check(out->comm, dset = H5Dcreate2(loc, name, filetype, fspace, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), out->h5_part);
  /* testing aid: a failure of a rank-local call on one rank (-tsl_debug_fail_kind output) */
  TslH5Check(out->comm, mspace = TslInjectNow(&out->inject, TSL_INJECT_OUTPUT, out->cur_step) ? H5I_INVALID_HID : H5Screate_simple(rank, mdims, NULL),
             out->h5_part);
  /* one agreement either way: every rank must make the same collective calls, whatever its count */
  if (count)
    TslH5Check(out->comm, H5Sselect_hyperslab(fspace, H5S_SELECT_SET, off, NULL, cnt, NULL), out->h5_part);
  else
    TslH5Check(out->comm, H5Sselect_none(fspace) < 0 || H5Sselect_none(mspace) < 0 ? -1 : 0, out->h5_part);
  TslH5Check(out->comm, H5Dwrite(dset, memtype, mspace, fspace, out->dxpl, count ? buf : (const void *)&dummy), out->h5_part);
  TslH5Check(out->comm, H5Sclose(mspace), out->h5_part);
  TslH5Check(out->comm, H5Sclose(fspace), out->h5_part);
  TslH5Check(out->comm, H5Dclose(dset), out->h5_part);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Moves one int per item to the natural blocks and writes it as int64. */
static PetscErrorCode WriteIds(TslOutput out, const TslRedist *rd, const char *name, const PetscInt ids[])
{
  int64_t *loc, *blk;

  PetscFunctionBeginUser;
  PetscCall(PetscMalloc2(rd->nlocal, &loc, rd->nblock, &blk));
  for (PetscInt k = 0; k < rd->nlocal; k++) loc[k] = ids[k];
  PetscCall(TslRedistMove(out->comm, rd, sizeof(int64_t), loc, blk));
  PetscCall(WriteRows(out, out->file, name, H5T_STD_I64LE, H5T_NATIVE_INT64, (hsize_t)rd->nglobal, 0, (hsize_t)rd->bstart, (hsize_t)rd->nblock, blk));
  PetscCall(PetscFree2(loc, blk));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* /mesh/connectivity, [M][n] natural node indices, when every element is of one XDMF cell type with n nodes (on every
 * rank: a rank without elements agrees with any type): the .xmf then gives that type's own topology, which readers
 * without the quadratic Mixed records take (meshio). blkpad holds this rank's block of the padded records
 * [type, n0, ...] (maxlen each, natural order). */
static PetscErrorCode WriteConnectivity(TslOutput out, PetscInt nelem, const PetscInt xdmf_type[], PetscInt maxlen, const int64_t blkpad[])
{
  const TslRedist *rd = &out->elems;
  PetscInt         range[2] = {PETSC_MAX_INT, PETSC_MAX_INT}, n; /* min type, -max type */
  int64_t         *conn;

  PetscFunctionBeginUser;
  out->cell_name = NULL;
  for (PetscInt e = 0; e < nelem; e++) range[0] = PetscMin(range[0], xdmf_type[e]), range[1] = PetscMin(range[1], -xdmf_type[e]);
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, range, 2, MPIU_INT, MPI_MIN, out->comm));
  if (out->nelem_global == 0 || range[0] != -range[1]) PetscFunctionReturn(PETSC_SUCCESS);
  const PetscInt h = range[0] == 2 ? 2 : 1; /* a Polyline record: type, count, nodes */
  if (!TslXdmfTopologyName(range[0], &n) || n != maxlen - h) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(PetscMalloc1(rd->nblock * n, &conn));
  for (PetscInt k = 0; k < rd->nblock; k++)
    for (PetscInt j = 0; j < n; j++) conn[k * n + j] = blkpad[k * maxlen + h + j];
  PetscCall(WriteRows(out, out->file, "/mesh/connectivity", H5T_STD_I64LE, H5T_NATIVE_INT64, (hsize_t)rd->nglobal, (hsize_t)n, (hsize_t)rd->bstart,
                      (hsize_t)rd->nblock, conn));
  PetscCall(PetscFree(conn));
  out->cell_name  = TslXdmfTopologyName(range[0], &out->cell_nodes);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* /mesh/topology: XDMF Mixed records [type, n0, n1, ...] in natural element order (a Polyline, type 2, the heat-transfer
 * links DC1D2: [2, node count, n0, n1], as XDMF has it for that type). Records differ in
 * length, so they travel padded to the longest one; each block then packs its records and finds its
 * offset in the file by an exclusive scan of the block lengths. */
static PetscErrorCode WriteTopology(TslOutput out, PetscInt nelem, const PetscInt xdmf_type[], const PetscInt ptr[], const PetscInt conn[])
{
  const TslRedist *rd     = &out->elems;
  PetscInt         maxlen = 0, badnode = -1, anybad;
  int64_t         *pad, *blkpad, *rec, blklen = 0, offset = 0, total = 0;

  PetscFunctionBeginUser;
  for (PetscInt e = 0; e < nelem; e++) {
    maxlen = PetscMax(maxlen, 1 + (xdmf_type[e] == 2) + ptr[e + 1] - ptr[e]);
    for (PetscInt j = ptr[e]; j < ptr[e + 1]; j++)
      if (conn[j] < 0 || conn[j] >= out->nnode_global) badnode = conn[j];
    if (ptr[e + 1] <= ptr[e] || xdmf_type[e] <= 0) badnode = -2;
  }
  anybad = badnode == -1 ? 0 : 1;
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &anybad, 1, MPIU_INT, MPI_MAX, out->comm));
  PetscCheck(!anybad, out->comm, PETSC_ERR_ARG_OUTOFRANGE,
             "Element connectivity: empty element, bad cell type or node index outside [0, %" PetscInt_FMT ") (this rank: %" PetscInt_FMT
             ", -1 = fine, -2 = empty element or type)",
             out->nnode_global, badnode);
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &maxlen, 1, MPIU_INT, MPI_MAX, out->comm));
  if (maxlen == 0) maxlen = 1; /* no elements at all */

  PetscCall(PetscMalloc2(nelem * maxlen, &pad, rd->nblock * maxlen, &blkpad));
  for (PetscInt e = 0; e < nelem; e++) {
    int64_t *r = pad + e * maxlen;
    const PetscInt h = xdmf_type[e] == 2 ? 2 : 1; /* a Polyline's record gives its node count */
    r[0]             = xdmf_type[e];
    if (h == 2) r[1] = ptr[e + 1] - ptr[e];
    for (PetscInt j = ptr[e]; j < ptr[e + 1]; j++) r[h + j - ptr[e]] = conn[j];
    for (PetscInt j = h + ptr[e + 1] - ptr[e]; j < maxlen; j++) r[j] = -1;
  }
  /* The padding of -1 marks where a record ends; node indices are never negative. */
  PetscCall(TslRedistMove(out->comm, rd, maxlen * sizeof(int64_t), pad, blkpad));
  for (PetscInt k = 0; k < rd->nblock; k++) {
    PetscInt n = 1;
    while (n < maxlen && blkpad[k * maxlen + n] >= 0) n++;
    blklen += n;
  }
  PetscCall(PetscMalloc1(blklen, &rec));
  blklen = 0;
  for (PetscInt k = 0; k < rd->nblock; k++) {
    PetscInt n = 1;
    while (n < maxlen && blkpad[k * maxlen + n] >= 0) n++;
    for (PetscInt j = 0; j < n; j++) rec[blklen++] = blkpad[k * maxlen + j];
  }
  PetscCall(WriteConnectivity(out, nelem, xdmf_type, maxlen, blkpad));
  PetscCallMPI(MPI_Exscan(&blklen, &offset, 1, MPI_INT64_T, MPI_SUM, out->comm));
  if (out->rank == 0) offset = 0; /* MPI_Exscan leaves rank 0's result undefined */
  PetscCallMPI(MPI_Allreduce(&blklen, &total, 1, MPI_INT64_T, MPI_SUM, out->comm));
  out->topo_len = total;
  PetscCall(WriteRows(out, out->file, "/mesh/topology", H5T_STD_I64LE, H5T_NATIVE_INT64, (hsize_t)total, 0, (hsize_t)offset, (hsize_t)blklen, rec));
  PetscCall(PetscFree(rec));
  PetscCall(PetscFree2(pad, blkpad));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TslOutputSetMesh(TslOutput out, PetscInt nnode_global, PetscInt nnode, const PetscInt node_nat[], const PetscInt node_id[],
                                const PetscReal xyz[], PetscInt nelem_global, PetscInt nelem, const PetscInt elem_nat[], const PetscInt elem_id[],
                                const PetscInt xdmf_type[], const PetscInt ptr[], const PetscInt conn[])
{
  PetscReal *blkxyz;

  PetscFunctionBeginUser;
  PetscCheck(!out->mesh_set, out->comm, PETSC_ERR_ORDER, "TslOutputSetMesh() called twice");
  PetscCheck(!out->finalized, out->comm, PETSC_ERR_ORDER, "Output %s already finalized", out->h5_final);
  out->nnode_global = nnode_global;
  out->nelem_global = nelem_global;
  PetscCall(TslRedistSetUp(out->comm, nnode_global, nnode, node_nat, "Output nodes", &out->nodes));
  PetscCall(TslRedistSetUp(out->comm, nelem_global, nelem, elem_nat, "Output elements", &out->elems));

  PetscCall(PetscMalloc1(3 * out->nodes.nblock, &blkxyz));
  PetscCall(TslRedistMove(out->comm, &out->nodes, 3 * sizeof(PetscReal), xyz, blkxyz));
  PetscCall(WriteRows(out, out->file, "/mesh/coordinates", H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, (hsize_t)nnode_global, 3, (hsize_t)out->nodes.bstart,
                      (hsize_t)out->nodes.nblock, blkxyz));
  PetscCall(PetscFree(blkxyz));
  PetscCall(WriteIds(out, &out->nodes, "/mesh/node_ids", node_id));
  PetscCall(WriteIds(out, &out->elems, "/mesh/element_ids", elem_id));
  PetscCall(WriteTopology(out, nelem, xdmf_type, ptr, conn));
  out->mesh_set = PETSC_TRUE;
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode WriteAttribute(TslOutput out, hid_t loc, const char *name, hid_t filetype, hid_t memtype, const void *val)
{
  hid_t space, attr;

  PetscFunctionBeginUser;
  TslH5Check(out->comm, space = H5Screate(H5S_SCALAR), out->h5_part);
  TslH5Check(out->comm, attr = H5Acreate2(loc, name, filetype, space, H5P_DEFAULT, H5P_DEFAULT), out->h5_part);
  TslH5Check(out->comm, H5Awrite(attr, memtype, val), out->h5_part);
  TslH5Check(out->comm, H5Aclose(attr), out->h5_part);
  TslH5Check(out->comm, H5Sclose(space), out->h5_part);
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TslOutputBeginFrame(TslOutput out, PetscInt step, PetscInt increment, PetscReal time)
{
  TslOutputFrameInfo *f;
  char                gname[32];
  int64_t             istep = step, iinc = increment;
  double              t = time;

  PetscFunctionBeginUser;
  PetscCheck(out->mesh_set, out->comm, PETSC_ERR_ORDER, "TslOutputSetMesh() must come before the first frame");
  PetscCheck(!out->in_frame, out->comm, PETSC_ERR_ORDER, "TslOutputBeginFrame() while a frame is open");
  PetscCheck(!out->finalized, out->comm, PETSC_ERR_ORDER, "Output %s already finalized", out->h5_final);
  out->cur_step = step;
  if (out->nframe == out->maxframe) {
    TslOutputFrameInfo *more;
    PetscInt            newmax = PetscMax(8, 2 * out->maxframe);
    PetscCall(PetscCalloc1(newmax, &more));
    if (out->nframe) PetscCall(PetscArraycpy(more, out->frames, out->nframe));
    PetscCall(PetscFree(out->frames));
    out->frames   = more;
    out->maxframe = newmax;
  }
  f            = &out->frames[out->nframe];
  f->step      = step;
  f->increment = increment;
  f->time      = time;
  f->nfield    = 0;
  PetscCheck(out->nframe + 1 <= 999999, out->comm, PETSC_ERR_SUP, "More than 999999 output frames");
  snprintf(gname, sizeof(gname), "/frames/%06d", (int)(out->nframe + 1));
  TslH5Check(out->comm, out->frame_group = H5Gcreate2(out->file, gname, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), out->h5_part);
  PetscCall(WriteAttribute(out, out->frame_group, "time", H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, &t));
  PetscCall(WriteAttribute(out, out->frame_group, "step", H5T_STD_I64LE, H5T_NATIVE_INT64, &istep));
  PetscCall(WriteAttribute(out, out->frame_group, "increment", H5T_STD_I64LE, H5T_NATIVE_INT64, &iinc));
  out->nframe++;
  out->in_frame = PETSC_TRUE;
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode WriteField(TslOutput out, const char *name, PetscInt ncomp, const PetscReal vals[], const PetscReal block[], PetscBool on_cells)
{
  const TslRedist    *rd = on_cells ? &out->elems : &out->nodes;
  TslOutputFrameInfo *f;
  PetscReal          *blk;

  PetscFunctionBeginUser;
  PetscCall(TslOutputCheckName(out->comm, "Field", name, "/:\"<>&'"));
  PetscCheck(out->in_frame, out->comm, PETSC_ERR_ORDER, "Field %s given outside TslOutputBeginFrame/EndFrame", name);
  PetscCheck(ncomp >= 1, out->comm, PETSC_ERR_ARG_OUTOFRANGE, "Field %s: ncomp %" PetscInt_FMT " < 1", name, ncomp);
  f = &out->frames[out->nframe - 1];
  for (PetscInt i = 0; i < f->nfield; i++)
    PetscCheck(strcmp(f->fields[i].name, name), out->comm, PETSC_ERR_ARG_WRONG, "Field %s written twice in one frame", name);
  if (f->nfield == f->maxfield) {
    TslOutputFieldInfo *more;
    PetscInt            newmax = PetscMax(8, 2 * f->maxfield);
    PetscCall(PetscCalloc1(newmax, &more));
    if (f->nfield) PetscCall(PetscArraycpy(more, f->fields, f->nfield));
    PetscCall(PetscFree(f->fields));
    f->fields   = more;
    f->maxfield = newmax;
  }

  if (!block) {
    PetscCall(PetscMalloc1(ncomp * rd->nblock, &blk));
    PetscCall(TslRedistMove(out->comm, rd, ncomp * sizeof(PetscReal), vals, blk));
  } else blk = (PetscReal *)block; /* already this rank's natural block (TslOutputCopyFrames) */
  PetscCall(WriteRows(out, out->frame_group, name, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, (hsize_t)rd->nglobal, (hsize_t)ncomp, (hsize_t)rd->bstart,
                      (hsize_t)rd->nblock, blk));
  if (!block) PetscCall(PetscFree(blk));
  {
    /* where the values live, for a continuation that copies the frame (TslOutputCopyFrames) */
    hid_t   dset;
    int64_t cells = on_cells;
    TslH5Check(out->comm, dset = H5Dopen2(out->frame_group, name, H5P_DEFAULT), out->h5_part);
    PetscCall(WriteAttribute(out, dset, "cells", H5T_STD_I64LE, H5T_NATIVE_INT64, &cells));
    TslH5Check(out->comm, H5Dclose(dset), out->h5_part);
  }
  PetscCall(PetscStrncpy(f->fields[f->nfield].name, name, sizeof(f->fields[f->nfield].name)));
  f->fields[f->nfield].ncomp    = ncomp;
  f->fields[f->nfield].on_cells = on_cells;
  f->nfield++;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TslOutputNodeField(TslOutput out, const char *name, PetscInt ncomp, const PetscReal vals[])
{
  PetscFunctionBeginUser;
  PetscCall(WriteField(out, name, ncomp, vals, NULL, PETSC_FALSE));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TslOutputElementField(TslOutput out, const char *name, PetscInt ncomp, const PetscReal vals[])
{
  PetscFunctionBeginUser;
  PetscCall(WriteField(out, name, ncomp, vals, NULL, PETSC_TRUE));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The .xmf.part is rewritten whole into a scratch name and renamed over, so that a reader (or a
 * crash) never sees a half-written XML file. */
static PetscErrorCode RewriteXmf(TslOutput out)
{
  int err = 0;

  PetscFunctionBeginUser;
  if (out->rank == 0) {
    PetscCall(TslOutputWriteXmf(out, out->xmf_tmp, &err));
    if (!err && rename(out->xmf_tmp, out->xmf_part)) err = errno;
  }
  PetscCall(TslOutputCheckRoot(out->comm, err, "write", out->xmf_part));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TslOutputEndFrame(TslOutput out)
{
  PetscFunctionBeginUser;
  PetscCheck(out->in_frame, out->comm, PETSC_ERR_ORDER, "TslOutputEndFrame() without TslOutputBeginFrame()");
  TslH5Check(out->comm, H5Gclose(out->frame_group), out->h5_part);
  out->frame_group = H5I_INVALID_HID;
  out->in_frame    = PETSC_FALSE;
  {
    double now  = MPI_Wtime();
    int    sync = now - out->last_sync >= out->sync_interval;
    PetscCallMPI(MPI_Bcast(&sync, 1, MPI_INT, 0, out->comm));
    if (!sync) PetscFunctionReturn(PETSC_SUCCESS);
  }
  PetscCall(TslOutputSync(out));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TslOutputSync(TslOutput out)
{
  PetscFunctionBeginUser;
  if (out->in_frame || out->file < 0) PetscFunctionReturn(PETSC_SUCCESS);
  out->last_sync = MPI_Wtime();
  /* The .xmf about to name this frame must not point at data still in HDF5's cache. */
  TslH5Check(out->comm, H5Fflush(out->file, H5F_SCOPE_GLOBAL), out->h5_part);
  PetscCall(RewriteXmf(out));
  PetscFunctionReturn(PETSC_SUCCESS);
}

uint64_t TslOutputRunId(TslOutput out)
{
  return out->run_id;
}

PetscErrorCode TslOutputFrameCount(TslOutput out, PetscInt *n)
{
  PetscFunctionBeginUser;
  *n = out->nframe;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Reads attribute name of loc into val (rank-agreed failure naming path). */
static PetscErrorCode ReadAttribute(MPI_Comm comm, hid_t loc, const char *name, hid_t memtype, void *val, const char *path)
{
  hid_t attr;

  PetscFunctionBeginUser;
  TslH5Check(comm, attr = H5Aopen(loc, name, H5P_DEFAULT), path);
  TslH5Check(comm, H5Aread(attr, memtype, val), path);
  TslH5Check(comm, H5Aclose(attr), path);
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TslOutputCopyFrames(TslOutput out, const char *src, uint64_t run_id, PetscInt nframe)
{
  hid_t    fapl, file;
  uint64_t id = 0;

  PetscFunctionBeginUser;
  TslH5Check(out->comm, fapl = H5Pcreate(H5P_FILE_ACCESS), src);
  TslH5Check(out->comm, H5Pset_fapl_mpio(fapl, out->comm, MPI_INFO_NULL), src);
  TslH5Check(out->comm, H5Pset_all_coll_metadata_ops(fapl, 1), src);
  TslH5Check(out->comm, H5Pset_fclose_degree(fapl, H5F_CLOSE_STRONG), src);
  TslH5Check(out->comm, file = H5Fopen(src, H5F_ACC_RDONLY, fapl), src);
  TslH5Check(out->comm, H5Pclose(fapl), src);
  PetscCall(ReadAttribute(out->comm, file, "run_id", H5T_NATIVE_UINT64, &id, src));
  PetscCheck(id == run_id, out->comm, PETSC_ERR_FILE_UNEXPECTED, "%s is the output of another run than the restart point's (run %llx, not %llx)", src,
             (unsigned long long)id, (unsigned long long)run_id);
  for (PetscInt i = 1; i <= nframe; i++) {
    char    gname[32];
    hid_t   grp;
    hsize_t nlink;
    int64_t step, inc;
    double  t;
    H5G_info_t info;

    snprintf(gname, sizeof(gname), "/frames/%06d", (int)i);
    TslH5Check(out->comm, grp = H5Gopen2(file, gname, H5P_DEFAULT), src);
    PetscCall(ReadAttribute(out->comm, grp, "time", H5T_NATIVE_DOUBLE, &t, src));
    PetscCall(ReadAttribute(out->comm, grp, "step", H5T_NATIVE_INT64, &step, src));
    PetscCall(ReadAttribute(out->comm, grp, "increment", H5T_NATIVE_INT64, &inc, src));
    PetscCall(TslOutputBeginFrame(out, (PetscInt)step, (PetscInt)inc, (PetscReal)t));
    TslH5Check(out->comm, H5Gget_info(grp, &info), src);
    nlink = info.nlinks;
    for (hsize_t k = 0; k < nlink; k++) {
      char             name[TSL_NAME_LEN];
      hid_t            dset, fspace, mspace;
      hsize_t          dims[2] = {0, 1}, off[2] = {0, 0}, cnt[2];
      int64_t          cells   = 0;
      const TslRedist *rd;
      PetscReal       *blk;
      double           dummy;
      ssize_t          len;

      TslH5Check(out->comm, len = H5Lget_name_by_idx(grp, ".", H5_INDEX_NAME, H5_ITER_INC, k, name, sizeof(name), H5P_DEFAULT), src);
      PetscCheck(len < (ssize_t)sizeof(name), out->comm, PETSC_ERR_FILE_UNEXPECTED, "%s: a field name of frame %" PetscInt_FMT " is too long", src, i);
      TslH5Check(out->comm, dset = H5Dopen2(grp, name, H5P_DEFAULT), src);
      PetscCall(ReadAttribute(out->comm, dset, "cells", H5T_NATIVE_INT64, &cells, src));
      TslH5Check(out->comm, fspace = H5Dget_space(dset), src);
      TslH5Check(out->comm, H5Sget_simple_extent_dims(fspace, dims, NULL), src);
      rd = cells ? &out->elems : &out->nodes;
      PetscCheck((PetscInt)dims[0] == rd->nglobal, out->comm, PETSC_ERR_FILE_UNEXPECTED, "%s: field %s of frame %" PetscInt_FMT " has %llu rows, the model %" PetscInt_FMT, src, name,
                 i, (unsigned long long)dims[0], rd->nglobal);
      off[0] = (hsize_t)rd->bstart, cnt[0] = (hsize_t)rd->nblock, cnt[1] = dims[1];
      PetscCall(PetscMalloc1(PetscMax(1, (PetscInt)(dims[1] * rd->nblock)), &blk));
      TslH5Check(out->comm, mspace = H5Screate_simple(2, (hsize_t[]){cnt[0] ? cnt[0] : 1, dims[1]}, NULL), src);
      if (cnt[0]) TslH5Check(out->comm, H5Sselect_hyperslab(fspace, H5S_SELECT_SET, off, NULL, cnt, NULL), src);
      else TslH5Check(out->comm, H5Sselect_none(fspace) < 0 || H5Sselect_none(mspace) < 0 ? -1 : 0, src);
      TslH5Check(out->comm, H5Dread(dset, H5T_NATIVE_DOUBLE, mspace, fspace, out->dxpl, cnt[0] ? (void *)blk : (void *)&dummy), src);
      TslH5Check(out->comm, H5Sclose(mspace), src);
      TslH5Check(out->comm, H5Sclose(fspace), src);
      TslH5Check(out->comm, H5Dclose(dset), src);
      PetscCall(WriteField(out, name, (PetscInt)dims[1], NULL, blk, (PetscBool)(cells != 0)));
      PetscCall(PetscFree(blk));
    }
    TslH5Check(out->comm, H5Gclose(grp), src);
    PetscCall(TslOutputEndFrame(out));
  }
  TslH5Check(out->comm, H5Fclose(file), src);
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TslOutputSetSyncInterval(TslOutput out, PetscReal seconds)
{
  PetscFunctionBeginUser;
  out->sync_interval = (double)seconds;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TslOutputFinalize(TslOutput out, const char *tag)
{
  int err = 0;

  PetscFunctionBeginUser;
  PetscCheck(!out->in_frame, out->comm, PETSC_ERR_ORDER, "TslOutputFinalize() inside a frame");
  PetscCheck(!out->finalized, out->comm, PETSC_ERR_ORDER, "Output %s already finalized", out->h5_final);
  if (tag) {
    PetscCall(TslOutputFinalPath(out->comm, NULL, out->job, tag, ".h5", out->h5_base, sizeof(out->h5_base)));
    PetscCall(TslOutputFinalPath(out->comm, out->dir, out->job, tag, ".h5", out->h5_final, sizeof(out->h5_final)));
    PetscCall(TslOutputFinalPath(out->comm, out->dir, out->job, tag, ".xmf", out->xmf_final, sizeof(out->xmf_final)));
  }
  TslH5Check(out->comm, H5Fclose(out->file), out->h5_part);
  out->file = H5I_INVALID_HID;
  PetscCall(RewriteXmf(out));
  /* The .h5 goes first: a crash in between leaves the old .xmf, which may name frames the new .h5
   * lacks, rather than a new .xmf with no .h5 at all. */
  if (out->rank == 0 && rename(out->h5_part, out->h5_final)) err = errno;
  PetscCall(TslOutputCheckRoot(out->comm, err, "rename the finished output to", out->h5_final));
  if (out->rank == 0 && rename(out->xmf_part, out->xmf_final)) err = errno;
  PetscCall(TslOutputCheckRoot(out->comm, err, "rename the finished output to", out->xmf_final));
  out->finalized = PETSC_TRUE;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Collective. Without a Finalize the temporary files go, and the previous results stay. */
PetscErrorCode TslOutputDestroy(TslOutput *out)
{
  TslOutput o;

  PetscFunctionBeginUser;
  if (!out || !*out) PetscFunctionReturn(PETSC_SUCCESS);
  o = *out;
  {
    /* best effort and quiet: after a failed write some of these may fail too, and the temporary files
     * must go all the same */
    H5E_auto2_t efunc;
    void       *edata;
    (void)H5Eget_auto2(H5E_DEFAULT, &efunc, &edata);
    (void)H5Eset_auto2(H5E_DEFAULT, NULL, NULL);
    if (o->frame_group >= 0) (void)H5Gclose(o->frame_group);
    if (o->file >= 0) (void)H5Fclose(o->file);
    if (o->dxpl >= 0) (void)H5Pclose(o->dxpl);
    (void)H5Eset_auto2(H5E_DEFAULT, efunc, edata);
  }
  if (!o->finalized) {
    if (o->rank == 0) {
      (void)unlink(o->h5_part); /* any of them may never have been created */
      (void)unlink(o->xmf_part);
      (void)unlink(o->xmf_tmp);
    }
    PetscCallMPI(MPI_Barrier(o->comm)); /* no rank returns while the files are still there */
  }
  PetscCall(TslRedistReset(&o->nodes));
  PetscCall(TslRedistReset(&o->elems));
  for (PetscInt i = 0; i < o->nframe; i++) PetscCall(PetscFree(o->frames[i].fields));
  PetscCall(PetscFree(o->frames));
  PetscCall(PetscFree(o));
  *out = NULL;
  PetscFunctionReturn(PETSC_SUCCESS);
}
