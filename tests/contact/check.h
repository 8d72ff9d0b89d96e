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
