/* Candidate search for the caller: a uniform bin grid (2D or 3D) over the main faces' inflated bounding
 * boxes. Each face is listed in every bin its box overlaps (compressed rows), so a point query visits the
 * bins its query box overlaps and tests only the faces listed there, never all pairs. */
#include <thermoslide/contact.h>

struct _n_TslContactBinGrid {
  PetscInt   dim, nseg, n[3];
  PetscReal  o[3], h;       /* grid origin and bin size */
  PetscReal *box;           /* [2*dim*nseg] min[dim], max[dim] (inflated) */
  PetscInt  *offset, *item; /* bin b lists item[offset[b] .. offset[b+1]-1] */
  PetscInt  *mark, stamp;   /* de-duplication of faces met in several bins during one query */
};

static PetscInt BinIndex(PetscReal v, PetscReal origin, PetscReal h, PetscInt n)
{
  PetscInt i = (PetscInt)PetscFloorReal((v - origin) / h);
  return PetscMax(0, PetscMin(n - 1, i));
}

/* Bin ranges lo[d]..hi[d] covered by the box b = (min[dim], max[dim]). */
static void BinRange(const struct _n_TslContactBinGrid *G, const PetscReal b[], PetscInt lo[3], PetscInt hi[3])
{
  for (PetscInt d = 0; d < 3; d++) {
    lo[d] = hi[d] = 0;
    if (d < G->dim) {
      lo[d] = BinIndex(b[d], G->o[d], G->h, G->n[d]);
      hi[d] = BinIndex(b[G->dim + d], G->o[d], G->h, G->n[d]);
    }
  }
}

