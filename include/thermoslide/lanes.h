/* Lanes: the explicit force records are evaluated TSL_FAST_LANES elements at a time (element.h), every
 * real a vector of the batch's values. Internal to the element kernels (src/element/fast.c) and the
 * explicit loop's gather and scatter (src/physics/dynamics.c), which share these helpers:
 *   TslV, TslVI   the vector of lanes (GCC/Clang vector extensions) and its integer mask type
 *   TslLd, TslSt  an unaligned load/store of a vector
 *   TslTranspose4 4 x 4 transpose: four nodal rows of four unknowns <-> four lane vectors per unknown
 *   TSL_CLONES    a function compiled twice, for x86-64-v3 (AVX2, FMA) and the baseline, the loader picking
 *                 the one the machine runs (GCC function multi-versioning): a Debian build stays portable
 *                 and still uses the wide registers. */
#pragma once
#include <thermoslide/element.h>
#include <string.h>

#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wpsabi" /* the helpers below are always inlined: no vector crosses a call */
#endif
typedef PetscReal TslV __attribute__((vector_size(TSL_FAST_LANES * sizeof(PetscReal))));
typedef long long TslVI __attribute__((vector_size(TSL_FAST_LANES * sizeof(PetscReal))));

static inline __attribute__((always_inline)) TslV TslLd(const PetscReal *p)
{
  TslV v;
  memcpy(&v, p, sizeof(v));
  return v;
}
static inline __attribute__((always_inline)) void TslSt(PetscReal *p, TslV v) { memcpy(p, &v, sizeof(v)); }

#if defined(__has_builtin)
#if __has_builtin(__builtin_shufflevector) && TSL_FAST_LANES == 4
#define TSL_HAVE_TRANSPOSE4 1
/* r[0..3] -> c[0..3] with c[i][j] = r[j][i] */
static inline __attribute__((always_inline)) void TslTranspose4(const TslV r[4], TslV c[4])
{
  const TslV t0 = __builtin_shufflevector(r[0], r[1], 0, 4, 2, 6), t1 = __builtin_shufflevector(r[0], r[1], 1, 5, 3, 7);
  const TslV t2 = __builtin_shufflevector(r[2], r[3], 0, 4, 2, 6), t3 = __builtin_shufflevector(r[2], r[3], 1, 5, 3, 7);
  c[0] = __builtin_shufflevector(t0, t2, 0, 1, 4, 5), c[1] = __builtin_shufflevector(t1, t3, 0, 1, 4, 5);
  c[2] = __builtin_shufflevector(t0, t2, 2, 3, 6, 7), c[3] = __builtin_shufflevector(t1, t3, 2, 3, 6, 7);
}
#endif
#endif

#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && defined(__linux__)
#define TSL_CLONES __attribute__((target_clones("arch=x86-64-v3", "default")))
#else
#define TSL_CLONES
#endif
