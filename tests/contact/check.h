/* Check printing shared by the contact unit tests: one line per check,
 *   name: value (expected, tolerance) PASS/FAIL
 * and a failure count the program turns into its exit status. */
#pragma once
#include <thermoslide/contact.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

typedef struct {
  PetscInt checks, failures;
} TestLog;

static inline void CheckV(TestLog *log, PetscBool ok, PetscReal value, PetscReal expected, PetscReal tol, const char *fmt, va_list ap)
{
  char name[256];

  vsnprintf(name, sizeof(name), fmt, ap);
  log->checks++;
  if (!ok) log->failures++;
  printf("%s: %.12g (%.12g, %.1e) %s\n", name, (double)value, (double)expected, (double)tol, ok ? "PASS" : "FAIL");
}

/* |value - expected| <= tol passes. */
static inline void Check(TestLog *log, PetscReal value, PetscReal expected, PetscReal tol, const char *fmt, ...)
{
  va_list ap;

  va_start(ap, fmt);
  CheckV(log, (PetscBool)(PetscAbsReal(value - expected) <= tol), value, expected, tol, fmt, ap);
  va_end(ap);
}

/* |value - expected| <= rtol * max(|expected|, floor) passes. */
static inline void CheckRel(TestLog *log, PetscReal value, PetscReal expected, PetscReal rtol, PetscReal floor, const char *fmt, ...)
{
  va_list   ap;
  PetscReal tol = rtol * PetscMax(PetscAbsReal(expected), floor);

  va_start(ap, fmt);
  CheckV(log, (PetscBool)(PetscAbsReal(value - expected) <= tol), value, expected, tol, fmt, ap);
  va_end(ap);
}

static inline int Summary(const TestLog *log)
{
  printf("%d of %d checks failed\n", (int)log->failures, (int)log->checks);
  return log->failures ? 1 : 0;
}

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
