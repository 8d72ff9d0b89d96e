/* Candidate search for the caller: a uniform bin grid over the main segments' inflated bounding boxes.
 * Each segment is listed in every bin its box overlaps (compressed rows), so a point query visits one bin
 * and tests only the segments listed there, never all pairs. */
#include <thermoslide/contact.h>

struct _n_TslContactBinGrid {
  PetscInt   nseg, nx, ny;
  PetscReal  x0, y0, h;     /* grid origin and bin size */
  PetscReal *box;           /* [4*nseg] xmin, ymin, xmax, ymax (inflated) */
  PetscInt  *offset, *item; /* bin b lists item[offset[b] .. offset[b+1]-1] */
  PetscInt  *mark, stamp;   /* de-duplication of segments met in several bins during one query */
};

static PetscInt BinIndex(PetscReal v, PetscReal origin, PetscReal h, PetscInt n)
{
  PetscInt i = (PetscInt)PetscFloorReal((v - origin) / h);
  return PetscMax(0, PetscMin(n - 1, i));
}

PetscErrorCode TslContactBinGridCreate(PetscInt nseg, const PetscReal seg_x[], PetscReal margin, TslContactBinGrid *grid)
{
  TslContactBinGrid G;
  PetscReal         lo[2] = {PETSC_MAX_REAL, PETSC_MAX_REAL}, hi[2] = {-PETSC_MAX_REAL, -PETSC_MAX_REAL}, size = 0;
  PetscInt          nbin, *fill;

  PetscFunctionBeginUser;
  PetscCheck(nseg >= 0 && margin >= 0, PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE, "Need nseg >= 0 and margin >= 0");
  PetscCall(PetscNew(&G));
  G->nseg = nseg;
  PetscCall(PetscMalloc2(4 * nseg + 1, &G->box, nseg + 1, &G->mark));
  for (PetscInt s = 0; s < nseg; s++) {
    const PetscReal *x = &seg_x[4 * s];
    PetscReal       *b = &G->box[4 * s];

    b[0] = PetscMin(x[0], x[2]) - margin;
    b[1] = PetscMin(x[1], x[3]) - margin;
    b[2] = PetscMax(x[0], x[2]) + margin;
    b[3] = PetscMax(x[1], x[3]) + margin;
    for (PetscInt d = 0; d < 2; d++) {
      lo[d] = PetscMin(lo[d], b[d]);
      hi[d] = PetscMax(hi[d], b[d + 2]);
    }
    size += PetscMax(b[2] - b[0], b[3] - b[1]);
    G->mark[s] = -1;
  }
  if (nseg == 0) {
    lo[0] = lo[1] = 0;
    hi[0] = hi[1] = 1;
    size          = 1;
  }
  /* bins about the size of a typical box, but never more than ~4 bins per segment in total */
  G->h = PetscMax(size / PetscMax(nseg, 1), 1e-12 * PetscMax(hi[0] - lo[0], hi[1] - lo[1]));
  if (G->h <= 0) G->h = 1;
  for (;;) {
    G->nx = (PetscInt)PetscCeilReal((hi[0] - lo[0]) / G->h) + 1;
    G->ny = (PetscInt)PetscCeilReal((hi[1] - lo[1]) / G->h) + 1;
    if ((PetscReal)G->nx * G->ny <= 4.0 * nseg + 16) break;
    G->h *= 1.5;
  }
  G->x0 = lo[0];
  G->y0 = lo[1];
  nbin  = G->nx * G->ny;

  /* two passes: count per bin, then fill */
  PetscCall(PetscCalloc1(nbin + 1, &G->offset));
  PetscCall(PetscCalloc1(nbin, &fill));
  for (PetscInt pass = 0; pass < 2; pass++) {
    for (PetscInt s = 0; s < nseg; s++) {
      const PetscReal *b  = &G->box[4 * s];
      PetscInt         i0 = BinIndex(b[0], G->x0, G->h, G->nx), i1 = BinIndex(b[2], G->x0, G->h, G->nx);
      PetscInt         j0 = BinIndex(b[1], G->y0, G->h, G->ny), j1 = BinIndex(b[3], G->y0, G->h, G->ny);

      for (PetscInt j = j0; j <= j1; j++)
        for (PetscInt i = i0; i <= i1; i++) {
          PetscInt bin = j * G->nx + i;
          if (pass == 0)
            G->offset[bin + 1]++;
          else
            G->item[G->offset[bin] + fill[bin]++] = s;
        }
    }
    if (pass == 0) {
      for (PetscInt b = 0; b < nbin; b++) G->offset[b + 1] += G->offset[b];
      PetscCall(PetscMalloc1(G->offset[nbin] + 1, &G->item));
    }
  }
  PetscCall(PetscFree(fill));
  G->stamp = 0;
  *grid    = G;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TslContactBinGridDestroy(TslContactBinGrid *grid)
{
  PetscFunctionBeginUser;
  if (!*grid) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(PetscFree2((*grid)->box, (*grid)->mark));
  PetscCall(PetscFree((*grid)->offset));
  PetscCall(PetscFree((*grid)->item));
  PetscCall(PetscFree(*grid));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TslContactBinGridQuery(TslContactBinGrid G, const PetscReal p[], PetscReal radius, PetscInt cap, PetscInt cand[], PetscInt *ncand,
                                      PetscInt *nbins)
{
  PetscReal q[4]   = {p[0] - radius, p[1] - radius, p[0] + radius, p[1] + radius};
  PetscReal top[2] = {G->x0 + G->nx * G->h, G->y0 + G->ny * G->h};
  PetscInt  n = 0, visited = 0;

  PetscFunctionBeginUser;
  PetscCheck(radius >= 0, PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE, "Query radius must be >= 0");
  if (q[2] >= G->x0 && q[3] >= G->y0 && q[0] <= top[0] && q[1] <= top[1] && G->nseg > 0) {
    PetscInt i0 = BinIndex(q[0], G->x0, G->h, G->nx), i1 = BinIndex(q[2], G->x0, G->h, G->nx);
    PetscInt j0 = BinIndex(q[1], G->y0, G->h, G->ny), j1 = BinIndex(q[3], G->y0, G->h, G->ny);

    if (G->stamp == PETSC_MAX_INT) {
      for (PetscInt s = 0; s < G->nseg; s++) G->mark[s] = -1;
      G->stamp = 0;
    }
    G->stamp++;
    for (PetscInt j = j0; j <= j1; j++)
      for (PetscInt i = i0; i <= i1; i++) {
        PetscInt bin = j * G->nx + i;

        visited++;
        for (PetscInt k = G->offset[bin]; k < G->offset[bin + 1]; k++) {
          PetscInt         s = G->item[k];
          const PetscReal *b = &G->box[4 * s];

          if (G->mark[s] == G->stamp) continue;
          G->mark[s] = G->stamp;
          if (q[2] < b[0] || q[0] > b[2] || q[3] < b[1] || q[1] > b[3]) continue;
          if (n < cap) cand[n] = s;
          n++;
        }
      }
    PetscCall(PetscSortInt(PetscMin(n, cap), cand));
  }
  *ncand = n;
  if (nbins) *nbins = visited;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TslContactBinGridGetSize(TslContactBinGrid grid, PetscInt *nx, PetscInt *ny)
{
  PetscFunctionBeginUser;
  if (nx) *nx = grid->nx;
  if (ny) *ny = grid->ny;
  PetscFunctionReturn(PETSC_SUCCESS);
}
