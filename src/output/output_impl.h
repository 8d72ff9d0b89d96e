/* Private to src/output/: the writer objects and the natural-order redistribution they share. */
#pragma once
#include <thermoslide/output.h>
#include <thermoslide/sys.h>
#include <hdf5.h>
#include <stdint.h>
#include <stdio.h>

/* Checks an HDF5 return value (herr_t or hid_t: negative means failure) on every rank together: a call
 * that failed on one rank only raises the same error naming the call and the file on all ranks, before
 * any of them enters the next collective call (where the others would wait for it for ever). */
#define TslH5Check(comm, expr, path) PetscCall(TslH5Agree((comm), (PetscBool)((expr) < 0), #expr, (path)))
PetscErrorCode TslH5Agree(MPI_Comm comm, PetscBool failed, const char *call, const char *path);

/* Moves per-item records from "each rank its own items, any natural indices" to "each rank one
 * contiguous block of natural indices" (PETSC_DECIDE layout: the first N % size ranks get one item
 * more). Set up once per index set (nodes, elements); then any fixed-width record can be moved.
 * Memory is O(local items + block + ranks); nothing is of global size. */
typedef struct {
  PetscInt     nglobal;                           /* N */
  PetscInt     nlocal;                            /* items this rank hands over */
  PetscInt     bstart;                            /* first natural index of this rank's block */
  PetscInt     nblock;                            /* size of this rank's block */
  PetscMPIInt *scount, *sdispl, *rcount, *rdispl; /* per rank, in items */
  PetscInt    *sorder;                            /* sorder[k]: local item placed k-th in the send buffer */
  PetscInt    *rslot;                             /* rslot[k]: block position of the k-th received item */
} TslRedist;

PetscErrorCode TslRedistSetUp(MPI_Comm comm, PetscInt nglobal, PetscInt nlocal, const PetscInt nat[], const char *what, TslRedist *rd);
PetscErrorCode TslRedistMove(MPI_Comm comm, const TslRedist *rd, size_t width, const void *src, void *dst);
PetscErrorCode TslRedistReset(TslRedist *rd);

/* What the .xmf needs to know about a frame; kept on every rank (small: names and sizes only). */
typedef struct {
  char      name[TSL_NAME_LEN];
  PetscInt  ncomp;
  PetscBool on_cells;
} TslOutputFieldInfo;

typedef struct {
  PetscInt            step, increment;
  PetscReal           time;
  PetscInt            nfield, maxfield;
  TslOutputFieldInfo *fields;
} TslOutputFrameInfo;

struct _p_TslOutput {
  MPI_Comm            comm;
  PetscMPIInt         rank;
  char                job[TSL_NAME_LEN];
  char                dir[PETSC_MAX_PATH_LEN];
  PetscInt            cur_step;                    /* step of the open frame */
  TslInject           inject;                      /* testing aid: an output failure on one rank */
  char                h5_base[PETSC_MAX_PATH_LEN]; /* "<job>.h5", as the .xmf refers to it */
  char                h5_part[PETSC_MAX_PATH_LEN], h5_final[PETSC_MAX_PATH_LEN];
  char                xmf_part[PETSC_MAX_PATH_LEN], xmf_tmp[PETSC_MAX_PATH_LEN], xmf_final[PETSC_MAX_PATH_LEN];
  hid_t               file, dxpl, frame_group;
  PetscBool           mesh_set, in_frame, finalized;
  PetscInt            nnode_global, nelem_global;
  int64_t             topo_len; /* length of /mesh/topology */
  const char         *cell_name; /* every element of one XDMF cell type: its topology name (/mesh/connectivity written); NULL: Mixed */
  PetscInt            cell_nodes; /* ... and its nodes per element */
  TslRedist           nodes, elems;
  PetscInt            nframe, maxframe;
  TslOutputFrameInfo *frames;
  double              sync_interval, last_sync; /* wall seconds between syncs of the .h5 and .xmf.part; last one */
  uint64_t            run_id; /* this run's identity (the root attribute run_id; restart points name it) */
};

/* The XDMF topology type of a cell type id (XDMF's numbering, as in /mesh/topology): its name and node count, for
 * a mesh of that type alone; NULL for an id without a fixed node count. */
const char *TslXdmfTopologyName(PetscInt xdmf_type, PetscInt *nodes);

/* Writes the whole .xmf text for the frames so far to path. Called on rank 0 only; returns 0 or an
 * errno value in *err instead of raising, so the caller can broadcast the outcome. */
PetscErrorCode TslOutputWriteXmf(TslOutput out, const char *path, int *err);

/* Raises the same error on every rank when rank 0's file operation failed (err is rank 0's errno). */
PetscErrorCode TslOutputCheckRoot(MPI_Comm comm, int err, const char *action, const char *path);

/* Builds dir/name+suffix into buf, failing if it does not fit. */
PetscErrorCode TslOutputPath(MPI_Comm comm, const char *dir, const char *name, const char *suffix, char buf[], size_t len);
PetscErrorCode TslOutputCheckName(MPI_Comm comm, const char *kind, const char *name, const char *forbidden);

struct _p_TslHistory {
  MPI_Comm    comm;
  PetscMPIInt rank;
  PetscInt    ncol;
  FILE       *fp; /* rank 0 only */
  char        part[PETSC_MAX_PATH_LEN], final[PETSC_MAX_PATH_LEN];
  char        dir[PETSC_MAX_PATH_LEN], job[TSL_NAME_LEN];
  PetscBool   finalized;
  PetscInt    nrow; /* data rows written (copied ones included) */
};

/* The final name dir/job[.tag]suffix: tag (may be NULL) marks the results of a run that stopped. */
PetscErrorCode TslOutputFinalPath(MPI_Comm comm, const char *dir, const char *job, const char *tag, const char *suffix, char buf[], size_t len);
