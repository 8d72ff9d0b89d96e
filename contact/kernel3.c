/* The 3D node-to-surface contact element: a secondary node against one main face (tri3, quad4, tri6),
 * residual and consistent tangent by forward-mode dual numbers, with the laws of laws.c. Formulas, units
 * and signs: include/thermoslide/contact.h ("3D node-to-surface") and docs/contact.md. */
#include "contact_impl.h"

#define NU TSL_CONTACT3_NU

/* The element's geometry in duals, relative to the reference position of the face's first node (as 2D:
 * gap, slip and projection do not lose digits to the size of the coordinates). */
typedef struct {
  const TslContactFace3 *face;
  PetscInt               nper;
  TslDual                xs[3], xm[TSL_CONTACT3_MAX_FACE_NODES][3];
  PetscReal              xmv[TSL_CONTACT3_MAX_FACE_NODES][3]; /* xm's values */
  PetscInt               slot0;                               /* xm[a][d] is seeded in slot slot0 + NU a + d (-1: constants) */
  PetscReal              nn[TSL_CONTACT3_MAX_FACE_NODES][3]; /* nodal normals of the smoothing */
  PetscReal              s;                                  /* smoothing fraction */
  PetscReal              h;                                  /* face size (current): tolerances */
} Geom3;

static PetscErrorCode GeomSetUp(const TslContactInput3 *in, PetscBool seed, Geom3 *geo)
{
  const PetscReal *O = in->x[1];
  PetscReal        xc[3 * TSL_CONTACT3_MAX_FACE_NODES];

  PetscFunctionBeginUser;
  geo->face = TslContactFace3Get(in->face);
  PetscCheck(geo->face, PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE, "Unknown 3D contact face family %d", (int)in->face);
  PetscCheck(in->smoothing >= 0 && in->smoothing < 0.5, PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE, "Contact smoothing fraction %g outside [0, 0.5)",
             (double)in->smoothing);
  geo->nper = geo->face->geom->nnode;
  geo->s     = in->smoothing;
  geo->slot0 = seed ? TSL_DUAL_DOF + NU : -1;
  for (PetscInt d = 0; d < 3; d++) geo->xs[d] = DVar((in->x[0][d] - O[d]) + in->u[0][d], seed ? TSL_DUAL_DOF + d : -1);
  for (PetscInt a = 0; a < geo->nper; a++)
    for (PetscInt d = 0; d < 3; d++) {
      geo->xm[a][d] = DVar((in->x[1 + a][d] - O[d]) + in->u[1 + a][d], seed ? TSL_DUAL_DOF + NU * (1 + a) + d : -1);
      geo->nn[a][d] = in->nodal_normal[a][d];
      xc[3 * a + d] = geo->xmv[a][d] = geo->xm[a][d].v;
    }
  geo->h = TslContactFace3Size(geo->face, xc);
  PetscCheck(geo->h > 0, PETSC_COMM_SELF, PETSC_ERR_ARG_WRONG, "3D contact face with coincident nodes");
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Whether the parameters' derivatives are those of seeded parameters (*seed) or none: the face point can then be
 * formed from the seeded node coordinates directly (TslContactFace3PointSeeded). */
static PetscBool PlainParameters(const TslDual xi[2], PetscBool *seed)
{
  *seed = (PetscBool)(xi[0].d[TSL_DUAL_XI] == 1 && xi[1].d[TSL_DUAL_ETA] == 1);
  for (PetscInt i = 0; i < 2; i++)
    for (PetscInt j = 0; j < TSL_DUAL_N; j++)
      if (xi[i].d[j] != (*seed && j == TSL_DUAL_XI + i ? 1 : 0)) return PETSC_FALSE;
  return PETSC_TRUE;
}

/* The face point, tangents and shape functions at xi (TslContactFace3PointDual), through the seeded form when it applies. */
static void FacePoint3(const Geom3 *geo, const TslDual xi[2], TslDual p[3], TslDual a[2][3], TslDual N[])
{
  PetscBool seed;

  if (PlainParameters(xi, &seed)) {
    const PetscReal xv[2] = {xi[0].v, xi[1].v};
    TslContactFace3PointSeeded(geo->face, (const PetscReal(*)[3])geo->xmv, geo->slot0, xv, seed, p, a, N);
  } else
    TslContactFace3PointDual(geo->face, (const TslDual(*)[3])geo->xm, xi, p, a, N);
}

/* Position p, tangents a, shape functions N and the smoothed unit normal n at dual parameters xi:
 *   n = normalise((1 - beta) n_f + beta sum_a N_a nn_a),  beta = 1 - prod_i (1 - h(1 - d_i/s)),
 * d_i the distances from the edges in units of the face (TslContactFace3.edge_distance), h the C1 ramp.
 * Written as c + beta |c| sum_a N_a (nn_a - n_f), c = a1 x a2 (the same direction, as sum N_a = 1): with
 * nodal normals equal to the face normal the smoothing term is exactly zero and n is the face normal to
 * the last bit. */
static void Surface(const Geom3 *geo, const TslDual xi[2], TslDual p[3], TslDual a[2][3], TslDual N[], TslDual n[3])
{
  TslDual c[3], len;

  FacePoint3(geo, xi, p, a, N);
  DCross(a[0], a[1], c);
  len = DSqrt(DDot3(c, c));
  if (geo->s > 0) {
    TslDual  d[3], keep = DConst(1), beta, m[3] = {DConst(0), DConst(0), DConst(0)};
    PetscInt nd = geo->face->edge_distance(xi, d);

    for (PetscInt i = 0; i < nd; i++) keep = DMul(keep, DAddC(DScale(-1, DSmoothStep(DAddC(DScale(-1 / geo->s, d[i]), 1))), 1));
    beta = DAddC(DScale(-1, keep), 1);
    if (beta.v > 0) {
      TslDual nf[3]; /* the face normal */
      for (PetscInt k = 0; k < 3; k++) nf[k] = DDiv(c[k], len);
      for (PetscInt b = 0; b < geo->nper; b++)
        for (PetscInt k = 0; k < 3; k++) {
          TslDual e = DScale(-1, nf[k]);
          e.v += geo->nn[b][k]; /* nn - nf, as DSub(DConst(nn), nf) forms it */
          DAccMul(&m[k], &N[b], &e);
        }
      for (PetscInt k = 0; k < 3; k++) c[k] = DAdd(c[k], DMul(DMul(beta, len), m[k]));
      len = DSqrt(DDot3(c, c));
    }
  }
  for (PetscInt k = 0; k < 3; k++) n[k] = DDiv(c[k], len);
}

/* F_alpha = (x_s - x_m) . (a_alpha - (a_alpha . n) n): zero at the projection along the smoothed normal. */
/* The face's point, tangents, shape functions and smoothed normal at a parameter (Surface's results). */
typedef struct {
  TslDual p[3], a[2][3], N[TSL_CONTACT3_MAX_FACE_NODES], n[3];
} FacePoint;

/* The projection's function F_c = (x_s - x_m(xi)) . t_c (t_c the part of a_c orthogonal to n) at xi, seeded in
 * the parameters' slots; S not NULL: the face point it was evaluated on, with the same seeds. */
static PetscErrorCode ProjectionEval(const Geom3 *geo, const PetscReal xi[2], TslDual F[2], FacePoint *S)
{
  TslDual   xv[2] = {DVar(xi[0], TSL_DUAL_XI), DVar(xi[1], TSL_DUAL_ETA)}, r[3];
  FacePoint local, *f = S ? S : &local;

  PetscFunctionBeginUser;
  Surface(geo, xv, f->p, f->a, f->N, f->n);
  for (PetscInt d = 0; d < 3; d++) r[d] = DSub(geo->xs[d], f->p[d]);
  for (PetscInt i = 0; i < 2; i++) {
    TslDual an = DDot3(f->a[i], f->n), t[3];

    for (PetscInt d = 0; d < 3; d++) t[d] = DSubMul(&f->a[i][d], &an, &f->n[d]);
    F[i] = DDot3(r, t);
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode ProjectionFunction(void *ctx, const PetscReal xi[2], TslDual F[2])
{
  PetscFunctionBeginUser;
  PetscCall(ProjectionEval((const Geom3 *)ctx, xi, F, NULL));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The projection's parameters (unclamped) and whether it froze beyond the band, from the projection at the
 * start of the increment when that lies on the face (the node has moved little since: two Newton
 * iterations instead of four or five from the centre). Values alone are needed: the full kernel runs these
 * iterations in the values copy (contact/values/, TslContactProject3Raw), whose geometry carries no
 * unknowns' derivatives, and evaluates the full duals once, at the converged point (ProjectDual). */
static PetscErrorCode ProjectRaw(Geom3 *geo, const PetscReal start[2], PetscReal raw[2], PetscBool *frozen)
{
  PetscReal dist2 = 0, tol;

  PetscFunctionBeginUser;
  for (PetscInt d = 0; d < 3; d++) dist2 += geo->xs[d].v * geo->xs[d].v;
  tol    = 1e3 * PETSC_MACHINE_EPSILON * (1 + PetscSqrtReal(dist2) / geo->h) * geo->face->size;
  raw[0] = geo->face->centre[0];
  raw[1] = geo->face->centre[1];
  if (start[0] >= geo->face->lo && start[0] <= geo->face->hi && start[1] >= geo->face->lo && start[1] <= geo->face->hi &&
      start[0] + start[1] <= geo->face->sum)
    raw[0] = start[0], raw[1] = start[1];
  PetscCall(TslContactFace3Solve(geo->face, ProjectionFunction, geo, geo->face->affine && geo->s == 0 ? PETSC_MAX_REAL : 0.25 * geo->face->size, tol,
                                 raw, frozen));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Where the projection starts: the caller's guess, or the history's projection at the increment's start. */
static void ProjectStart(const TslContactInput3 *in, PetscReal start[2])
{
  start[0] = in->has_guess ? in->guess[0] : in->hist.xi_old;
  start[1] = in->has_guess ? in->guess[1] : in->hist.eta_old;
}

PetscErrorCode TslContactProject3Raw(const TslContactInput3 *in, PetscReal raw[2], PetscBool *frozen)
{
  Geom3     geo;
  PetscReal start[2];

  PetscFunctionBeginUser;
  ProjectStart(in, start);
  PetscCall(GeomSetUp(in, PETSC_FALSE, &geo));
  PetscCall(ProjectRaw(&geo, start, raw, frozen));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The projection as duals carrying dxi/du = -F_xi^{-1} F_u (implicit function theorem at F = 0; zero when
 * frozen beyond the band), and the unclamped values. With the tangent and not frozen, *have: S holds the face
 * point at the projection as Surface would give it for these xi, by the chain rule from the evaluation of F
 * (its derivatives in the parameters' slots composed with dxi/du): the same first derivatives without a
 * second evaluation of the face in every slot. */
static PetscErrorCode ProjectDual(const TslContactInput3 *in, Geom3 *geo, TslDual xi[2], PetscReal raw[2], FacePoint *S, PetscBool *have)
{
  PetscBool frozen;

  PetscFunctionBeginUser;
  *have = PETSC_FALSE;
#if defined(TSL_DUAL_VALUES)
  (void)S;
  {
    PetscReal start[2];
    ProjectStart(in, start);
    PetscCall(ProjectRaw(geo, start, raw, &frozen)); /* this geometry already holds values alone */
  }
#else
  PetscCall(TslContactProject3Raw_Values(in, raw, &frozen));
#endif
  xi[0] = DConst(raw[0]);
  xi[1] = DConst(raw[1]);
#if !defined(TSL_DUAL_VALUES) /* values alone: no derivatives to carry */
  if (!frozen) {
    TslDual   F[2];
    PetscReal J[2][2];

    PetscCall(ProjectionEval(geo, raw, F, S));
    for (PetscInt i = 0; i < 2; i++) {
      J[i][0] = F[i].d[TSL_DUAL_XI];
      J[i][1] = F[i].d[TSL_DUAL_ETA];
    }
    for (PetscInt j = TSL_DUAL_DOF; j < TSL_DUAL_N; j++) {
      PetscReal b[2] = {-F[0].d[j], -F[1].d[j]}, x[2];

      PetscCheck(TslContactSolve2(J, b, x), PETSC_COMM_SELF, PETSC_ERR_CONV_FAILED, "3D contact projection: singular derivative at the projection");
      xi[0].d[j] = x[0];
      xi[1].d[j] = x[1];
    }
    {
      TslDual *q[3 + 6 + TSL_CONTACT3_MAX_FACE_NODES + 3];
      PetscInt nq = 0;
      for (PetscInt d = 0; d < 3; d++) q[nq++] = &S->p[d], q[nq++] = &S->a[0][d], q[nq++] = &S->a[1][d], q[nq++] = &S->n[d];
      for (PetscInt b = 0; b < geo->nper; b++) q[nq++] = &S->N[b];
      for (PetscInt k = 0; k < nq; k++) {
        TslDual        *v  = q[k];
        const PetscReal dx = v->d[TSL_DUAL_XI], de = v->d[TSL_DUAL_ETA];
        for (PetscInt j = TSL_DUAL_DOF; j < TSL_DUAL_N; j++) v->d[j] += dx * xi[0].d[j] + de * xi[1].d[j];
        v->d[TSL_DUAL_XI] = v->d[TSL_DUAL_ETA] = 0;
      }
    }
    *have = PETSC_TRUE;
  }
#else
  (void)S;
#endif
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The anchor of an elastic slip r (components along t1, t2): the face point x_m(xi_a) whose tangential
 * offset from x_m(xi) is r, G_c(xi_a) = (x_m(xi) - x_m(xi_a)) . t_c - r_c = 0. Its first Newton step from
 * xi is the solve with the 2x2 metric t_c . a_beta; the next ones make it exact on curved faces, so that
 * the next increment starts with exactly the elastic slip the law left. */
typedef struct {
  const Geom3 *geo;
  PetscReal    p[3], t[2][3], r[2];
} Anchor;

static PetscErrorCode AnchorFunction(void *ctx, const PetscReal xi[2], TslDual G[2])
{
  const Anchor *an    = (const Anchor *)ctx;
  TslDual       xv[2] = {DVar(xi[0], TSL_DUAL_XI), DVar(xi[1], TSL_DUAL_ETA)}, q[3], a[2][3];

  PetscFunctionBeginUser;
  FacePoint3(an->geo, xv, q, a, NULL);
  for (PetscInt c = 0; c < 2; c++) {
    G[c] = DConst(-an->r[c]);
    for (PetscInt d = 0; d < 3; d++) G[c] = DAdd(G[c], DScale(an->t[c][d], DAddC(DScale(-1, q[d]), an->p[d])));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode AnchorSolve(const Geom3 *geo, const TslDual xi[2], const TslDual p[3], const TslDual t[2][3], const PetscReal r[2],
                                  PetscReal xa[2])
{
  Anchor    an;
  PetscBool frozen;

  PetscFunctionBeginUser;
  an.geo = geo;
  for (PetscInt d = 0; d < 3; d++) {
    an.p[d]    = p[d].v;
    an.t[0][d] = t[0][d].v;
    an.t[1][d] = t[1][d].v;
  }
  an.r[0] = r[0];
  an.r[1] = r[1];
  xa[0]   = xi[0].v;
  xa[1]   = xi[1].v;
  /* G_xi = -(t_c . a_beta): minus a metric, as the projection's Jacobian (the same solver) */
  PetscCall(TslContactFace3Solve(geo->face, AnchorFunction, &an, 0.25 * geo->face->size, 1e3 * PETSC_MACHINE_EPSILON * geo->face->size, xa, &frozen));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Tangential components of x_m(xi) - x_m(xi_b) along t1, t2 (xi_b a history point on the current face). */
static void SlipFrom(const Geom3 *geo, const TslDual p[3], PetscReal xb, PetscReal eb, const TslDual t[2][3], TslDual s[2])
{
  const PetscReal xv[2] = {xb, eb};
  TslDual         q[3], dx[3];

  TslContactFace3PointAtSeeded(geo->face, (const PetscReal(*)[3])geo->xmv, geo->slot0, xv, q);
  for (PetscInt d = 0; d < 3; d++) dx[d] = DSub(p[d], q[d]);
  for (PetscInt c = 0; c < 2; c++) s[c] = DDot3(dx, t[c]);
}

PetscErrorCode TslContactElement3(const TslContactLaw *law, const TslContactInput3 *in, PetscReal R[], PetscReal K[], TslContactOutput *out)
{
  Geom3              geo;
  PetscInt           nnode, ndof;
  PetscReal          raw[2], anchor[2] = {in->hist.xi_anchor, in->hist.eta_anchor};
  TslDual            xi[2], p[3], a[2][3], n[3], t[2][3], r[3], g, pN, traction[3], k, C, q, theta_s, theta_m, heat, len, an;
  TslDual            N[TSL_CONTACT3_MAX_FACE_NODES], Rd[TSL_CONTACT_MAX_DOF];
  TslContactSlip     sl;
  TslContactFriction fs;
  PetscBool          closed;

  PetscFunctionBeginUser;
  PetscCheck(in->area > 0, PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE, "Tributary area must be positive");
#if !defined(TSL_DUAL_VALUES)
  if (!K) { /* values alone: the copy without the unknowns' derivatives (contact/values/) */
    PetscCall(TslContactElement3_Values(law, in, R, NULL, out));
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  {
    const TslContactFace3 *f = TslContactFace3Get(in->face);
    if (f) { /* the element's unknowns: the secondary node and the face's */
      const PetscInt nd = NU * (1 + f->geom->nnode);
#if defined(TSL_DUAL_SHORT)
      PetscCheck(nd <= TSL_DUAL_SHORT_DOF, PETSC_COMM_SELF, PETSC_ERR_PLIB, "3D contact element with %" PetscInt_FMT " unknowns in the short kernels",
                 nd);
#else
      if (nd <= TSL_DUAL_SHORT_DOF) { /* its tangent fits fewer slots (contact/short/) */
        PetscCall(TslContactElement3_Short(law, in, R, K, out));
        PetscFunctionReturn(PETSC_SUCCESS);
      }
#endif
    }
  }
#endif
  PetscCall(GeomSetUp(in, PETSC_TRUE, &geo));
  nnode = 1 + geo.nper;
  ndof  = NU * nnode;

  /* kinematics: projection along the smoothed normal, gap, the slip basis t1 (the part of a1 orthogonal to
   * n), t2 = n x t1 */
  {
    FacePoint fp;
    PetscBool have;
    PetscCall(ProjectDual(in, &geo, xi, raw, &fp, &have));
    if (have) {
      for (PetscInt d = 0; d < 3; d++) p[d] = fp.p[d], a[0][d] = fp.a[0][d], a[1][d] = fp.a[1][d], n[d] = fp.n[d];
      for (PetscInt b = 0; b < geo.nper; b++) N[b] = fp.N[b];
    } else
      Surface(&geo, xi, p, a, N, n);
  }
  for (PetscInt d = 0; d < 3; d++) r[d] = DSub(geo.xs[d], p[d]);
  g  = DDot3(r, n);
  an = DDot3(a[0], n);
  for (PetscInt d = 0; d < 3; d++) t[0][d] = DSub(a[0][d], DMul(an, n[d]));
  len = DSqrt(DDot3(t[0], t[0]));
  for (PetscInt d = 0; d < 3; d++) t[0][d] = DDiv(t[0][d], len);
  DCross(n, t[0], t[1]);
  sl.nc = 2;
  SlipFrom(&geo, p, in->hist.xi_old, in->hist.eta_old, (const TslDual(*)[3])t, sl.ds);
  SlipFrom(&geo, p, in->hist.xi_anchor, in->hist.eta_anchor, (const TslDual(*)[3])t, sl.e);

  /* mechanical laws (laws.c); the traction on the secondary node is pN n - tT, tT = t_1 t1 + t_2 t2 */
  pN = TslContactNormalPressure(law, &in->hist, g, geo.h, &closed);
  PetscCall(TslContactFrictionLaw(law, in->dt, pN, &sl, &fs));
  if (!fs.keep_anchor) {
    if (fs.elastic[0] == 0 && fs.elastic[1] == 0) {
      anchor[0] = xi[0].v;
      anchor[1] = xi[1].v;
    } else
      PetscCall(AnchorSolve(&geo, xi, p, (const TslDual(*)[3])t, fs.elastic, anchor));
  }
  for (PetscInt d = 0; d < 3; d++) traction[d] = DSub(DMul(pN, n[d]), DAdd(DMul(fs.t[0], t[0][d]), DMul(fs.t[1], t[1][d])));

  /* thermal laws */
  theta_s = DVar(in->u[0][3], TSL_DUAL_DOF + 3);
  theta_m = DConst(0);
  for (PetscInt b = 0; b < geo.nper; b++) theta_m = DAdd(theta_m, DMul(N[b], DVar(in->u[1 + b][3], TSL_DUAL_DOF + NU * (1 + b) + 3)));
  PetscCall(TslContactHeatFlux(law, pN, closed, g, theta_s, theta_m, &k, &C, &q));
  heat = DScale(law->eta, fs.D);

  TslContactResidualRows(in->area, law->f, 3, NU, nnode, geo.nper, N, traction, q, heat, Rd);
  TslContactDualExtract(ndof, Rd, R, K);
  if (out) {
    PetscCall(PetscMemzero(out, sizeof(*out)));
    out->nnode                 = nnode;
    out->nu                    = NU;
    out->xi                    = xi[0].v;
    out->eta                   = xi[1].v;
    out->xi_raw                = raw[0];
    out->eta_raw               = raw[1];
    out->outside               = !TslContactFace3Inside(in->face, raw, TSL_CONTACT3_INSIDE_TOL);
    out->normal[0]             = n[0].v;
    out->normal[1]             = n[1].v;
    out->normal_z              = n[2].v;
    out->gap                   = g.v;
    out->area                  = in->area;
    out->pressure              = pN.v;
    out->slip                  = sl.ds[0].v;
    out->slip_circ             = sl.ds[1].v;
    out->shear                 = fs.t[0].v;
    out->shear_circ            = fs.t[1].v;
    out->slip_dissipative      = fs.slip_diss[0];
    out->slip_dissipative_circ = fs.slip_diss[1];
    out->conductance           = k.v;
    out->radiation_C           = C.v;
    out->heat_flux             = q.v;
    out->dissipation_rate      = fs.D.v;
    out->heat_generation       = heat.v;
    out->status                = fs.status;
    out->xi_anchor             = anchor[0];
    out->eta_anchor            = anchor[1];
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}
