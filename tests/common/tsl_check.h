/* The one check harness of the unit tests: one line per check,
 *   name: value (expected, tolerance) PASS/FAIL     or     name: value (>= bound) PASS/FAIL
 * and a failure count the program turns into its exit status (Summary). Element, contact and deck
 * tests all use it (tests/element/check.h, tests/contact/check.h and tests/deck/expect.h add only
 * their own fixtures). */
#pragma once
#include <petscsys.h>
#include <stdarg.h>
#include <stdio.h>

typedef struct {
  PetscInt checks, failures;
} TestLog;

static inline void CheckReport(TestLog *log, PetscBool ok, const char *detail, const char *fmt, va_list ap)
{
  char name[256];

  vsnprintf(name, sizeof(name), fmt, ap);
  log->checks++;
  if (!ok) log->failures++;
  printf("%s: %s %s\n", name, detail, ok ? "PASS" : "FAIL");
}

/* |value - expected| <= tol passes. */
static inline void Check(TestLog *log, PetscReal value, PetscReal expected, PetscReal tol, const char *fmt, ...)
{
  char    detail[96];
  va_list ap;

  snprintf(detail, sizeof(detail), "%.12g (%.12g, %.1e)", (double)value, (double)expected, (double)tol);
  va_start(ap, fmt);
  CheckReport(log, (PetscBool)(PetscAbsReal(value - expected) <= tol), detail, fmt, ap);
  va_end(ap);
}

/* |value - expected| <= rtol * max(|expected|, floor) passes. */
static inline void CheckRel(TestLog *log, PetscReal value, PetscReal expected, PetscReal rtol, PetscReal floor, const char *fmt, ...)
{
  char            detail[96];
  const PetscReal tol = rtol * PetscMax(PetscAbsReal(expected), floor);
  va_list         ap;

  snprintf(detail, sizeof(detail), "%.12g (%.12g, %.1e)", (double)value, (double)expected, (double)tol);
  va_start(ap, fmt);
  CheckReport(log, (PetscBool)(PetscAbsReal(value - expected) <= tol), detail, fmt, ap);
  va_end(ap);
}

static inline void CheckBoundV(TestLog *log, PetscReal value, PetscReal bound, PetscBool lower, const char *fmt, va_list ap)
{
  char detail[96];

  snprintf(detail, sizeof(detail), "%.6g (%s %.6g)", (double)value, lower ? ">=" : "<=", (double)bound);
  CheckReport(log, (PetscBool)(lower ? value >= bound : value <= bound), detail, fmt, ap);
}

static inline void CheckAtLeast(TestLog *log, PetscReal value, PetscReal bound, const char *fmt, ...)
{
  va_list ap;
  va_start(ap, fmt);
  CheckBoundV(log, value, bound, PETSC_TRUE, fmt, ap);
  va_end(ap);
}

static inline void CheckAtMost(TestLog *log, PetscReal value, PetscReal bound, const char *fmt, ...)
{
  va_list ap;
  va_start(ap, fmt);
  CheckBoundV(log, value, bound, PETSC_FALSE, fmt, ap);
  va_end(ap);
}

/* A condition (deck tests: EXPECT). */
static inline void CheckTrue(TestLog *log, PetscBool ok, const char *fmt, ...)
{
  va_list ap;
  va_start(ap, fmt);
  CheckReport(log, ok, "", fmt, ap);
  va_end(ap);
}

static inline int Summary(const TestLog *log)
{
  printf("%d of %d checks failed\n", (int)log->failures, (int)log->checks);
  return log->failures ? 1 : 0;
}
