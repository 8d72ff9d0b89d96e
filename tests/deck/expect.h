/* The deck unit tests' checks: EXPECT(condition) through the shared harness (tests/common/tsl_check.h),
 * naming the file and line of the expectation; nfail is the failure count. */
#pragma once
#include "../common/tsl_check.h"

static TestLog tsl_deck_log = {0, 0};

#define EXPECT(c) CheckTrue(&tsl_deck_log, (PetscBool)((c) ? 1 : 0), "%s:%d: %s", __FILE__, __LINE__, #c)
#define nfail     ((int)tsl_deck_log.failures)
#define NEAR(a, b) (PetscAbsReal((PetscReal)(a) - (PetscReal)(b)) <= 1e-12 * (1 + PetscAbsReal((PetscReal)(b))))
