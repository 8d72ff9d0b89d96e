/* The explicit stable increment's eigenvalue (src/sys/eigen.c, TslLargestEigenvalue) against LAPACK's syev:
 * on symmetric matrices of 1 to 32 rows (random, positive semi-definite as an element stiffness is,
 * indefinite, diagonal, with repeated and zero eigenvalues, scaled by 1e-30 and 1e+30), the value is never
 * below syev's largest eigenvalue and at most 2e-12 of the spectrum's scale above it. */
#include "check.h"
#include <thermoslide/sys.h>
#include <petscblaslapack.h>

/* Largest eigenvalue by LAPACK (A not changed). */
static PetscErrorCode Reference(PetscInt n, const PetscReal A[], PetscReal *lmax, PetscReal *scale)
{
  PetscReal    S[TSL_EIGEN_MAX_N * TSL_EIGEN_MAX_N], ev[TSL_EIGEN_MAX_N], work[8 * TSL_EIGEN_MAX_N];
  PetscBLASInt bn, lwork = 8 * TSL_EIGEN_MAX_N, info;

  PetscFunctionBeginUser;
  PetscCall(PetscBLASIntCast(n, &bn));
  PetscCall(PetscArraycpy(S, A, n * n));
  PetscCallBLAS("LAPACKsyev", LAPACKsyev_("N", "U", &bn, S, &bn, ev, work, &lwork, &info));
  PetscCheck(!info, PETSC_COMM_SELF, PETSC_ERR_LIB, "syev failed");
  *lmax  = ev[n - 1];
  *scale = PetscMax(PetscAbsReal(ev[0]), PetscAbsReal(ev[n - 1]));
  PetscFunctionReturn(PETSC_SUCCESS);
}

int main(int argc, char **argv)
{
  TestLog   log = {0, 0};
  PetscReal worst_above = 0, worst_below = 0;
  unsigned  seed = 12345;

  PetscCall(PetscInitialize(&argc, &argv, NULL, NULL));
  for (PetscInt kind = 0; kind < 6; kind++)
    for (PetscInt n = 1; n <= 32; n++) {
      PetscReal A[TSL_EIGEN_MAX_N * TSL_EIGEN_MAX_N], B[TSL_EIGEN_MAX_N * TSL_EIGEN_MAX_N], S[TSL_EIGEN_MAX_N * TSL_EIGEN_MAX_N], lmax = 0, scale = 0, l;
      const PetscReal f = kind == 4 ? 1e-30 : kind == 5 ? 1e30 : 1;
      for (PetscInt i = 0; i < n * n; i++) {
        seed = seed * 1103515245u + 12345u;
        B[i] = ((seed >> 8) & 0xffff) / 32768.0 - 1;
      }
      for (PetscInt i = 0; i < n; i++)
        for (PetscInt j = 0; j < n; j++) {
          PetscReal v = 0;
          if (kind == 0 || kind >= 4) /* B^T B with a null space (rank n - 1 at most): an element stiffness */
            for (PetscInt k = 0; k + 1 < n; k++) v += B[k * n + i] * B[k * n + j];
          else if (kind == 1) v = 0.5 * (B[i * n + j] + B[j * n + i]); /* indefinite */
          else if (kind == 2) v = i == j ? (PetscReal)(i % 3) : 0;     /* diagonal, repeated eigenvalues, zeros */
          else v = i == j ? 2 : (j == i + 1 || i == j + 1 ? -1 : 0);   /* the 1D Laplacian */
          A[i * n + j] = f * v;
        }
      PetscCall(Reference(n, A, &lmax, &scale));
      PetscCall(PetscArraycpy(S, A, n * n));
      l = TslLargestEigenvalue(n, S);
      if (scale > 0) {
        worst_above = PetscMax(worst_above, (l - lmax) / scale);
        worst_below = PetscMax(worst_below, (lmax - l) / scale);
      } else
        worst_above = PetscMax(worst_above, PetscAbsReal(l) > 1e-300 ? 1.0 : 0.0);
    }
  CheckAtMost(&log, worst_below, 0.0, "never below LAPACK's largest eigenvalue (largest shortfall relative to the spectrum's scale)");
  CheckAtMost(&log, worst_above, 2e-12, "above it by at most 2e-12 of the spectrum's scale");
  PetscCall(PetscFinalize());
  return log.failures ? 1 : 0;
}
