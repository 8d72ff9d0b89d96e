/* The contact unit tests' checks (the shared harness, tests/common/tsl_check.h) and their fixture. */
#pragma once
#include <thermoslide/contact.h>
#include <string.h>
#include "../common/tsl_check.h"

/* A plane-strain element input with zero unknowns: s at xs, segment x1 -> x2. */
static inline TslContactInput InputSetUp(const PetscReal xs[2], const PetscReal x1[2], const PetscReal x2[2])
{
  TslContactInput in;

  memset(&in, 0, sizeof(in));
  in.kin       = TSL_KIN_PLANE_STRAIN;
  in.thickness = 1;
  in.length    = 1;
  in.dt        = 1;
  for (PetscInt d = 0; d < 2; d++) {
    in.x[0][d] = xs[d];
    in.x[1][d] = x1[d];
    in.x[2][d] = x2[d];
  }
  return in;
}

/* A consistent tangent K against its central-difference estimate Kfd (nd x nd, row-major), block by block:
 * kind[i] (0 .. nkind-1) says what unknown i is (u, theta, phi), each block relative to its own scale (an
 * element's force, heat and moment rows differ by orders), and a block that finite differences find empty
 * (e.g. u-theta: contact forces do not depend on temperature) must be empty in K too. */
static inline void CheckTangentBlocks(TestLog *log, const char *name, PetscInt nd, const PetscReal K[], const PetscReal Kfd[], const PetscInt kind[],
                                      PetscInt nkind, const char *const kname[])
{
  for (PetscInt bi = 0; bi < nkind; bi++)
    for (PetscInt bj = 0; bj < nkind; bj++) {
      PetscReal scale = 0, err = 0, all = 0;

      for (PetscInt i = 0; i < nd; i++)
        for (PetscInt j = 0; j < nd; j++) {
          all = PetscMax(all, PetscAbsReal(Kfd[i * nd + j]));
          if (kind[i] != bi || kind[j] != bj) continue;
          scale = PetscMax(scale, PetscAbsReal(Kfd[i * nd + j]));
          err   = PetscMax(err, PetscAbsReal(K[i * nd + j] - Kfd[i * nd + j]));
        }
      if (scale <= 1e-12 * all)
        Check(log, err, 0, 1e-9 * all, "%s: %s-%s block empty (|K| vs overall scale)", name, kname[bi], kname[bj]);
      else
        Check(log, err / scale, 0, 1e-6, "%s: %s-%s block, max|K - K_fd| / max|K_fd| (scale %.3g)", name, kname[bi], kname[bj], (double)scale);
    }
}
