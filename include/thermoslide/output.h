/* thermoslide output: XDMF + parallel HDF5 field output and the history CSV.
 *
 * Field output is written in natural (deck) order: node i of the file is the i-th smallest node id,
 * element j the j-th smallest element id, whatever the number of ranks. Each rank hands over the
 * values of the nodes it owns and the elements it holds, with their natural indices; the writer
 * moves them into contiguous blocks and writes collectively.
 *
 * Files are written under temporary names (<job>.h5.part, <job>.xmf.part, <job>.csv.part) and
 * renamed over the final names only by TslOutputFinalize / TslHistoryFinalize, so an earlier good
 * result is never replaced by a partial one. Destroying an output that was not finalized removes the
 * temporary files.
 *
 * Layout of <job>.h5:
 *   /mesh/coordinates   [N][3]  double
 *   /mesh/topology      [L]     int64, XDMF "Mixed" records (cell type id, then natural node indices)
 *   /mesh/connectivity  [M][n]  int64 natural node indices, when every element has one XDMF cell type of n nodes
 *                               (the .xmf then names that type's topology, Hexahedron_20 ..., instead of Mixed)
 *   /mesh/node_ids      [N]     int64 deck node ids
 *   /mesh/element_ids   [M]     int64 deck element ids
 *   /frames/NNNNNN/<name>  [N][ncomp] (node fields) or [M][ncomp] (element fields) double
 *   attributes of /frames/NNNNNN: time, step, increment
 */
#pragma once
#include <stdint.h>
#include <thermoslide/compat.h>

typedef struct _p_TslOutput *TslOutput;

/* Creates the writer; dir must exist. jobname is the deck's base name without extension. */
PetscErrorCode TslOutputCreate(MPI_Comm comm, const char *dir, const char *jobname, TslOutput *out);

/* The mesh, given once before the first frame.
 *   nnode_global, nelem_global: totals
 *   nnode: nodes this rank writes (its owned nodes), node_nat[nnode] their natural indices,
 *          node_id[nnode] deck ids, xyz[3*nnode] coordinates
 *   nelem: elements this rank holds, elem_nat[nelem] natural indices, elem_id[nelem] deck ids,
 *          xdmf_type[nelem] cell types, ptr[nelem+1]/conn natural node indices of each element */
PetscErrorCode TslOutputSetMesh(TslOutput out, PetscInt nnode_global, PetscInt nnode, const PetscInt node_nat[], const PetscInt node_id[],
                                const PetscReal xyz[], PetscInt nelem_global, PetscInt nelem, const PetscInt elem_nat[], const PetscInt elem_id[],
                                const PetscInt xdmf_type[], const PetscInt ptr[], const PetscInt conn[]);

/* One frame (an output increment). Fields are given between Begin and End; vals are
 * [nnode][ncomp] for node fields (in SetMesh's node order) and [nelem][ncomp] for element fields. */
PetscErrorCode TslOutputBeginFrame(TslOutput out, PetscInt step, PetscInt increment, PetscReal time);
PetscErrorCode TslOutputNodeField(TslOutput out, const char *name, PetscInt ncomp, const PetscReal vals[]);
PetscErrorCode TslOutputElementField(TslOutput out, const char *name, PetscInt ncomp, const PetscReal vals[]);
/* Ends the frame. The .h5 is flushed and the .xmf.part rewritten to name it when at least the sync
 * interval has passed since the last time (rank 0's clock decides; always for the first frame), and at
 * TslOutputFinalize: a long job's frames become visible to a reader within that interval, while a job
 * of many small increments does not spend its time rewriting the XML and flushing metadata. */
PetscErrorCode TslOutputEndFrame(TslOutput out);
/* Seconds between syncs (default 1; 0: after every frame). */
PetscErrorCode TslOutputSetSyncInterval(TslOutput out, PetscReal seconds);
/* Restart (src/solve/restart.c): this run's identity, its frames so far, and the first nframe frames of the earlier
 * run run_id copied from its file src into this output (a continuation's output extends the original's). Collective;
 * after TslOutputSetMesh, before any frame of this run. */
