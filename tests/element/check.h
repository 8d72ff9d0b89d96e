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

static inline int Summary(const TestLog *log)
{
  printf("%d of %d checks failed\n", (int)log->failures, (int)log->checks);
  return log->failures ? 1 : 0;
}
