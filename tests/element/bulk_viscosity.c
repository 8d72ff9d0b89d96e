/* The bulk viscosity kernel (TslElementBulkViscosity; Abaqus Analysis User's Guide, "Bulk viscosity"):
 *   p = b1 rho c_d L eps_vol_dot + rho (b2 L)^2 |eps_vol_dot| min(0, eps_vol_dot)
 * at the element centre, passed as eta1 = b1 L / c_d and eta2 = (b2 L / c_d)^2. On an undistorted element in
 * a uniform dilatation v = a x (eps_vol_dot = 2a plane, 3a axisymmetric and 3D) the pressure the kernel
 * applies is its power / (eps_vol_dot V): in compression (a < 0) the linear term plus rho (b2 L)^2
 * eps_vol_dot^2, in expansion the linear term alone (and the forces those of the linear term alone); the
 * quadratic term alone gives no force in expansion. The dissipated power is the forces' work on v and is
 * >= 0 for arbitrary velocity fields. */
#include "check.h"

static const PetscReal E = 200e3, NU = 0.3, RHO = 2, LEN = 0.7, B1 = 0.06, B2 = 1.2, THICK = 0.5, THETA0 = 20;

typedef struct {
  const TslElementType *type;
  TslMaterial           mat;
  TslElementSection     sec;
  PetscReal             x[TSL_MAX_ELEM_NODES * 3], u[TSL_MAX_ELEM_DOF], theta_init[TSL_MAX_ELEM_NODES];
  TslElementInput       in;
  PetscReal             volume, eta1, eta2, M;
} Case;

static PetscBool IsAxi(const TslElementType *t)
{
  return t->kin == TSL_KIN_AXISYMMETRIC || t->kin == TSL_KIN_AXISYMMETRIC_TWIST;
}

static void Constant(TslPropertyTable *t, PetscReal v0, PetscReal v1)
{
  t->n           = 1;
  t->value[0][0] = v0, t->value[0][1] = v1;
}

/* The reference element mapped onto [0, 1] in every direction (r in [1, 2] for axisymmetry), at rest and at
 * its initial temperature; the coefficients for a characteristic length LEN: L / c_d = LEN / sqrt(M / rho). */
