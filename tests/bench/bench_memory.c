/* What the machine's memory allows, per rank and in all: the ceiling under the implicit solve, whose
 * AMG cycles, Krylov vectors and matrix-vector products stream far more data than they compute on
 * (docs/running.md "What bounds the 2-rank speed-up"). Run on 1 and then on 2 ranks and compare:
 *   - triad: y = a + s b over three vectors of 320 MB each (STREAM's triad; 24 bytes per entry);
 *   - AIJ MatMult: PETSc's product with a 27-point, 4-unknowns-per-node matrix laid out as thermoslide's
 *     Jacobian (node-interleaved, 108 nonzeros per interior row) on a 2N x N x N block of nodes, counted as
 *     12 bytes per nonzero (value and column index).
 * Each figure is the best of 10 repetitions between barriers. Figures only (ctest -L bench).
 * usage: mpirun -n P bench_memory [-n N (default 40: 545 k rows, 57 M nonzeros)] */
#include <petscmat.h>

static double Best(double t, double best)
{
  return t < best ? t : best;
}

static PetscErrorCode Triad(MPI_Comm comm, PetscMPIInt size)
{
  const PetscInt n = 40000000;
  PetscScalar   *a, *b, *c, check = 0;
  double         best = 1e30;

  PetscFunctionBeginUser;
  PetscCall(PetscMalloc3(n, &a, n, &b, n, &c));
  for (PetscInt i = 0; i < n; i++) a[i] = 1, b[i] = 2, c[i] = 0;
  for (PetscInt k = 0; k < 10; k++) {
    double t;
    PetscCallMPI(MPI_Barrier(comm));
    t = MPI_Wtime();
    for (PetscInt i = 0; i < n; i++) c[i] = a[i] + 1.5 * b[i];
    PetscCallMPI(MPI_Barrier(comm));
    best = Best(MPI_Wtime() - t, best);
  }
  for (PetscInt i = 0; i < n; i += 4096) check += c[i];
  PetscCheck(check == 4.0 * ((n + 4095) / 4096), PETSC_COMM_SELF, PETSC_ERR_PLIB, "triad result wrong");
  PetscCall(PetscPrintf(comm, "ranks %d  triad:       %6.1f GB/s per rank, %6.1f GB/s in all\n", size, 24.0 * n / best / 1e9, size * 24.0 * n / best / 1e9));
  PetscCall(PetscFree3(a, b, c));
  PetscFunctionReturn(0);
}

static PetscErrorCode Product(MPI_Comm comm, PetscMPIInt size, PetscInt N)
{
  const PetscInt bs = 4, nx = 2 * N + 1, ny = N + 1, nz = N + 1, nodes = nx * ny * nz;
  Mat            A;
  Vec            x, y;
  PetscInt       rs, re, cols[27 * 4];
  PetscScalar    v[27 * 4];
  MatInfo        info;
  double         best = 1e30;

  PetscFunctionBeginUser;
  PetscCall(MatCreateAIJ(comm, PETSC_DECIDE, PETSC_DECIDE, nodes * bs, nodes * bs, 27 * bs, NULL, 9 * bs, NULL, &A));
  PetscCall(MatSetOption(A, MAT_NEW_NONZERO_ALLOCATION_ERR, PETSC_FALSE));
  PetscCall(MatGetOwnershipRange(A, &rs, &re));
  for (PetscInt r = rs; r < re; r++) {
    const PetscInt node = r / bs, i = node % nx, j = (node / nx) % ny, k = node / (nx * ny);
    PetscInt       c    = 0;
    for (PetscInt dk = -1; dk <= 1; dk++)
      for (PetscInt dj = -1; dj <= 1; dj++)
        for (PetscInt di = -1; di <= 1; di++) {
          const PetscInt ii = i + di, jj = j + dj, kk = k + dk;
          if (ii < 0 || jj < 0 || kk < 0 || ii >= nx || jj >= ny || kk >= nz) continue;
          for (PetscInt b = 0; b < bs; b++, c++) cols[c] = ((kk * ny + jj) * nx + ii) * bs + b, v[c] = cols[c] == r ? 30.0 : -0.1;
        }
    PetscCall(MatSetValues(A, 1, &r, c, cols, v, INSERT_VALUES));
  }
  PetscCall(MatAssemblyBegin(A, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(A, MAT_FINAL_ASSEMBLY));
  PetscCall(MatCreateVecs(A, &x, &y));
  PetscCall(VecSet(x, 1.0));
  PetscCall(MatMult(A, x, y));
  for (PetscInt k = 0; k < 10; k++) {
    double t;
    PetscCallMPI(MPI_Barrier(comm));
    t = MPI_Wtime();
    PetscCall(MatMult(A, x, y));
    PetscCallMPI(MPI_Barrier(comm));
    best = Best(MPI_Wtime() - t, best);
  }
  PetscCall(MatGetInfo(A, MAT_GLOBAL_SUM, &info));
  PetscCall(PetscPrintf(comm, "ranks %d  AIJ MatMult: %6.1f GB/s in all (%" PetscInt_FMT " rows, %.3g nonzeros, %.4f s per product)\n", size,
                        12 * info.nz_used / best / 1e9, nodes * bs, info.nz_used, best));
  PetscCall(VecDestroy(&x));
  PetscCall(VecDestroy(&y));
  PetscCall(MatDestroy(&A));
  PetscFunctionReturn(0);
}

int main(int argc, char **argv)
{
  PetscInt    N = 40;
  PetscMPIInt size;

  PetscCall(PetscInitialize(&argc, &argv, NULL, NULL));
  PetscCall(PetscOptionsGetInt(NULL, NULL, "-n", &N, NULL));
  PetscCallMPI(MPI_Comm_size(PETSC_COMM_WORLD, &size));
  PetscCall(Triad(PETSC_COMM_WORLD, size));
  PetscCall(Product(PETSC_COMM_WORLD, size, N));
  PetscCall(PetscFinalize());
  return 0;
}