uint64_t       TslOutputRunId(TslOutput out);
/* Collective: the frames so far on disk now (HDF5 flushed, the .xmf.part rewritten), whatever the sync interval; a
 * restart point that counts them is written after this. */
PetscErrorCode TslOutputSync(TslOutput out);
PetscErrorCode TslOutputFrameCount(TslOutput out, PetscInt *n);
PetscErrorCode TslOutputCopyFrames(TslOutput out, const char *src, uint64_t run_id, PetscInt nframe);

/* Moves the temporary files over <job>.h5 / <job>.xmf, or <job>.<tag>.h5 / .xmf when tag is given (the
 * results of a run that stopped, kept beside earlier ones). Collective. */
PetscErrorCode TslOutputFinalize(TslOutput out, const char *tag);
PetscErrorCode TslOutputDestroy(TslOutput *out);

/* History: one CSV row per increment, written by rank 0; values must be the same on all ranks. */
typedef struct _p_TslHistory *TslHistory;
PetscErrorCode TslHistoryCreate(MPI_Comm comm, const char *dir, const char *jobname, PetscInt ncol, const char *const names[], TslHistory *hist);
PetscErrorCode TslHistoryAppend(TslHistory hist, const PetscReal vals[]);
PetscErrorCode TslHistoryFinalize(TslHistory hist, const char *tag); /* as TslOutputFinalize */
PetscErrorCode TslHistoryDestroy(TslHistory *hist);
/* Restart: the first nrow data rows of an earlier history file src copied into this one (rank 0 reads it;
 * collective), and the rows so far. */
PetscErrorCode TslHistoryCopyRows(TslHistory hist, const char *src, PetscInt nrow);
PetscInt       TslHistoryRowCount(TslHistory hist);

/* Printed tables (*NODE PRINT, *EL PRINT) in rank order with bounded memory: rank 0 prints its own lines
 * as they come, then asks each rank in turn, which sends its lines in chunks of at most 64 kB. No rank
 * ever holds more than a chunk of text, whatever the size of the table. emit() is called once on every
 * rank and writes its lines with TslPrintLine; a failure on any rank is raised on all (collective). */
typedef struct _p_TslPrintSink *TslPrintSink;
PetscErrorCode TslPrintOrdered(MPI_Comm comm, PetscErrorCode (*emit)(TslPrintSink sink, void *ctx), void *ctx);
PetscErrorCode TslPrintLine(TslPrintSink sink, const char *fmt, ...) PETSC_ATTRIBUTE_FORMAT(2, 3);

/* Reading a job's results back (*TEMPERATURE, FILE=: src/physics/tfile.c). Not collective: each rank opens the file
 * read-only for itself and reads the rows of its own nodes, nothing of global size beyond the list of frames. A
 * failure is an error on PETSC_COMM_SELF (PETSC_ERR_FILE_READ, naming the file and what was looked for): callers
 * capture it and decide with the other ranks (TslAgree). Rows are natural node indices (the file's node order). */
typedef struct _p_TslResults *TslResults;
typedef struct {
  PetscInt  step, increment;
  PetscReal time; /* total time */
} TslResultsFrame;
PetscErrorCode TslResultsOpen(const char *path, TslResults *r);
/* the number of nodes, and the frames in file order (frame k is /frames/%06d of k + 1) */
PetscErrorCode TslResultsInfo(TslResults r, PetscInt *nnode, PetscInt *nframe, const TslResultsFrame **frames);
/* ncomp values of each of n rows of a node dataset ("/mesh/coordinates", "/frames/000003/NT"); n may be 0 */
PetscErrorCode TslResultsReadRows(TslResults r, const char *dataset, PetscInt n, const PetscInt rows[], PetscInt ncomp, PetscReal vals[]);
/* the deck ids of n rows (/mesh/node_ids) */
PetscErrorCode TslResultsReadNodeIds(TslResults r, PetscInt n, const PetscInt rows[], PetscInt ids[]);
PetscErrorCode TslResultsClose(TslResults *r);
