/* thermoslide step procedures: increments, Newton (SNES), cutback, output.
 *
 * Run-time options (PETSc options database):
 *   -tsl_rtol <1e-9>       Newton: per-field residual reduction (displacement and temperature rows separately)
 *   -tsl_atol_rel <1e-8>   Newton: per-field residual below this fraction of the largest residual seen in the job
 *   -tsl_cutback <0.25>    increment factor after a failed increment
 *   -tsl_growth <1.5>      increment factor after an increment that needed at most -tsl_easy_its Newton iterations
 *   -tsl_easy_its <5>
 * Solver defaults (overridable with the usual PETSc options): -snes_type newtonls -snes_linesearch_type basic
 * -ksp_type fgmres -ksp_rtol 1e-10 -pc_type fieldsplit (splits "T" then "u", multiplicative), each split
 * -fieldsplit_X_ksp_type preonly -fieldsplit_X_pc_type hypre (BoomerAMG).
 */
#pragma once
#include <thermoslide/problem.h>

/* Runs every step of the model. Output goes to dir/jobname.{h5,xmf,csv}. Increments end on the corners of
 * the amplitudes a step follows. Any failure is the same on all ranks (sys.h); after one, the last
 * converged state is saved (as jobname.failed.* beside earlier results, nothing if no increment
 * converged; docs/output.md) and the error is returned (PETSC_ERR_NOT_CONVERGED at the minimum
 * increment). */
PetscErrorCode TslAnalysisRun(TslProblem prob, const char *dir, const char *jobname);

/* Calls a function that may fail on some ranks only, and turns its failure into an error on all ranks
 * (so no rank waits forever in a collective call). The original message is printed by the failing rank. */
#define TslCallCollective(comm, call)                                                                                                                \
  do {                                                                                                                                               \
    PetscErrorCode tsl_ierr_ = (call), tsl_gerr_ = 0;                                                                                                \
    PetscCallMPI(MPI_Allreduce(&tsl_ierr_, &tsl_gerr_, 1, MPI_INT, MPI_MAX, (comm)));                                                                \
    if (tsl_gerr_) SETERRQ((comm), tsl_gerr_, " ");                                                                                                  \
  } while (0)
