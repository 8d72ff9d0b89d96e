/* Private to contact/: forward-mode dual numbers used to linearise the contact element.
 *
 * Why dual numbers: the residual of a node-to-segment element depends on the unknowns through the
 * smoothed normal, the implicit projection xi(u), the return mapping and the thermal laws. Writing that
 * chain by hand is long and fragile; carrying the derivatives with every operation gives the exact
 * (consistent, unsymmetric) tangent at a small fixed cost (TSL_DUAL_N flops per operation), and the unit
 * tests still compare it against finite differences.
 *
 * Slot TSL_DUAL_XI (0) is the projection parameter xi (used to get dF/dxi in the projection Newton
 * iteration and the implicit derivative dxi/du), slot TSL_DUAL_ETA (1) the second surface parameter of the
 * 3D faces (unused, always zero, in 2D), and slots TSL_DUAL_DOF + j the element unknowns j. Each slot is
 * computed on its own, so a slot more or less leaves every other derivative unchanged to the last bit.
 *
 * The kernels are compiled three times (contact/variant.h): as they are, for the tangent of any element; for
 * values alone with the two surface parameters' slots only (contact/values/: TSL_DUAL_VALUES, TSL_DUAL_N = 2),
 * so that an evaluation without a tangent (explicit steps, residual evaluations, the search's projections)
 * neither computes nor copies the unknowns' derivatives; and for the tangent of an element with at most
 * TSL_DUAL_SHORT_DOF unknowns (contact/short/: TSL_DUAL_SHORT), whose derivatives need no more slots. The same
 * operations on the slots in use give the same bits. Seeds of slots beyond TSL_DUAL_N are ignored. */
#pragma once
#include <thermoslide/contact.h>

#define TSL_DUAL_XI  0
#define TSL_DUAL_ETA 1
#define TSL_DUAL_DOF 2 /* slot of the element's unknown 0 */
#define TSL_DUAL_SHORT_DOF 20 /* 2D linear faces (5 nodes with the neighbours, 4 unknowns with twist), 3D quad4 faces */
#if defined(TSL_DUAL_VALUES)
  #define TSL_DUAL_N TSL_DUAL_DOF
#elif defined(TSL_DUAL_SHORT)
  #define TSL_DUAL_N (TSL_DUAL_DOF + TSL_DUAL_SHORT_DOF)
#else
  #define TSL_DUAL_N (TSL_DUAL_DOF + TSL_CONTACT_MAX_DOF)
#endif

#if !defined(TSL_DUAL_VALUES)
/* The values' copies (contact/values/values.h) that the public entries hand a call without a tangent to. */
PetscErrorCode TslContactElement_Values(const TslContactLaw *law, const TslContactInput *in, PetscReal R[], PetscReal K[], TslContactOutput *out);
PetscErrorCode TslContactProject3Raw(const TslContactInput3 *in, PetscReal raw[2], PetscBool *frozen);
PetscErrorCode TslContactProject3Raw_Values(const TslContactInput3 *in, PetscReal raw[2], PetscBool *frozen);
PetscErrorCode TslContactElement3_Values(const TslContactLaw *law, const TslContactInput3 *in, PetscReal R[], PetscReal K[], TslContactOutput *out);
PetscErrorCode TslContactProject_Values(const TslContactInput *in, PetscReal *xi, PetscReal *g, PetscReal n[]);
PetscErrorCode TslContactElement_Short(const TslContactLaw *law, const TslContactInput *in, PetscReal R[], PetscReal K[], TslContactOutput *out);
PetscErrorCode TslContactElement3_Short(const TslContactLaw *law, const TslContactInput3 *in, PetscReal R[], PetscReal K[], TslContactOutput *out);
PetscErrorCode TslContactSurfacePoint_Values(const TslContactInput *in, PetscReal xi, PetscReal x[], PetscReal n[]);
PetscErrorCode TslContactFace3Evaluate_Values(PetscInt kind, const PetscReal x[], const PetscReal xi[], PetscReal p[], PetscReal n[]);
PetscErrorCode TslContactFace3Project_Values(PetscInt kind, const PetscReal x[], const PetscReal p[], PetscReal xi[]);
#endif

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
  if (slot >= 0 && slot < TSL_DUAL_N) r.d[slot] = 1;
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

