/* Private to contact/: forward-mode dual numbers used to linearise the contact element.
 *
 * Why dual numbers: the residual of a node-to-segment element depends on the unknowns through the
 * smoothed normal, the implicit projection xi(u), the return mapping and the thermal laws. Writing that
 * chain by hand is long and fragile; carrying the derivatives with every operation gives the exact
 * (consistent, unsymmetric) tangent at a small fixed cost (TSL_DUAL_N flops per operation), and the unit
 * tests still compare it against finite differences.
 *
 * Slots 0..TSL_CONTACT_MAX_DOF-1 are the element unknowns, slot TSL_DUAL_XI is the projection parameter xi
 * (used to get dF/dxi in the projection Newton iteration and the implicit derivative dxi/du). */
#pragma once
#include <thermoslide/contact.h>

#define TSL_DUAL_XI TSL_CONTACT_MAX_DOF
#define TSL_DUAL_N  (TSL_CONTACT_MAX_DOF + 1)

typedef struct {
  PetscReal v;
  PetscReal d[TSL_DUAL_N];
} TslDual;

static inline TslDual DConst(PetscReal v)
{
  TslDual r;
  r.v = v;
  for (PetscInt i = 0; i < TSL_DUAL_N; i++) r.d[i] = 0;
  return r;
}

/* A variable with value v seeded in slot (slot < 0: constant). */
static inline TslDual DVar(PetscReal v, PetscInt slot)
{
  TslDual r = DConst(v);
  if (slot >= 0) r.d[slot] = 1;
  return r;
}

static inline TslDual DAdd(TslDual a, TslDual b)
{
  a.v += b.v;
  for (PetscInt i = 0; i < TSL_DUAL_N; i++) a.d[i] += b.d[i];
  return a;
}

static inline TslDual DSub(TslDual a, TslDual b)
{
  a.v -= b.v;
  for (PetscInt i = 0; i < TSL_DUAL_N; i++) a.d[i] -= b.d[i];
  return a;
}

static inline TslDual DScale(PetscReal s, TslDual a)
{
  a.v *= s;
  for (PetscInt i = 0; i < TSL_DUAL_N; i++) a.d[i] *= s;
  return a;
}

static inline TslDual DAddC(TslDual a, PetscReal c)
{
  a.v += c;
  return a;
}

static inline TslDual DMul(TslDual a, TslDual b)
{
  TslDual r;
  r.v = a.v * b.v;
  for (PetscInt i = 0; i < TSL_DUAL_N; i++) r.d[i] = a.d[i] * b.v + a.v * b.d[i];
  return r;
}

static inline TslDual DDiv(TslDual a, TslDual b)
{
  TslDual   r;
  PetscReal ib = 1 / b.v;
  r.v          = a.v * ib;
  for (PetscInt i = 0; i < TSL_DUAL_N; i++) r.d[i] = (a.d[i] - r.v * b.d[i]) * ib;
  return r;
}

static inline TslDual DSqrt(TslDual a)
{
  TslDual   r;
  PetscReal s = PetscSqrtReal(a.v);
  r.v         = s;
  for (PetscInt i = 0; i < TSL_DUAL_N; i++) r.d[i] = a.d[i] / (2 * s);
  return r;
}

/* f(a) with f(a.v) = fv and f'(a.v) = df: chain rule for tabulated or scalar functions. */
static inline TslDual DChain(TslDual a, PetscReal fv, PetscReal df)
{
  TslDual r;
  r.v = fv;
  for (PetscInt i = 0; i < TSL_DUAL_N; i++) r.d[i] = df * a.d[i];
  return r;
}

static inline TslDual DPow4(TslDual a)
{
  PetscReal a3 = a.v * a.v * a.v;
  return DChain(a, a3 * a.v, 4 * a3);
}

/* Linear combination of two dual vectors stored as [2] arrays. */
static inline TslDual DDot(const TslDual a[2], const TslDual b[2])
{
  return DAdd(DMul(a[0], b[0]), DMul(a[1], b[1]));
}

/* Geometry of one element in dual numbers (current coordinates of all nodes present, relative to the
 * reference position of m1). The neighbouring segments are stored whole, in their face order, the node
 * they share with this segment being a copy of ours (prev[1] = seg[0], next[0] = seg[1]). */
typedef struct {
  const TslContactFace *face;
  TslDual               xs[2];
  TslDual               seg[TSL_CONTACT_MAX_FACE_NODES][2], prev[TSL_CONTACT_MAX_FACE_NODES][2], next[TSL_CONTACT_MAX_FACE_NODES][2];
  PetscBool             has_prev, has_next;
  PetscReal             s;  /* smoothing fraction */
  PetscInt              nu; /* unknowns per node: node k's u_x, u_y are seeded in slots nu k, nu k + 1 */
} TslContactGeom;

/* Position x_m and tangent t = dx_m/dxi of a segment (face nodes x[nnode][2]) at dual parameter xi. */
void TslContactFacePointDual(const TslContactFace *face, const TslDual x[][2], TslDual xi, TslDual p[2], TslDual t[2]);

/* Position x_m (may be NULL), smoothed unit normal n and tangent tau = (-n_y, n_x) of the segment at dual
 * parameter xi (kinematics.c). */
void TslContactSurfaceDual(const TslContactGeom *geo, TslDual xi, TslDual x[2], TslDual n[2], TslDual tau[2]);

/* Solves the projection: returns xi as a dual carrying dxi/du (zero when clamped), and the unclamped value. */
PetscErrorCode TslContactProjectDual(const TslContactGeom *geo, TslDual *xi, PetscReal *xi_raw);

/* Builds the geometry from the input; seed = PETSC_TRUE seeds the displacement unknowns in their slots
 * (nu k + d for node k, nu = TslContactNodeUnknowns(in->kin)). */
PetscErrorCode TslContactGeomSetUp(const TslContactInput *in, PetscBool seed, TslContactGeom *geo, PetscInt *nnode);
