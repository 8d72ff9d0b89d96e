/* Lanes: the explicit force records are evaluated TSL_FAST_LANES elements at a time (element.h), every
 * real a vector of the batch's values. Internal to the element kernels (src/element/fast.c) and the
 * explicit loop's gather and scatter (src/physics/dynamics.c), which share these helpers:
 *   TslV, TslVI   the vector of lanes (GCC/Clang vector extensions) and its integer mask type
 *   TslLd, TslSt  an unaligned load/store of a vector
 *   TSL_TRANSPOSE4 4 x 4 transpose: four nodal rows of four unknowns <-> four lane vectors per unknown
 *   TSL_CLONES    a function compiled three times, for x86-64-v4 (AVX-512: the same 256-bit vectors, but 32
 *                 registers instead of 16, so fewer spills), x86-64-v3 (AVX2, FMA) and the baseline, the
 *                 loader picking the best one the machine runs (GCC function multi-versioning): a Debian
 *                 build stays portable and still uses the wide registers. The v4 and v3 clones give the same
 *                 bits (the same vector operations and FMA contractions; HDF5 of the explicit benchmark's
 *                 blocks compared at tolerance 0). */
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
/* The same on an address aligned to the vector's size (a batch's own arrays, declared TSL_LANES_ALIGNED): one
 * full-width move. memcpy of an unaligned vector is split into two halves under GCC's generic tuning, and a
 * vector stored in halves and reloaded whole stalls on store forwarding (the explicit scatter's transposes
 * spent a third of their time there). */
#define TSL_LANES_ALIGNED __attribute__((aligned(TSL_FAST_LANES * sizeof(PetscReal))))
static inline __attribute__((always_inline)) TslV TslLdA(const PetscReal *p)
{
  return *(const TslV *)__builtin_assume_aligned(p, sizeof(TslV));
}
static inline __attribute__((always_inline)) void TslStA(PetscReal *p, TslV v)
{
  *(TslV *)__builtin_assume_aligned(p, sizeof(TslV)) = v;
}

#if defined(__has_builtin)
#if __has_builtin(__builtin_shufflevector) && TSL_FAST_LANES == 4
#define TSL_HAVE_TRANSPOSE4 1
/* r0..r3 -> c0..c3 with c_i[j] = r_j[i], declaring c0..c3. A macro on named values rather than a function on
 * arrays: GCC kept arrays of vectors in memory and copied them in halves under its generic tuning, and the
 * whole-vector reloads then stalled on store forwarding (a third of the explicit gather's and scatter's time). */
#define TSL_TRANSPOSE4(r0, r1, r2, r3, c0, c1, c2, c3)                                                                                               \
  const TslV c0##_t0 = __builtin_shufflevector(r0, r1, 0, 4, 2, 6), c0##_t1 = __builtin_shufflevector(r0, r1, 1, 5, 3, 7);                           \
  const TslV c0##_t2 = __builtin_shufflevector(r2, r3, 0, 4, 2, 6), c0##_t3 = __builtin_shufflevector(r2, r3, 1, 5, 3, 7);                           \
  const TslV c0 = __builtin_shufflevector(c0##_t0, c0##_t2, 0, 1, 4, 5), c1 = __builtin_shufflevector(c0##_t1, c0##_t3, 0, 1, 4, 5);                 \
  const TslV c2 = __builtin_shufflevector(c0##_t0, c0##_t2, 2, 3, 6, 7), c3 = __builtin_shufflevector(c0##_t1, c0##_t3, 2, 3, 6, 7)
#endif
#endif

#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && defined(__linux__)
#define TSL_CLONES __attribute__((target_clones("arch=x86-64-v4", "arch=x86-64-v3", "default")))
#else
#define TSL_CLONES
#endif