/* f(a, b) of two duals with f = fv, df/da = dfa, df/db = dfb: shape functions of the two surface parameters. */
static inline TslDual DChain2(TslDual a, TslDual b, PetscReal fv, PetscReal dfa, PetscReal dfb)
{
  TslDual r;
  r.v = fv;
  for (PetscInt i = 0; i < TSL_DUAL_N; i++) r.d[i] = dfa * a.d[i] + dfb * b.d[i];
  return r;
}

/* h(t) = 3t^2 - 2t^3 clamped to [0, 1] (constant outside): the C1 ramp of the normal smoothing, with zero
 * slope at both ends of the rounded zone. */
static inline TslDual DSmoothStep(TslDual t)
{
  if (t.v >= 1) return DConst(1);
  if (t.v <= 0) return DConst(0);
  return DMul(DMul(t, t), DAddC(DScale(-2, t), 3));
}

static inline TslDual DPow4(TslDual a)
{
  PetscReal a3 = a.v * a.v * a.v;
  return DChain(a, a3 * a.v, 4 * a3);
}

/* The fused forms below do in one pass over the slots what their comments' compositions do in several
 * (with a temporary dual each): the same operations in the same order, so the same bits. The kernels
 * spend most of their time in these (the face point's sums, dot and cross products). */

/* *acc = DAdd(*acc, DMul(*a, *b)) */
static inline void DAccMul(TslDual *acc, const TslDual *a, const TslDual *b)
{
  acc->v += a->v * b->v;
  for (PetscInt i = 0; i < TSL_DUAL_N; i++) acc->d[i] += a->d[i] * b->v + a->v * b->d[i];
}

/* DSub(a, DMul(b, c)) */
static inline TslDual DSubMul(const TslDual *a, const TslDual *b, const TslDual *c)
{
  TslDual r;
  r.v = a->v - b->v * c->v;
  for (PetscInt i = 0; i < TSL_DUAL_N; i++) r.d[i] = a->d[i] - (b->d[i] * c->v + b->v * c->d[i]);
  return r;
}

/* DAdd(DMul(a[0], b[0]), DMul(a[1], b[1])) */
static inline TslDual DDot(const TslDual a[2], const TslDual b[2])
{
  TslDual r;
  r.v = a[0].v * b[0].v + a[1].v * b[1].v;
  for (PetscInt i = 0; i < TSL_DUAL_N; i++) r.d[i] = (a[0].d[i] * b[0].v + a[0].v * b[0].d[i]) + (a[1].d[i] * b[1].v + a[1].v * b[1].d[i]);
  return r;
}

/* DAdd(DAdd(DMul(a[0], b[0]), DMul(a[1], b[1])), DMul(a[2], b[2])) */
static inline TslDual DDot3(const TslDual a[3], const TslDual b[3])
{
  TslDual r;
  r.v = a[0].v * b[0].v + a[1].v * b[1].v + a[2].v * b[2].v;
  for (PetscInt i = 0; i < TSL_DUAL_N; i++)
    r.d[i] = (a[0].d[i] * b[0].v + a[0].v * b[0].d[i]) + (a[1].d[i] * b[1].v + a[1].v * b[1].d[i]) + (a[2].d[i] * b[2].v + a[2].v * b[2].d[i]);
  return r;
}

/* DSub(DMul(a, b), DMul(c, e)) */
static inline TslDual DMulSubMul(const TslDual *a, const TslDual *b, const TslDual *c, const TslDual *e)
{
  TslDual r;
  r.v = a->v * b->v - c->v * e->v;
  for (PetscInt i = 0; i < TSL_DUAL_N; i++) r.d[i] = (a->d[i] * b->v + a->v * b->d[i]) - (c->d[i] * e->v + c->v * e->d[i]);
  return r;
}

static inline void DCross(const TslDual a[3], const TslDual b[3], TslDual c[3])
{
  c[0] = DMulSubMul(&a[1], &b[2], &a[2], &b[1]);
  c[1] = DMulSubMul(&a[2], &b[0], &a[0], &b[2]);
  c[2] = DMulSubMul(&a[0], &b[1], &a[1], &b[0]);
}

