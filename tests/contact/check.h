/* The contact unit tests' checks (the shared harness, tests/common/tsl_check.h) and their fixture. */
#pragma once
#include <thermoslide/contact.h>
#include <string.h>
#include "../common/tsl_check.h"

/* The tangent tests' law: penalty normal contact and friction with heat generation (mu 0.3, eps_t 5e3, eta
 * 0.9, f 0.3); open = PETSC_TRUE adds the open state's thermal laws: clearance conductance and gap
 * radiation (the tables live here, the law points at them). */
static inline void TestLawSetUp(TslContactLaw *law, PetscBool open)
{
  static const PetscReal kd[3] = {0, 0.05, 0.2}, kdv[3] = {50, 30, 4}, Fd[2] = {0, 0.1}, Fv[2] = {1, 0.5};

  PetscCallAbort(PETSC_COMM_SELF, TslContactLawSetDefaults(law));
  law->eps_n      = 2e4;
  law->mu         = 0.3;
  law->eps_t      = 5e3;
  law->eta        = 0.9;
  law->f          = 0.3;
  law->theta_zero = -273.16;
  if (!open) return;
  law->conductance   = TSL_CONTACT_CONDUCTANCE_CLEARANCE;
  law->k_n           = 3;
  law->k_arg         = kd;
  law->k_value       = kdv;
  law->F_n           = 2;
  law->F_clearance   = Fd;
  law->F_value       = Fv;
  law->sigma         = 5.67e-8;
  law->eps_main      = 0.8;
  law->eps_secondary = 0.6;
  law->friction      = TSL_CONTACT_FRICTION_PENALTY;
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

/* A consistent tangent K against its central-difference estimate Kfd (nd x nd, row-major), block by block:
 * kind[i] (0 .. nkind-1) says what unknown i is (u, theta, phi), each block relative to its own scale (an
 * element's force, heat and moment rows differ by orders), and a block that finite differences find empty
 * (e.g. u-theta: contact forces do not depend on temperature) must be empty in K too. */
static inline void CheckTangentBlocks(TestLog *log, const char *name, PetscInt nd, const PetscReal K[], const PetscReal Kfd[], const PetscInt kind[],
                                      PetscInt nkind, const char *const kname[])
{
  for (PetscInt bi = 0; bi < nkind; bi++)
    for (PetscInt bj = 0; bj < nkind; bj++) {
      PetscReal scale = 0, err = 0, all = 0;

      for (PetscInt i = 0; i < nd; i++)
        for (PetscInt j = 0; j < nd; j++) {
          all = PetscMax(all, PetscAbsReal(Kfd[i * nd + j]));
          if (kind[i] != bi || kind[j] != bj) continue;
          scale = PetscMax(scale, PetscAbsReal(Kfd[i * nd + j]));
          err   = PetscMax(err, PetscAbsReal(K[i * nd + j] - Kfd[i * nd + j]));
        }
      if (scale <= 1e-12 * all)
        Check(log, err, 0, 1e-9 * all, "%s: %s-%s block empty (|K| vs overall scale)", name, kname[bi], kname[bj]);
      else
        Check(log, err / scale, 0, 1e-6, "%s: %s-%s block, max|K - K_fd| / max|K_fd| (scale %.3g)", name, kname[bi], kname[bj], (double)scale);
    }
}
