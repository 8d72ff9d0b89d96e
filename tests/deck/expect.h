/* Shared by the deck unit tests: EXPECT counts a failed condition in nfail and goes on. */
#pragma once
#include <petscsys.h>

static int nfail = 0;

#define EXPECT(c)                                                                                                                                    \
  do {                                                                                                                                               \
    if (!(c)) {                                                                                                                                      \
      PetscCall(PetscPrintf(PETSC_COMM_SELF, "FAIL %s:%d: %s\n", __FILE__, __LINE__, #c));                                                           \
      nfail++;                                                                                                                                       \
    }                                                                                                                                                \
  } while (0)
#define NEAR(a, b) (PetscAbsReal((PetscReal)(a) - (PetscReal)(b)) <= 1e-12 * (1 + PetscAbsReal((PetscReal)(b))))