/* ---------------------------------------------------------------------------------------------------
 * Interaction laws shared by the 2D (laws.c) and 3D (kernel3.c) elements: they see the gap, the slip
 * components and the temperatures, never the geometry they came from.
 * ------------------------------------------------------------------------------------------------- */

/* The slip of one element as nc components (2D: along tau, and circumferential with twist; 3D: along
 * t1, t2): e = slip from the sticking anchor, ds = slip increment from the start of the increment. */
typedef struct {
  PetscInt nc;
  TslDual  e[2], ds[2];
} TslContactSlip;

/* What the friction law returns. The anchor itself is the caller's (a parameter on its face): the law
 * says whether it stays (keep_anchor: stick) or moves so that the slip from it becomes `elastic` (the
 * elastic slip left after the return mapping; zero when open or frictionless: a new contact starts
 * stress-free at the current point). */
typedef struct {
  TslDual          t[2];         /* shear stress components (signed like the slip they resist) */
  TslDual          D;            /* dissipation rate per area (before eta) */
  PetscReal        slip_diss[2]; /* dissipative slip increments */
  PetscBool        keep_anchor;
  PetscReal        elastic[2];
  TslContactStatus status;
} TslContactFriction;

/* Normal pressure pN (penalty or augmented) and whether the law is on its closed branch, touching up to
 * 1e-12 of the face size L. */
TslDual TslContactNormalPressure(const TslContactLaw *law, const TslContactState *h, TslDual g, PetscReal L, PetscBool *closed);

/* Coulomb friction on the slip vector sl (PENALTY with return mapping, LAGRANGE); dt the increment. */
PetscErrorCode TslContactFrictionLaw(const TslContactLaw *law, PetscReal dt, TslDual pN, const TslContactSlip *sl, TslContactFriction *fs);

/* Heat flux per area from the main surface into the secondary node, q = k (theta_m - theta_s) +
 * C [(theta_m - theta_Z)^4 - (theta_s - theta_Z)^4], with the conductance k and radiation constant C
 * used. */
PetscErrorCode TslContactHeatFlux(const TslContactLaw *law, TslDual pN, PetscBool closed, TslDual g, TslDual theta_s, TslDual theta_m, TslDual *k,
                                  TslDual *C, TslDual *q);

/* Residual rows of a node-to-face element in duals, nper main nodes with shape functions N[], dim
 * displacement components per node followed by theta (index dim), nu unknowns per node:
 *   R_s = -A traction, R_a = A N_a traction, Rth_s = -A (q + f heat), Rth_a = A N_a (q - (1 - f) heat).
 * Rows beyond these (the twist's phi rows) are zeroed for the caller to fill. (Without a tangent the values'
 * copy of the kernels runs this on duals of two slots: contact/values/.) */
void TslContactResidualRows(PetscReal area, PetscReal f, PetscInt dim, PetscInt nu, PetscInt nnode, PetscInt nper, const TslDual N[],
                            const TslDual traction[], TslDual q, TslDual heat, TslDual Rd[]);

/* R (values) and K = dR/du (slots 0..ndof-1), either may be NULL. */
void TslContactDualExtract(PetscInt ndof, const TslDual Rd[], PetscReal R[], PetscReal K[]);

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

/* ---------------------------------------------------------------------------------------------------
 * 3D faces (face3.c): one row per family, as face.c's rows for the 2D faces
 * ------------------------------------------------------------------------------------------------- */
typedef struct {
  const TslGeometry *geom;      /* the catalogue's family: nnode, shape on its own reference coordinates, as_face rule */
  PetscReal          centre[2]; /* where the projection starts */
  PetscReal          size;      /* reference span of the face (quad 2, triangle 1): the band beyond the edges and step limits */
  /* the face in reference coordinates: xi_i in [lo, hi] for both, xi_1 + xi_2 <= sum (triangles) */
  PetscReal lo, hi, sum;
  PetscBool affine; /* x(xi) is affine in xi for a face of this family (tri3): the closest point in one Newton step */
  /* distances from the edges, in units of the face (quads: (1 - |xi_i|)/2 for the two directions; triangles:
   * the barycentric coordinates), for the normal smoothing; returns how many */
  PetscInt (*edge_distance)(const TslDual xi[2], TslDual d[3]);
  /* control points of the face's Bernstein form, hull[i][a]: the face lies in their convex hull */
  PetscReal hull[TSL_CONTACT3_MAX_FACE_NODES][TSL_CONTACT3_MAX_FACE_NODES];
} TslContactFace3;

