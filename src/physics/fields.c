/* Output fields of the current state: nodal (owned nodes) and element values. */
#include "problem_impl.h"
#include <string.h>

/* Node fields: U (3 comps, z = 0 in 2D), NT, RF (3), RFL, and the contact fields CPRESS, CSLIP,
 * CSTATUS, HFLA (see contact.c). RF/RFL are the unconstrained residual at
 * prescribed dofs, as computed by the last TslProblemHeatBalance; zero elsewhere. */
PetscErrorCode TslProblemNodeField(TslProblem p, const char *name, PetscInt *ncomp, PetscReal **vals)
{
  const PetscScalar *x;
  PetscBool          is_u = !strcmp(name, "U"), is_nt = !strcmp(name, "NT"), is_rf = !strcmp(name, "RF"), is_rfl = !strcmp(name, "RFL");
  Vec                src = (is_rf || is_rfl) ? p->Rraw : p->X;

  PetscFunctionBeginUser;
  if (!strcmp(name, "CPRESS") || !strcmp(name, "CSLIP") || !strcmp(name, "CSTATUS") || !strcmp(name, "HFLA")) {
    *ncomp = 1;
    PetscCall(PetscCalloc1(p->nown, vals));
    PetscCall(TslProblemContactNodeField(p, name, *vals));
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  PetscCheck(is_u || is_nt || is_rf || is_rfl, PETSC_COMM_SELF, PETSC_ERR_ARG_WRONG, "unknown node field %s", name);
  *ncomp = (is_u || is_rf) ? 3 : 1;
  PetscCall(PetscCalloc1(p->nown * *ncomp, vals));
  PetscCall(VecGetArrayRead(src, &x));
  for (PetscInt n = 0; n < p->nown; n++) {
    PetscInt d = n * p->ndof;
    if (is_u) {
      for (PetscInt c = 0; c < p->dim; c++) (*vals)[3 * n + c] = PetscRealPart(x[d + c]);
    } else if (is_nt) {
      (*vals)[n] = PetscRealPart(x[d + p->dim]);
    } else if (is_rf) {
      for (PetscInt c = 0; c < p->dim; c++) (*vals)[3 * n + c] = p->bc[d + c].active ? PetscRealPart(x[d + c]) : 0;
    } else {
      (*vals)[n] = p->bc[d + p->dim].active ? PetscRealPart(x[d + p->dim]) : 0;
    }
  }
  PetscCall(VecRestoreArrayRead(src, &x));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Element fields: S and E (6 comps, Voigt 11 22 33 12 13 23), HFL (3): integration-point averages. */
PetscErrorCode TslProblemElementField(TslProblem p, const char *name, PetscInt *ncomp, PetscReal **vals)
{
  const TslModel    *m = p->m;
  Vec                xl;
  const PetscScalar *xa;
  PetscInt           which = !strcmp(name, "S") ? 0 : !strcmp(name, "E") ? 1 : !strcmp(name, "HFL") ? 2 : -1;

  PetscFunctionBeginUser;
  PetscCheck(which >= 0, PETSC_COMM_SELF, PETSC_ERR_ARG_WRONG, "unknown element field %s", name);
  *ncomp = which == 2 ? 3 : 6;
  PetscCall(PetscCalloc1(m->nelem * *ncomp, vals));
  PetscCall(TslProblemGetLocalSolution(p, &xl, &xa));
  for (PetscInt e = 0; e < m->nelem; e++) {
    PetscReal   S[6], E[6], H[3];
    TslElemData d;
    TslProblemGather(p, e, xa, xa, &d);
    d.in.steady = PETSC_TRUE;
    PetscCall(TslElementOutput(&d.in, S, E, H));
    for (PetscInt c = 0; c < *ncomp; c++) (*vals)[e * *ncomp + c] = which == 0 ? S[c] : which == 1 ? E[c] : H[c];
  }
  PetscCall(TslProblemRestoreLocalSolution(p, &xl, &xa));
  PetscFunctionReturn(PETSC_SUCCESS);
}
