/* Bin-grid candidate search: on random points the grid returns exactly the segments a brute-force box test
 * finds (the brute force lives only here), and each query visits few bins. */
#include "check.h"

static PetscReal Rand(unsigned long long *state)
{
  *state = *state * 6364136223846793005ULL + 1442695040888963407ULL;
  return (PetscReal)((*state >> 11) * (1.0 / 9007199254740992.0));
}

/* Brute force: every segment whose inflated box meets the square of half-width r round p. */
static PetscInt BruteForce(PetscInt nseg, const PetscReal x[], PetscReal margin, const PetscReal p[], PetscReal r, PetscInt cand[])
{
  PetscInt n = 0;

  for (PetscInt s = 0; s < nseg; s++) {
    const PetscReal *e     = &x[4 * s];
    PetscReal        lo[2] = {PetscMin(e[0], e[2]) - margin, PetscMin(e[1], e[3]) - margin};
    PetscReal        hi[2] = {PetscMax(e[0], e[2]) + margin, PetscMax(e[1], e[3]) + margin};

    if (p[0] + r < lo[0] || p[0] - r > hi[0] || p[1] + r < lo[1] || p[1] - r > hi[1]) continue;
    cand[n++] = s;
  }
  return n;
}

int main(int argc, char **argv)
{
  TestLog            log  = {0, 0};
  const PetscInt     nseg = 400, npts = 2000;
  const PetscReal    margin = 0.02;
  PetscReal         *x;
  PetscInt          *a, *b, mismatches = 0, maxbins = 0, maxbins_r = 0, maxcand = 0, total = 0, nx, ny;
  unsigned long long state = 12345;
  TslContactBinGrid  grid;

  PetscCall(PetscInitialize(&argc, &argv, NULL, NULL));
  PetscCall(PetscMalloc3(4 * nseg, &x, nseg, &a, nseg, &b));
  /* a wavy main surface of 300 facets over [0, 3] plus 100 short random facets in [0,3]x[-1,1] */
  for (PetscInt s = 0; s < 300; s++) {
    PetscReal t0 = 3.0 * s / 300, t1 = 3.0 * (s + 1) / 300;
    x[4 * s + 0] = t1;
    x[4 * s + 1] = 0.2 * PetscSinReal(4 * t1);
    x[4 * s + 2] = t0;
    x[4 * s + 3] = 0.2 * PetscSinReal(4 * t0);
  }
  for (PetscInt s = 300; s < nseg; s++) {
    PetscReal cx = 3 * Rand(&state), cy = 2 * Rand(&state) - 1, ang = 2 * PETSC_PI * Rand(&state), l = 0.05;
    x[4 * s + 0] = cx;
    x[4 * s + 1] = cy;
    x[4 * s + 2] = cx + l * PetscCosReal(ang);
    x[4 * s + 3] = cy + l * PetscSinReal(ang);
  }
  PetscCall(TslContactBinGridCreate(nseg, x, margin, &grid));
  PetscCall(TslContactBinGridGetSize(grid, &nx, &ny));
  printf("bin grid: %d x %d bins for %d segments\n", (int)nx, (int)ny, (int)nseg);
  for (PetscInt i = 0; i < npts; i++) {
    PetscReal p[2] = {-0.2 + 3.4 * Rand(&state), -1.2 + 2.4 * Rand(&state)}, r = (i % 2) ? 0.01 : 0;
    PetscInt  na, nb, nbins;

    if (i % 4 == 0) p[1] = 0.2 * PetscSinReal(4 * p[0]) + 0.01 * (Rand(&state) - 0.5); /* near the surface */
    PetscCall(TslContactBinGridQuery(grid, p, r, nseg, a, &na, &nbins));
    nb = BruteForce(nseg, x, margin, p, r, b);
    if (na != nb)
      mismatches++;
    else
      for (PetscInt k = 0; k < na; k++)
        if (a[k] != b[k]) {
          mismatches++;
          break;
        }
    if (r == 0)
      maxbins = PetscMax(maxbins, nbins);
    else
      maxbins_r = PetscMax(maxbins_r, nbins);
    maxcand = PetscMax(maxcand, na);
    total += na;
  }
  Check(&log, (PetscReal)mismatches, 0, 0, "bin grid: candidate sets equal brute force on %d random points", (int)npts);
  Check(&log, (PetscReal)maxbins, 1, 0, "bin grid: a point query visits one bin");
  Check(&log, (PetscReal)(maxbins_r <= 4), 1, 0, "bin grid: a query of radius 0.01 visits <= 4 bins (max %d)", (int)maxbins_r);
  Check(&log, (PetscReal)(maxcand <= 20), 1, 0, "bin grid: at most 20 candidates per query (max %d, mean %.2f)", (int)maxcand, (double)total / npts);
  {
    PetscInt  n, cap1[1];
    PetscReal p[2] = {1.0, 0.2 * PetscSinReal(4.0)};
    PetscCall(TslContactBinGridQuery(grid, p, 0, 1, cap1, &n, NULL));
    Check(&log, (PetscReal)(n >= 2), 1, 0, "bin grid: count reported beyond capacity (%d found, cap 1)", (int)n);
    p[0] = 100;
    PetscCall(TslContactBinGridQuery(grid, p, 0, nseg, a, &n, NULL));
    Check(&log, (PetscReal)n, 0, 0, "bin grid: point far outside has no candidates");
  }
  PetscCall(TslContactBinGridDestroy(&grid));
  Check(&log, (PetscReal)(grid == NULL), 1, 0, "bin grid: destroy nulls the handle");
  PetscCall(TslContactBinGridCreate(0, NULL, 0, &grid));
  {
    PetscInt  n;
    PetscReal p[2] = {0, 0};
    PetscCall(TslContactBinGridQuery(grid, p, 1, 0, NULL, &n, NULL));
    Check(&log, (PetscReal)n, 0, 0, "bin grid: empty surface");
  }
  PetscCall(TslContactBinGridDestroy(&grid));
  PetscCall(PetscFree3(x, a, b));
  PetscCall(PetscFinalize());
  return Summary(&log);
}