const TslContactFace3 *TslContactFace3Get(PetscInt kind);

/* TslContactOutput.outside: beyond an edge by more than this (reference units), as the 2D pairing's 1e-6 of a
 * segment, so that round-off at a shared edge does not make a node bounce between two faces. */
#define TSL_CONTACT3_INSIDE_TOL 1e-6

/* N, dN/dxi_alpha and d2N/dxi_alpha dxi_beta of the face's nodes at xi[2] (any real values). */
void TslContactFace3Shape(const TslContactFace3 *face, const PetscReal xi[2], PetscReal N[], PetscReal dN[][2], PetscReal d2N[][2][2]);

/* Position p (relative to x[0]... as the nodes are given), tangents a[alpha] = dx/dxi_alpha and, when N
 * is not NULL, the shape functions N_a of a face with dual node positions x[nnode][3] at dual parameters
 * xi[2]: derivatives flow through the nodes and through xi (with the second derivatives of N). */
void TslContactFace3PointDual(const TslContactFace3 *face, const TslDual x[][3], const TslDual xi[2], TslDual p[3], TslDual a[2][3], TslDual N[]);

/* TslContactFace3PointDual for the kernels' face geometry: node coordinates that are seeded variables (values
 * x[b][d], derivative 1 in slot slot0 + TSL_CONTACT3_NU b + d; slot0 < 0: constants) at parameters seeded in the
 * parameters' slots (seed) or constant. The same values and derivatives formed directly: each output's
 * derivatives are nonzero in the parameters' and the nodes' slots only, where the generic products spend
 * TSL_DUAL_N operations per term (with the position below, a tenth of a 3D surface-to-surface run). */
void TslContactFace3PointSeeded(const TslContactFace3 *face, const PetscReal x[][3], PetscInt slot0, const PetscReal xi[2], PetscBool seed,
                                TslDual p[3], TslDual a[2][3], TslDual N[]);
/* The position alone at fixed parameters xi[2] (a history point), from the same seeded node coordinates:
 * derivatives through the nodes only. Kept apart from TslContactFace3PointSeeded (a NULL a there): the tangents'
 * loop bound and the second derivatives it would then carry cost 2 % of a 3D surface-to-surface run. */
void TslContactFace3PointAtSeeded(const TslContactFace3 *face, const PetscReal x[][3], PetscInt slot0, const PetscReal xi[2], TslDual p[3]);

/* A root of F(xi) = 0 for two face parameters by Newton, with dF/dxi from the dual slots TSL_DUAL_XI,
 * TSL_DUAL_ETA of fn's F: from xi[] as given, steps limited to `step` (reference units), a step down
 * the gradient of |x_s - x|^2 where -dF/dxi is not positive definite (far on the concave side), and
 * stopped (*frozen) where the iterate leaves the band of one face size around the face (clamped to it).
 * tol: on the step, in reference units. */
typedef PetscErrorCode (*TslContactFace3Function)(void *ctx, const PetscReal xi[2], TslDual F[2]);
PetscErrorCode TslContactFace3Solve(const TslContactFace3 *face, TslContactFace3Function fn, void *ctx, PetscReal step, PetscReal tol,
                                    PetscReal xi[2], PetscBool *frozen);

/* x = A^{-1} b for a 2x2 A; PETSC_FALSE when A is singular (to working precision). */
PetscBool TslContactSolve2(const PetscReal A[2][2], const PetscReal b[2], PetscReal x[2]);

/* Characteristic length of a face with node coordinates x[3*a + d]: the largest distance from its first node. */
PetscReal TslContactFace3Size(const TslContactFace3 *face, const PetscReal x[]);