static PetscErrorCode CaseSetUp(Case *c, const char *name)
{
  PetscInt           k = TslElementTypeFind(name);
  const TslGeometry *g;
  PetscReal          vol[TSL_MAX_ELEM_NODES], dt;

  PetscFunctionBeginUser;
  PetscCheck(k >= 0, PETSC_COMM_SELF, PETSC_ERR_PLIB, "no element type %s", name);
  PetscCall(PetscMemzero(c, sizeof(*c)));
  c->type = TslElementTypeGet(k);
  g       = c->type->geom;
  Constant(&c->mat.prop[TSL_PROP_ELASTIC], E, NU);
  Constant(&c->mat.prop[TSL_PROP_CONDUCTIVITY], 10, 0);
  Constant(&c->mat.prop[TSL_PROP_DENSITY], RHO, 0);
  Constant(&c->mat.prop[TSL_PROP_SPECIFIC_HEAT], 3, 0);
  c->sec = (TslElementSection){&c->mat, THICK, 0, 0, 0};
  for (PetscInt a = 0; a < g->nnode; a++) {
    for (PetscInt d = 0; d < c->type->dim; d++) c->x[3 * a + d] = 0.5 * (g->node_xi[a][d] + 1);
    if (IsAxi(c->type)) c->x[3 * a] += 1;
    c->theta_init[a]                            = THETA0;
    c->u[c->type->ndof * a + c->type->ndof - 1] = THETA0;
  }
  c->in = (TslElementInput){.type = c->type, .sec = &c->sec, .x = c->x, .u = c->u, .theta_init = c->theta_init};
  PetscCall(TslElementNodalVolume(&c->in, vol));
  for (PetscInt a = 0; a < g->nnode; a++) c->volume += vol[a];
  c->M    = E * (1 - NU) / ((1 + NU) * (1 - 2 * NU)); /* lambda + 2 mu (plane strain, axisymmetric, 3D) */
  dt      = LEN / PetscSqrtReal(c->M / RHO);
  c->eta1 = B1 * dt;
  c->eta2 = PetscSqr(B2 * dt);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Nodal velocities of the uniform dilatation v = a x (temperature slots 0); returns eps_vol_dot. */
static PetscReal Dilatation(const Case *c, PetscReal a, PetscReal v[])
{
  const PetscInt ndof = c->type->ndof;
  for (PetscInt i = 0; i < TslElementTypeNodes(c->type) * ndof; i++) v[i] = 0;
  for (PetscInt n = 0; n < c->type->geom->nnode; n++)
    for (PetscInt d = 0; d < c->type->dim; d++) v[ndof * n + d] = a * c->x[3 * n + d];
  return (c->type->dim == 3 || IsAxi(c->type)) ? 3 * a : 2 * a;
}

static PetscReal Dot(const Case *c, const PetscReal R[], const PetscReal v[])
{
  PetscReal s = 0;
  for (PetscInt i = 0; i < TslElementTypeNodes(c->type) * c->type->ndof; i++) s += R[i] * v[i];
  return s;
}

static PetscReal MaxDiff(const Case *c, const PetscReal A[], const PetscReal B[], PetscReal scale)
{
  PetscReal m = 0;
  for (PetscInt i = 0; i < TslElementTypeNodes(c->type) * c->type->ndof; i++) m = PetscMax(m, PetscAbsReal(A[i] - scale * B[i]));
  return m;
}

static PetscErrorCode Viscosity(Case *c, const PetscReal v[], PetscReal eta1, PetscReal eta2, PetscReal R[], PetscReal *power)
{
  PetscFunctionBeginUser;
  for (PetscInt i = 0; i < TslElementTypeNodes(c->type) * c->type->ndof; i++) R[i] = 0;
  PetscCall(TslElementBulkViscosity(&c->in, v, eta1, eta2, R, power, NULL));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode CheckType(TestLog *log, const char *name)
{
  Case      c;
  PetscReal v[TSL_MAX_ELEM_DOF], R[TSL_MAX_ELEM_DOF], Rlin[TSL_MAX_ELEM_DOF], w, wlin, rate, cd, p1, p2;

  PetscFunctionBeginUser;
  PetscCall(CaseSetUp(&c, name));
  cd = PetscSqrtReal(c.M / RHO);

  /* compression: the linear term plus rho (b2 L)^2 eps^2 */
  rate = Dilatation(&c, -0.3, v);
  p1   = B1 * RHO * cd * LEN * rate;
  p2   = -RHO * PetscSqr(B2 * LEN) * rate * rate;
  PetscCall(Viscosity(&c, v, c.eta1, c.eta2, R, &w));
  PetscCall(Viscosity(&c, v, c.eta1, 0, Rlin, &wlin));
  CheckRel(log, w / (rate * c.volume), p1 + p2, 1e-12, 0, "%s compression: pressure = b1 rho c_d L eps + rho (b2 L)^2 |eps| eps", name);
  CheckRel(log, wlin / (rate * c.volume), p1, 1e-12, 0, "%s compression, b2 = 0: pressure = b1 rho c_d L eps", name);
  CheckRel(log, Dot(&c, R, v), w, 1e-12, 0, "%s compression: the forces' work on v = the dissipated power", name);
  Check(log, MaxDiff(&c, R, Rlin, (p1 + p2) / p1), 0, 1e-12 * MaxDiff(&c, R, R, 0), "%s compression: forces = linear forces x (p1 + p2) / p1", name);
  CheckAtLeast(log, w, 0, "%s compression: dissipated power", name);
  PetscCall(Viscosity(&c, v, 0, c.eta2, R, &w));
  CheckRel(log, w / (rate * c.volume), p2, 1e-12, 0, "%s compression, b1 = 0: pressure = rho (b2 L)^2 |eps| eps", name);

  /* expansion: the linear term alone */
  rate = Dilatation(&c, 0.3, v);
  p1   = B1 * RHO * cd * LEN * rate;
  PetscCall(Viscosity(&c, v, c.eta1, c.eta2, R, &w));
  PetscCall(Viscosity(&c, v, c.eta1, 0, Rlin, &wlin));
  CheckRel(log, w / (rate * c.volume), p1, 1e-12, 0, "%s expansion: pressure = b1 rho c_d L eps only", name);
  Check(log, MaxDiff(&c, R, Rlin, 1), 0, 0, "%s expansion: forces identical to b2 = 0", name);
  CheckAtLeast(log, w, 0, "%s expansion: dissipated power", name);
  PetscCall(Viscosity(&c, v, 0, c.eta2, R, &w));
  Check(log, MaxDiff(&c, R, R, 0) + PetscAbsReal(w), 0, 0, "%s expansion, b1 = 0: no force, no power", name);

  /* arbitrary velocities (shear, rotation and dilatation mixed): power >= 0 and the forces' work on v */
  for (PetscInt k = 0; k < 8; k++) {
    for (PetscInt i = 0; i < TslElementTypeNodes(c.type) * c.type->ndof; i++)
      v[i] = (i % c.type->ndof == c.type->ndof - 1) ? 0 : PetscSinReal(1.7 * i + 2.3 * k + 0.4) * (1 + k);
    PetscCall(Viscosity(&c, v, c.eta1, c.eta2, R, &w));
    CheckAtLeast(log, w, 0, "%s velocity field %" PetscInt_FMT ": dissipated power", name, k);
    CheckRel(log, Dot(&c, R, v), w, 1e-12, 1e-30, "%s velocity field %" PetscInt_FMT ": the forces' work on v = the power", name, k);
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

int main(int argc, char **argv)
{
  TestLog     log     = {0, 0};
  const char *types[] = {"CPE4T", "CAX4T", "C3D8T", "C3D8RT", "C3D10MT"};

  PetscCall(PetscInitialize(&argc, &argv, NULL, NULL));
  for (size_t i = 0; i < sizeof(types) / sizeof(types[0]); i++) PetscCall(CheckType(&log, types[i]));
  PetscCall(PetscFinalize());
  return Summary(&log);
}