PetscErrorCode TslContactBinGridCreateDim(PetscInt dim, PetscInt nseg, const PetscReal seg_x[], PetscReal margin, TslContactBinGrid *grid)
{
  TslContactBinGrid G;
  PetscReal         lo[3] = {0, 0, 0}, hi[3] = {1, 1, 1}, size = 0, ext = 0, nbinr;
  PetscInt          nbin, *fill;

  PetscFunctionBeginUser;
  PetscCheck(dim == 2 || dim == 3, PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE, "Bin grids are 2D or 3D");
  PetscCheck(nseg >= 0 && margin >= 0, PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE, "Need nseg >= 0 and margin >= 0");
  PetscCall(PetscNew(&G));
  G->dim  = dim;
  G->nseg = nseg;
  PetscCall(PetscMalloc2(2 * dim * nseg + 1, &G->box, nseg + 1, &G->mark));
  if (nseg > 0)
    for (PetscInt d = 0; d < dim; d++) lo[d] = PETSC_MAX_REAL, hi[d] = -PETSC_MAX_REAL;
  for (PetscInt s = 0; s < nseg; s++) {
    const PetscReal *x = &seg_x[2 * dim * s];
    PetscReal       *b = &G->box[2 * dim * s], big = 0;

    for (PetscInt d = 0; d < dim; d++) {
      b[d]       = PetscMin(x[d], x[dim + d]) - margin;
      b[dim + d] = PetscMax(x[d], x[dim + d]) + margin;
      lo[d]      = PetscMin(lo[d], b[d]);
      hi[d]      = PetscMax(hi[d], b[dim + d]);
      big        = PetscMax(big, b[dim + d] - b[d]);
    }
    size += big;
    G->mark[s] = -1;
  }
  if (nseg == 0) size = 1;
  for (PetscInt d = 0; d < dim; d++) ext = PetscMax(ext, hi[d] - lo[d]);
  /* bins about the size of a typical box, but never more than ~4 bins per face in total */
  G->h = PetscMax(size / PetscMax(nseg, 1), 1e-12 * ext);
  if (G->h <= 0) G->h = 1;
  for (;;) {
    nbinr = 1;
    for (PetscInt d = 0; d < 3; d++) {
      G->n[d] = d < dim ? (PetscInt)PetscCeilReal((hi[d] - lo[d]) / G->h) + 1 : 1;
      nbinr *= G->n[d];
    }
    if (nbinr <= 4.0 * nseg + 16) break;
    G->h *= 1.5;
  }
  for (PetscInt d = 0; d < 3; d++) G->o[d] = d < dim ? lo[d] : 0;
  nbin = G->n[0] * G->n[1] * G->n[2];

  /* two passes: count per bin, then fill */
  PetscCall(PetscCalloc1(nbin + 1, &G->offset));
  PetscCall(PetscCalloc1(nbin, &fill));
  for (PetscInt pass = 0; pass < 2; pass++) {
    for (PetscInt s = 0; s < nseg; s++) {
      PetscInt l[3], u[3];

      BinRange(G, &G->box[2 * dim * s], l, u);
      for (PetscInt k = l[2]; k <= u[2]; k++)
        for (PetscInt j = l[1]; j <= u[1]; j++)
          for (PetscInt i = l[0]; i <= u[0]; i++) {
            PetscInt bin = (k * G->n[1] + j) * G->n[0] + i;
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

PetscErrorCode TslContactBinGridCreate(PetscInt nseg, const PetscReal seg_x[], PetscReal margin, TslContactBinGrid *grid)
{
  PetscFunctionBeginUser;
  PetscCall(TslContactBinGridCreateDim(2, nseg, seg_x, margin, grid));
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
  const PetscInt dim = G->dim;
  PetscReal      q[6];
  PetscInt       n = 0, visited = 0;
  PetscBool      meets = (PetscBool)(G->nseg > 0);

  PetscFunctionBeginUser;
  PetscCheck(radius >= 0, PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE, "Query radius must be >= 0");
  for (PetscInt d = 0; d < dim; d++) {
    q[d]       = p[d] - radius;
    q[dim + d] = p[d] + radius;
    if (q[dim + d] < G->o[d] || q[d] > G->o[d] + G->n[d] * G->h) meets = PETSC_FALSE;
  }
  if (meets) {
    PetscInt l[3], u[3];

    BinRange(G, q, l, u);
    if (G->stamp == PETSC_MAX_INT) {
      for (PetscInt s = 0; s < G->nseg; s++) G->mark[s] = -1;
      G->stamp = 0;
    }
    G->stamp++;
    for (PetscInt k = l[2]; k <= u[2]; k++)
      for (PetscInt j = l[1]; j <= u[1]; j++)
        for (PetscInt i = l[0]; i <= u[0]; i++) {
          PetscInt bin = (k * G->n[1] + j) * G->n[0] + i;

          visited++;
          for (PetscInt m = G->offset[bin]; m < G->offset[bin + 1]; m++) {
            PetscInt         s = G->item[m];
            const PetscReal *b = &G->box[2 * dim * s];
            PetscBool        hit = PETSC_TRUE;

            if (G->mark[s] == G->stamp) continue;
            G->mark[s] = G->stamp;
            for (PetscInt d = 0; d < dim; d++)
              if (q[dim + d] < b[d] || q[d] > b[dim + d]) hit = PETSC_FALSE;
            if (!hit) continue;
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

PetscErrorCode TslContactBinGridQueryGrow(TslContactBinGrid grid, const PetscReal p[], PetscReal radius, PetscInt *cap, PetscInt **cand, PetscInt *ncand)
{
  PetscFunctionBeginUser;
  PetscCall(TslContactBinGridQuery(grid, p, radius, *cap, *cand, ncand, NULL));
  if (*ncand > *cap) {
    *cap = *ncand;
    PetscCall(PetscFree(*cand));
    PetscCall(PetscMalloc1(*cap, cand));
    PetscCall(TslContactBinGridQuery(grid, p, radius, *cap, *cand, ncand, NULL));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TslContactBinGridGetSize(TslContactBinGrid grid, PetscInt *nx, PetscInt *ny)
{
  PetscFunctionBeginUser;
  if (nx) *nx = grid->n[0];
  if (ny) *ny = grid->n[1] * grid->n[2];
  PetscFunctionReturn(PETSC_SUCCESS);
}
