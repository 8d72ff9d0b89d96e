/* Check printing shared by the element unit tests: one line per check,
 *   name: value (expected, tolerance) PASS/FAIL
 * and a failure count the program turns into its exit status. */
#pragma once
#include <thermoslide/element.h>
#include <stdarg.h>
#include <stdio.h>

typedef struct {
  PetscInt checks, failures;
} TestLog;

/* |value - expected| <= tol passes. */
static inline void Check(TestLog *log, PetscReal value, PetscReal expected, PetscReal tol, const char *fmt, ...)
{
  char      name[256];
  va_list   ap;
  PetscBool ok = (PetscBool)(PetscAbsReal(value - expected) <= tol);

  va_start(ap, fmt);
  vsnprintf(name, sizeof(name), fmt, ap);
  va_end(ap);
  log->checks++;
  if (!ok) log->failures++;
  printf("%s: %.10g (%.10g, %.1e) %s\n", name, (double)value, (double)expected, (double)tol, ok ? "PASS" : "FAIL");
}

/* One-sided checks (rates, ratios, bounds): name: value (>= bound) PASS/FAIL. */
static inline void CheckBoundV(TestLog *log, PetscReal value, PetscReal bound, PetscBool lower, const char *fmt, va_list ap)
{
  char      name[256];
  PetscBool ok = (PetscBool)(lower ? value >= bound : value <= bound);

  vsnprintf(name, sizeof(name), fmt, ap);
  log->checks++;
  if (!ok) log->failures++;
  printf("%s: %.6g (%s %.6g) %s\n", name, (double)value, lower ? ">=" : "<=", (double)bound, ok ? "PASS" : "FAIL");
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

static inline int Summary(const TestLog *log)
{
  printf("%d of %d checks failed\n", (int)log->failures, (int)log->checks);
  return log->failures ? 1 : 0;
}
