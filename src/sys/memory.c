/* Large new arrays faulted in by one system call (include/thermoslide/sys.h). */
#define _DEFAULT_SOURCE
#include <thermoslide/sys.h>
#include <stdint.h>
#include <sys/mman.h>
#include <unistd.h>

#ifndef MADV_POPULATE_WRITE
#define MADV_POPULATE_WRITE 23 /* Linux 5.14; an older kernel rejects it (EINVAL), and the pages fault in as before */
#endif

void TslPrefault(void *p, size_t bytes)
{
  static uintptr_t page;
  uintptr_t        a, b;

  if (!p || bytes < ((size_t)4 << 20)) return;
  if (!page) page = (uintptr_t)sysconf(_SC_PAGESIZE);
  if (!page || page & (page - 1)) return;
  a = ((uintptr_t)p + page - 1) & ~(page - 1);
  b = ((uintptr_t)p + bytes) & ~(page - 1);
  if (b > a) (void)madvise((void *)a, (size_t)(b - a), MADV_POPULATE_WRITE);
}
