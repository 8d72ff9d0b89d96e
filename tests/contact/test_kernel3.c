/* The 3D node-to-surface contact kernel (contact/face3.c, contact/kernel3.c):
 *   - the consistent tangent against central differences of the residual, block by block (u, theta rows and
 *     columns, each relative to its own scale), on a tri3, a warped quad4 and a curved tri6, with smoothing
 *     and non-parallel nodal normals (the node over the rounded zone) and without, open/stick/slip for
 *     penalty (constant and automatic stick stiffness) and LAGRANGE friction, augmented Lagrange, conductance
 *     by pressure and by clearance, radiation and frictional heating;
 *   - a flat face under uniform penetration: pressure, nodal forces N_a A p n, force and heat balance,
 *     projection onto the centre, outside beyond an edge, the smoothed normal of equal nodal normals;
 *   - face families: closest point on a warped quad4 and a curved tri6, tributary weights (tri6: A/12, A/4),
 *     bounding boxes, history start and transfer between faces;
 *   - friction: |tT| = mu pN while slipping (vector slip), stick below, the anchor left at the elastic slip,
 *     dissipation mu pN |ds| / dt (LAGRANGE). */
#include "check.h"

#define NU   TSL_CONTACT3_NU
#define MAXD (NU * (1 + TSL_CONTACT3_MAX_FACE_NODES))

enum { TRI3 = 0, QUAD4 = 1, TRI6 = 2 };

/* Reference coordinates of the nodes (the catalogue's, in face order) and of the face centre. */
static const PetscReal *NodeXi(PetscInt kind, PetscInt a)
{
  static const PetscReal tri[6][2] = {{0, 0}, {1, 0}, {0, 1}, {0.5, 0}, {0.5, 0.5}, {0, 0.5}}, quad[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
  return kind == QUAD4 ? quad[a] : tri[a];
}

/* Shape functions at the centre: quad4 1/4; tri3 1/3; tri6 corners L(2L - 1) = -1/9, midsides 4 L L = 4/9. */
static PetscReal CentreN(PetscInt kind, PetscInt a)
{
  if (kind == QUAD4) return 0.25;
  if (kind == TRI3) return 1.0 / 3;
  return a < 3 ? -1.0 / 9 : 4.0 / 9;
}

static const char *FamilyName(PetscInt kind)
{
  return kind == TRI3 ? "tri3" : kind == QUAD4 ? "quad4" : "tri6";
}

/* Reference nodes of the test faces (body below, normal roughly +z): a tri3, a warped quad4 (its corners
 * off one plane by +-0.1) and a curved tri6 (midside nodes 0.08 above the chords' middles and moved along
 * them). */
static void FaceNodes(PetscInt kind, PetscReal x[][3])
{
  const PetscReal tri[3][3]  = {{0, 0, 0}, {1.2, 0.1, 0.05}, {0.2, 1.1, -0.1}};
  const PetscReal quad[4][3] = {{-0.6, -0.6, 0}, {0.6, -0.54, 0.1}, {0.66, 0.6, -0.1}, {-0.54, 0.66, 0.08}};

  if (kind == QUAD4) {
    for (PetscInt a = 0; a < 4; a++)
      for (PetscInt d = 0; d < 3; d++) x[a][d] = quad[a][d];
    return;
  }
  for (PetscInt a = 0; a < 3; a++)
    for (PetscInt d = 0; d < 3; d++) x[a][d] = tri[a][d];
  if (kind == TRI6) {
    const PetscInt  e[3][2]  = {{0, 1}, {1, 2}, {2, 0}};
    const PetscReal shift[3] = {0.03, -0.02, 0.04};
    for (PetscInt m = 0; m < 3; m++)
      for (PetscInt d = 0; d < 3; d++)
        x[3 + m][d] = 0.5 * (x[e[m][0]][d] + x[e[m][1]][d]) + shift[m] * (x[e[m][1]][d] - x[e[m][0]][d]) + (d == 2 ? 0.08 : 0);
  }
}

/* Current coordinates of the face of an input, x[3*a + d]. */
static void CurrentFace(const TslContactInput3 *in, PetscReal x[])
{
  for (PetscInt a = 0; a < TslContactFace3Nodes(in->face); a++)
    for (PetscInt d = 0; d < 3; d++) x[3 * a + d] = in->x[1 + a][d] + in->u[1 + a][d];
}

/* An input on face `kind`: the node at distance `gap` along the face normal from the point of reference
 * coordinates target[] (current configuration), small displacements and distinct temperatures; with
 * smoothing the nodal normals are the face normals at the nodes, each tilted differently. */
static PetscErrorCode CaseSetUp(PetscInt kind, const PetscReal target[2], PetscReal gap, PetscReal smoothing, TslContactInput3 *in)
{
  PetscInt  nper = TslContactFace3Nodes(kind);
  PetscReal X[TSL_CONTACT3_MAX_FACE_NODES][3], xc[3 * TSL_CONTACT3_MAX_FACE_NODES], p[3], n[3];

  PetscFunctionBeginUser;
  memset(in, 0, sizeof(*in));
  in->face      = kind;
  in->area      = 0.3;
  in->dt        = 0.2;
  in->smoothing = smoothing;
  FaceNodes(kind, X);
  for (PetscInt a = 0; a < nper; a++) {
    for (PetscInt d = 0; d < 3; d++) {
      in->x[1 + a][d] = X[a][d];
      in->u[1 + a][d] = 0.002 * PetscSinReal(1.0 + 3 * a + d);
    }
    in->u[1 + a][3] = 100 + 10 * a;
  }
  in->u[0][0] = 0.01;
  in->u[0][1] = -0.004;
  in->u[0][2] = 0.003;
  in->u[0][3] = 40;
  CurrentFace(in, xc);
  for (PetscInt a = 0; a < nper; a++) {
    const PetscReal *xi      = NodeXi(kind, a);
    PetscReal        tilt[3] = {0.12 * PetscCosReal(2.0 * a), 0.12 * PetscSinReal(2.0 * a), 0}, len = 0;

    PetscCall(TslContactFace3Evaluate(kind, xc, xi, NULL, n));
    for (PetscInt d = 0; d < 3; d++) len += (n[d] + tilt[d]) * (n[d] + tilt[d]);
    for (PetscInt d = 0; d < 3; d++) in->nodal_normal[a][d] = (n[d] + tilt[d]) / PetscSqrtReal(len);
  }
  PetscCall(TslContactFace3Evaluate(kind, xc, target, p, n));
  for (PetscInt d = 0; d < 3; d++) in->x[0][d] = p[d] + gap * n[d] - in->u[0][d];
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* History: start of the increment `old` away from the projection (reference units, along both directions),
 * the anchor `anchor` further away. */
static PetscErrorCode SetHistory(const TslContactLaw *law, TslContactInput3 *in, PetscReal old, PetscReal anchor)
{
  TslContactOutput out;

  PetscFunctionBeginUser;
  PetscCall(TslContactElement3(law, in, NULL, NULL, &out));
  in->hist.xi_old     = out.xi + old;
  in->hist.eta_old    = out.eta - 0.5 * old;
  in->hist.xi_anchor  = in->hist.xi_old + anchor;
  in->hist.eta_anchor = in->hist.eta_old + 0.7 * anchor;
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode CheckTangent(TestLog *log, const char *name, const TslContactLaw *law, TslContactInput3 *in, TslContactStatus status)
{
  PetscReal        K[MAXD * MAXD], Kfd[MAXD * MAXD], Rp[MAXD], Rm[MAXD], R0[MAXD];
  TslContactOutput out, outp, outm;
  PetscInt         nd;
  PetscInt         kind[MAXD];
  const char      *kname[2] = {"u", "theta"};

  PetscFunctionBeginUser;
  PetscCall(TslContactElement3(law, in, R0, K, &out));
  nd = NU * out.nnode;
  Check(log, (PetscReal)out.status, status, 0, "%s: status (gap %g, p %g, slip %g %g)", name, (double)out.gap, (double)out.pressure, (double)out.slip,
        (double)out.slip_circ);
  for (PetscInt j = 0; j < nd; j++) {
    PetscReal *v = &in->u[j / NU][j % NU], v0 = *v, h = (j % NU == 3) ? 1e-5 * PetscMax(1, PetscAbsReal(v0)) : 1e-7;

    *v = v0 + h;
    PetscCall(TslContactElement3(law, in, Rp, NULL, &outp));
    *v = v0 - h;
    PetscCall(TslContactElement3(law, in, Rm, NULL, &outm));
    *v = v0;
    PetscCheck(outp.status == out.status && outm.status == out.status, PETSC_COMM_SELF, PETSC_ERR_PLIB,
               "%s: perturbation of unknown %d changes the contact status", name, (int)j);
    for (PetscInt i = 0; i < nd; i++) Kfd[i * nd + j] = (Rp[i] - Rm[i]) / (2 * h);
  }
  for (PetscInt i = 0; i < nd; i++) kind[i] = i % NU == 3;
  CheckTangentBlocks(log, name, nd, K, Kfd, kind, 2, kname);
  PetscFunctionReturn(PETSC_SUCCESS);
}

static const char *Name(char buf[160], PetscInt kind, PetscReal s, const char *name)
{
  snprintf(buf, 160, "%s%s: %s", FamilyName(kind), s > 0 ? " smoothed" : "", name);
  return buf;
}

/* Every law case on family `kind`, with smoothing s (the node over the rounded zone of an edge: the
 * target lies at 0.1 of the face from an edge, inside the zone 0.2) or without (s = 0, an interior point). */
static PetscErrorCode CheckTangents(TestLog *log, PetscInt kind, PetscReal s)
{
  TslContactLaw    law;
  TslContactInput3 in;
  const PetscReal  kp[2] = {100, 400}, kv[2] = {20, 5};
  const PetscReal  tq[2] = {0.3, -0.8}, tt[2] = {0.25, 0.65}, *target = kind == QUAD4 ? tq : tt;
  PetscReal        ds = kind == QUAD4 ? 0.006 : 0.003; /* a slip of ~0.004 in length */
  char             name[160];

  PetscFunctionBeginUser;
  /* open: clearance conductance and radiation */
  TestLawSetUp(&law, PETSC_TRUE);
  PetscCall(CaseSetUp(kind, target, 0.03, s, &in));
  PetscCall(SetHistory(&law, &in, ds, 0));
  PetscCall(CheckTangent(log, Name(name, kind, s, "open, clearance conductance + radiation"), &law, &in, TSL_CONTACT_OPEN));

  /* stick, pressure conductance (pN ~ 200, mu pN = 60: an elastic slip of ~0.004 sticks) */
  law.conductance = TSL_CONTACT_CONDUCTANCE_PRESSURE;
  law.k_n         = 2;
  law.k_arg       = kp;
  law.k_value     = kv;
  law.F_n         = 0;
  PetscCall(CaseSetUp(kind, target, -0.01, s, &in));
  PetscCall(SetHistory(&law, &in, ds, -0.5 * ds));
  PetscCall(CheckTangent(log, Name(name, kind, s, "stick, pressure conductance"), &law, &in, TSL_CONTACT_STICK));

  /* slip, pressure conductance + radiation + frictional heating */
  law.F_n = 2;
  PetscCall(CaseSetUp(kind, target, -0.01, s, &in));
  PetscCall(SetHistory(&law, &in, ds, 10 * ds));
  PetscCall(CheckTangent(log, Name(name, kind, s, "slip, pressure conductance + radiation + heating"), &law, &in, TSL_CONTACT_SLIP));
  if (s > 0) {
    /* the node lies in the rounded zone: the tilted nodal normals turn the normal used */
    TslContactOutput o1, o0;
    PetscReal        turn = 0;

    PetscCall(TslContactElement3(&law, &in, NULL, NULL, &o1));
    in.smoothing = 0;
    PetscCall(TslContactElement3(&law, &in, NULL, NULL, &o0));
    in.smoothing = s;
    turn         = PetscSqrtReal(PetscSqr(o1.normal[0] - o0.normal[0]) + PetscSqr(o1.normal[1] - o0.normal[1]) + PetscSqr(o1.normal_z - o0.normal_z));
    CheckAtLeast(log, turn, 0.01, "%s: smoothing turns the normal in the rounded zone (|n - n_face|)", FamilyName(kind));
  }

  /* automatic penalty: stick and slip */
  law.eps_t        = 0;
  law.elastic_slip = 0.01;
  PetscCall(CaseSetUp(kind, target, -0.01, s, &in));
  PetscCall(SetHistory(&law, &in, ds, -0.5 * ds));
  PetscCall(CheckTangent(log, Name(name, kind, s, "automatic penalty, stick"), &law, &in, TSL_CONTACT_STICK));
  PetscCall(CaseSetUp(kind, target, -0.01, s, &in));
  PetscCall(SetHistory(&law, &in, ds, 10 * ds));
  PetscCall(CheckTangent(log, Name(name, kind, s, "automatic penalty, slip + heating"), &law, &in, TSL_CONTACT_SLIP));
  law.eps_t        = 5e3;
  law.elastic_slip = 0;

  /* LAGRANGE: slip beyond the ramp, and on the ramp (the regularised stick branch) */
  law.friction = TSL_CONTACT_FRICTION_LAGRANGE;
  law.slip_tol = 1e-6;
  PetscCall(CaseSetUp(kind, target, -0.01, s, &in));
  PetscCall(SetHistory(&law, &in, ds, 0));
  PetscCall(CheckTangent(log, Name(name, kind, s, "Lagrange slip + heating"), &law, &in, TSL_CONTACT_SLIP));
  law.slip_tol = 0.05;
  PetscCall(CaseSetUp(kind, target, -0.01, s, &in));
  PetscCall(SetHistory(&law, &in, ds, 0));
  PetscCall(CheckTangent(log, Name(name, kind, s, "Lagrange on the ramp + heating"), &law, &in, TSL_CONTACT_STICK));
  law.slip_tol = 1e-6;

  /* augmented Lagrange normal, penalty stick, slightly open but pressed by the multiplier */
  law.friction = TSL_CONTACT_FRICTION_PENALTY;
  law.normal   = TSL_CONTACT_NORMAL_AUGMENTED;
  PetscCall(CaseSetUp(kind, target, 0.001, s, &in));
  in.hist.lambda = 150;
  PetscCall(SetHistory(&law, &in, ds, -0.2 * ds));
  PetscCall(CheckTangent(log, Name(name, kind, s, "augmented Lagrange, stick"), &law, &in, TSL_CONTACT_STICK));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* A flat face in the plane z = 0 (normal +z): tri3 (0,0), (2,0), (0,2); quad4 the square [0,2]^2; tri6 the
 * tri3 with midside nodes in the middles of the edges. */
static void FlatFace(PetscInt kind, TslContactInput3 *in)
{
  const PetscReal tri[6][2] = {{0, 0}, {2, 0}, {0, 2}, {1, 0}, {1, 1}, {0, 1}}, quad[4][2] = {{0, 0}, {2, 0}, {2, 2}, {0, 2}};

  memset(in, 0, sizeof(*in));
  in->face = kind;
  in->area = 0.25;
  in->dt   = 0.5;
  for (PetscInt a = 0; a < TslContactFace3Nodes(kind); a++) {
    in->x[1 + a][0] = kind == QUAD4 ? quad[a][0] : tri[a][0];
    in->x[1 + a][1] = kind == QUAD4 ? quad[a][1] : tri[a][1];
  }
}

static PetscErrorCode CheckFlat(TestLog *log, PetscInt kind)
{
  const char      *fam   = FamilyName(kind);
  const PetscReal  delta = 0.004, centre[2] = {kind == QUAD4 ? 1 : 2.0 / 3, kind == QUAD4 ? 1 : 2.0 / 3};
  const PetscReal  cref[2] = {kind == QUAD4 ? 0 : 1.0 / 3, kind == QUAD4 ? 0 : 1.0 / 3};
  TslContactLaw    law;
  TslContactInput3 in;
  TslContactOutput out;
  PetscReal        R[MAXD], fsum[3] = {0, 0, 0}, hmain = 0;
  PetscInt         nper = TslContactFace3Nodes(kind);

  PetscFunctionBeginUser;
  PetscCall(TslContactLawSetDefaults(&law));
  law.eps_n       = 1e4;
  law.conductance = TSL_CONTACT_CONDUCTANCE_PRESSURE;
  law.k_n         = 1;
  law.k_arg       = &law.eps_n; /* any one point: k = 7 */
  {
    static const PetscReal kval = 7;
    law.k_value                 = &kval;
  }
  FlatFace(kind, &in);
  in.x[0][0] = centre[0];
  in.x[0][1] = centre[1];
  in.u[0][2] = -delta;
  in.u[0][3] = 20;
  for (PetscInt a = 0; a < nper; a++) in.u[1 + a][3] = 50;
  PetscCall(TslContactElement3(&law, &in, R, NULL, &out));
  Check(log, out.xi, cref[0], 1e-14, "%s flat: node above the centre projects to the centre (xi)", fam);
  Check(log, out.eta, cref[1], 1e-14, "%s flat: node above the centre projects to the centre (eta)", fam);
  Check(log, out.outside, 0, 0, "%s flat: on the face", fam);
  CheckRel(log, out.gap, -delta, 1e-12, 1, "%s flat: gap", fam);
  CheckRel(log, out.pressure, law.eps_n * delta, 1e-12, 1, "%s flat: pressure = eps_n delta", fam);
  CheckRel(log, R[2], -in.area * out.pressure, 1e-12, 1, "%s flat: force on s = -A p n (residual)", fam);
  for (PetscInt a = 0; a < nper; a++)
    CheckRel(log, R[NU * (1 + a) + 2], in.area * CentreN(kind, a) * out.pressure, 1e-12, 1, "%s flat: force on main node %d = N_a A p n", fam,
             (int)a);
  for (PetscInt k = 0; k < 1 + nper; k++) {
    for (PetscInt d = 0; d < 3; d++) fsum[d] += R[NU * k + d];
    if (k > 0) hmain += R[NU * k + 3];
  }
  for (PetscInt d = 0; d < 3; d++) Check(log, fsum[d], 0, 1e-12 * in.area * out.pressure, "%s flat: sum of forces, component %d", fam, (int)d);
  CheckRel(log, out.heat_flux, 7 * 30, 1e-12, 1, "%s flat: q = k (theta_m - theta_s)", fam);
  CheckRel(log, R[3], -in.area * out.heat_flux, 1e-12, 1, "%s flat: heat row of s = -A q", fam);
  CheckRel(log, hmain, in.area * out.heat_flux, 1e-12, 1, "%s flat: heat rows of the main nodes sum to +A q", fam);

  /* sliding (LAGRANGE) heats: the thermal rows sum to -A eta D */
  law.friction = TSL_CONTACT_FRICTION_LAGRANGE;
  law.mu       = 0.2;
  law.slip_tol = 1e-9;
  law.eta      = 0.8;
  law.f        = 0.3;
  in.u[0][0]   = 0.03;
  in.u[0][1]   = -0.04;
  {
    PetscReal xi[2] = {cref[0], cref[1]}, hsum = 0;

    PetscCall(TslContactStateStart3(xi, &in.hist));
    PetscCall(TslContactElement3(&law, &in, R, NULL, &out));
    for (PetscInt k = 0; k < 1 + nper; k++) hsum += R[NU * k + 3];
    CheckRel(log, PetscSqrtReal(out.slip * out.slip + out.slip_circ * out.slip_circ), 0.05, 1e-12, 1, "%s flat: slip |ds| = 0.05", fam);
    CheckRel(log, out.dissipation_rate, law.mu * out.pressure * 0.05 / in.dt, 1e-9, 1, "%s flat: dissipation = mu pN |ds| / dt (LAGRANGE)", fam);
    CheckRel(log, hsum, -in.area * law.eta * out.dissipation_rate, 1e-12, 1, "%s flat: heat rows sum to -A eta D", fam);
    CheckRel(log, R[3], -in.area * (out.heat_flux + law.f * law.eta * out.dissipation_rate), 1e-12, 1, "%s flat: heat row of s = -A (q + f eta D)",
             fam);
  }

  /* beyond an edge: outside (the quad's xi = +1 edge, the triangles' hypotenuse) */
  in.u[0][0] = in.u[0][1] = 0;
  in.x[0][0]              = kind == QUAD4 ? 2.5 : 1.5;
  in.x[0][1]              = kind == QUAD4 ? 1 : 1.2;
  PetscCall(TslContactElement3(&law, &in, R, NULL, &out));
  Check(log, out.outside, 1, 0, "%s flat: node beyond an edge is outside (xi %g, eta %g)", fam, (double)out.xi_raw, (double)out.eta_raw);

  /* smoothing with nodal normals all equal to the face's: the face normal to the last bit */
  in.x[0][0]   = centre[0] * 0.3;
  in.x[0][1]   = centre[1] * 0.2;
  in.smoothing = 0.3;
  for (PetscInt a = 0; a < nper; a++) in.nodal_normal[a][2] = 1;
  PetscCall(TslContactElement3(&law, &in, R, NULL, &out));
  Check(log, out.normal[0], 0, 0, "%s flat, smoothed, equal nodal normals: n_x exactly 0", fam);
  Check(log, out.normal[1], 0, 0, "%s flat, smoothed, equal nodal normals: n_y exactly 0", fam);
  Check(log, out.normal_z, 1, 0, "%s flat, smoothed, equal nodal normals: n_z exactly 1", fam);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Closest points: points at distance g along the normal of known face points must project back onto them
 * (warped quad4, curved tri6, tri3), the residual (p - x) x n at round-off. */
static PetscErrorCode CheckProjection(TestLog *log, PetscInt kind)
{
  PetscReal X[TSL_CONTACT3_MAX_FACE_NODES][3], x[3 * TSL_CONTACT3_MAX_FACE_NODES];
  PetscReal targets[4][2] = {{0.1, 0.2}, {0.7, 0.2}, {0.05, 0.9}, {0.3, 0.3}}, err = 0, res = 0;

  PetscFunctionBeginUser;
  FaceNodes(kind, X);
  for (PetscInt a = 0; a < TslContactFace3Nodes(kind); a++)
    for (PetscInt d = 0; d < 3; d++) x[3 * a + d] = X[a][d] + 100; /* far from the origin: relative arithmetic */
  for (PetscInt i = 0; i < 4; i++)
    for (PetscInt sg = -1; sg <= 1; sg += 2) {
      PetscReal t[2] = {kind == QUAD4 ? 2 * targets[i][0] - 1 : targets[i][0], kind == QUAD4 ? 2 * targets[i][1] - 0.6 : targets[i][1]};
      PetscReal p[3], n[3], q[3], xi[2], r[3], c[3];

      if (kind != QUAD4 && t[0] + t[1] > 1) t[0] = 1 - t[1] - 0.02;
      PetscCall(TslContactFace3Evaluate(kind, x, t, p, n));
      for (PetscInt d = 0; d < 3; d++) q[d] = p[d] + sg * 0.05 * n[d];
      PetscCall(TslContactFace3Project(kind, x, q, xi));
      err = PetscMax(err, PetscMax(PetscAbsReal(xi[0] - t[0]), PetscAbsReal(xi[1] - t[1])));
      PetscCall(TslContactFace3Evaluate(kind, x, xi, p, n));
      for (PetscInt d = 0; d < 3; d++) r[d] = q[d] - p[d];
      c[0] = r[1] * n[2] - r[2] * n[1];
      c[1] = r[2] * n[0] - r[0] * n[2];
      c[2] = r[0] * n[1] - r[1] * n[0];
      res  = PetscMax(res, PetscSqrtReal(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]));
    }
  Check(log, err, 0, 1e-11, "%s: closest point recovers the foot of the normal (max |xi - xi*|)", FamilyName(kind));
  Check(log, res, 0, 1e-12, "%s: projection residual |(p - x) x n| (round-off)", FamilyName(kind));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode CheckFaceTools(TestLog *log)
{
  PetscReal w[TSL_CONTACT3_MAX_FACE_NODES], A, sum;

  PetscFunctionBeginUser;
  Check(log, TslContactFace3Find("TRI3"), TRI3, 0, "family of tri3");
  Check(log, TslContactFace3Find("quad4"), QUAD4, 0, "family of quad4");
  Check(log, TslContactFace3Find("tri6"), TRI6, 0, "family of tri6");
  Check(log, TslContactFace3Find("quad8"), -1, 0, "quad8 not supported");
  Check(log, TslContactFace3Nodes(TRI6), 6, 0, "tri6 nodes");

  /* tributary weights */
  {
    const PetscReal tri3[9]  = {0, 0, 1, 3, 0, 1, 0, 2, 1};                                /* area 3 */
    const PetscReal quad[12] = {0, 0, 0, 4, 0, 0, 3, 2, 0, 1, 2, 0};                       /* trapezoid, area 6 */
    const PetscReal tri6[18] = {0, 0, 0, 3, 0, 0, 0, 2, 0, 1.5, 0, 0, 1.5, 1, 0, 0, 1, 0}; /* area 3 */

    PetscCall(TslContactFace3Integrate(TRI3, tri3, w, &A));
    CheckRel(log, A, 3, 1e-14, 1, "tri3: area");
    for (PetscInt a = 0; a < 3; a++) CheckRel(log, w[a], 1, 1e-14, 1, "tri3: weight %d = A/3", (int)a);
    PetscCall(TslContactFace3Integrate(QUAD4, quad, w, &A));
    sum = w[0] + w[1] + w[2] + w[3];
    CheckRel(log, A, 6, 1e-14, 1, "quad4 trapezoid: area");
    CheckRel(log, sum, 6, 1e-14, 1, "quad4 trapezoid: weights sum to the area");
    /* int N_a dA over the trapezoid (0,0),(4,0),(3,2),(1,2) (exact, by hand/sympy): 5/3 on the long side, 4/3 on the short */
    CheckRel(log, w[0], 5.0 / 3, 1e-14, 1, "quad4 trapezoid: weight of a long-side node int N_a dA = 5/3");
    CheckRel(log, w[2], 4.0 / 3, 1e-14, 1, "quad4 trapezoid: weight of a short-side node int N_a dA = 4/3");
    PetscCall(TslContactFace3Integrate(TRI6, tri6, w, &A));
    CheckRel(log, A, 3, 1e-14, 1, "tri6: area");
    for (PetscInt a = 0; a < 3; a++) CheckRel(log, w[a], 3.0 / 12, 1e-14, 1, "tri6: corner weight %d = A/12", (int)a);
    for (PetscInt a = 3; a < 6; a++) CheckRel(log, w[a], 3.0 / 4, 1e-14, 1, "tri6: midside weight %d = A/4", (int)a);
  }
  /* a warped quad: the weights sum to the integrated area */
  {
    PetscReal X[4][3], x[12];
    FaceNodes(QUAD4, X);
    for (PetscInt i = 0; i < 12; i++) x[i] = X[i / 3][i % 3];
    PetscCall(TslContactFace3Integrate(QUAD4, x, w, &A));
    CheckRel(log, w[0] + w[1] + w[2] + w[3], A, 1e-14, 1, "warped quad4: weights sum to the area");
  }

  /* bounding boxes contain sampled points of the curved tri6 and the warped quad4 */
  for (PetscInt kind = 0; kind < 3; kind++) {
    PetscReal X[TSL_CONTACT3_MAX_FACE_NODES][3], x[18], box[6], worst = PETSC_MAX_REAL;
    FaceNodes(kind, X);
    for (PetscInt a = 0; a < TslContactFace3Nodes(kind); a++)
      for (PetscInt d = 0; d < 3; d++) x[3 * a + d] = X[a][d];
    PetscCall(TslContactFace3Box(kind, x, box));
    for (PetscInt i = 0; i <= 20; i++)
      for (PetscInt j = 0; j <= 20; j++) {
        PetscReal xi[2] = {kind == QUAD4 ? -1 + 0.1 * i : 0.05 * i, kind == QUAD4 ? -1 + 0.1 * j : 0.05 * j}, p[3];
        if (kind != QUAD4 && i + j > 20) continue;
        PetscCall(TslContactFace3Evaluate(kind, x, xi, p, NULL));
        for (PetscInt d = 0; d < 3; d++) worst = PetscMin(worst, PetscMin(p[d] - box[d], box[d + 3] - p[d]));
      }
    CheckAtLeast(log, worst, -1e-15, "%s: bounding box contains the face (least margin)", FamilyName(kind));
  }

  /* history: start, and transfer between coplanar neighbours (quad -> quad, quad -> tri3) */
  {
    const PetscReal qa[12] = {0, 0, 0, 2, 0, 0, 2, 2, 0, 0, 2, 0}, qb[12] = {2, 0, 0, 4, 0, 0, 4, 2, 0, 2, 2, 0}, tb[9] = {2, 0, 0, 4, 0, 0, 2, 2, 0};
    TslContactState h;
    PetscReal       xi[2] = {0.6, -0.3}, pa[3], pb[3];

    PetscCall(TslContactStateStart3(xi, &h));
    Check(log, h.xi_old + h.xi_anchor, 1.2, 0, "start: xi_old = xi_anchor = xi");
    Check(log, h.eta_old + h.eta_anchor, -0.6, 0, "start: eta_old = eta_anchor = eta");
    Check(log, h.lambda + h.w_old + h.w_anchor, 0, 0, "start: lambda = w = 0");
    h.xi_old     = 1.3; /* beyond the shared edge x = 2 */
    h.eta_old    = 0.2;
    h.xi_anchor  = 1.1;
    h.eta_anchor = -0.4;
    h.lambda     = 42;
    {
      TslContactState g     = h;
      PetscReal       xo[2] = {h.xi_old, h.eta_old}, xn[2];

      PetscCall(TslContactStateTransfer3(QUAD4, qa, QUAD4, qb, &g));
      PetscCall(TslContactFace3Evaluate(QUAD4, qa, xo, pa, NULL));
      xn[0] = g.xi_old, xn[1] = g.eta_old;
      PetscCall(TslContactFace3Evaluate(QUAD4, qb, xn, pb, NULL));
      Check(log, PetscAbsReal(pa[0] - pb[0]) + PetscAbsReal(pa[1] - pb[1]) + PetscAbsReal(pa[2] - pb[2]), 0, 1e-14,
            "transfer quad4 -> quad4: the same physical point (start of the increment)");
      Check(log, g.xi_anchor, 1.1 - 2, 1e-14, "transfer quad4 -> quad4: anchor xi");
      Check(log, g.eta_anchor, -0.4, 1e-14, "transfer quad4 -> quad4: anchor eta");
      Check(log, g.lambda, 42, 0, "transfer: lambda kept");
      g = h;
      PetscCall(TslContactStateTransfer3(QUAD4, qa, TRI3, tb, &g));
      xn[0] = g.xi_old, xn[1] = g.eta_old;
      PetscCall(TslContactFace3Evaluate(TRI3, tb, xn, pb, NULL));
      Check(log, PetscAbsReal(pa[0] - pb[0]) + PetscAbsReal(pa[1] - pb[1]) + PetscAbsReal(pa[2] - pb[2]), 0, 1e-14,
            "transfer quad4 -> tri3: the same physical point");
    }
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Penalty friction on a flat quad and on the warped one: stick below mu pN, |tT| = mu pN slipping, and the
 * anchor left so that the next solve from it sees exactly the elastic slip (|tT| = mu pN, at the stick limit). */
static PetscErrorCode CheckFriction(TestLog *log, PetscInt kind, PetscBool warped)
{
  TslContactLaw    law;
  TslContactInput3 in;
  TslContactOutput out;
  const char      *fam = FamilyName(kind), *shape = warped ? "warped" : "flat";
  PetscReal        R[MAXD], mup, tmag, start[2];

  PetscFunctionBeginUser;
  PetscCall(TslContactLawSetDefaults(&law));
  law.eps_n    = 1e4;
  law.friction = TSL_CONTACT_FRICTION_PENALTY;
  law.mu       = 0.25;
  law.eps_t    = 2e3;
  law.eta      = 0;
  if (warped) {
    const PetscReal t[2] = {0.1, -0.2};
    PetscCall(CaseSetUp(kind, t, -0.005, 0, &in));
  } else {
    FlatFace(kind, &in);
    in.x[0][0] = in.x[0][1] = 0.9;
    in.u[0][2]              = -0.005;
  }
  PetscCall(TslContactElement3(&law, &in, R, NULL, &out));
  start[0] = out.xi;
  start[1] = out.eta;
  PetscCall(TslContactStateStart3(start, &in.hist));
  mup = law.mu * out.pressure;
  /* stick: a slide of 0.5 mu pN / eps_t */
  in.u[0][0] += 0.5 * mup / law.eps_t;
  PetscCall(TslContactElement3(&law, &in, R, NULL, &out));
  tmag = PetscSqrtReal(out.shear * out.shear + out.shear_circ * out.shear_circ);
  Check(log, out.status, TSL_CONTACT_STICK, 0, "%s %s penalty: small slide sticks", fam, shape);
  CheckAtLeast(log, mup - tmag, 0.4 * mup, "%s %s penalty: stick |tT| below mu pN", fam, shape);
  /* slip: a diagonal slide of 5 mu pN / eps_t */
  in.u[0][0] += 3 * mup / law.eps_t;
  in.u[0][1] += 3 * mup / law.eps_t;
  PetscCall(TslContactElement3(&law, &in, R, NULL, &out));
  mup  = law.mu * out.pressure;
  tmag = PetscSqrtReal(out.shear * out.shear + out.shear_circ * out.shear_circ);
  Check(log, out.status, TSL_CONTACT_SLIP, 0, "%s %s penalty: large slide slips", fam, shape);
  CheckRel(log, tmag, mup, 1e-12, 1, "%s %s penalty: slipping |tT| = mu pN", fam, shape);
  /* the anchor at the elastic slip: the same configuration from it is at the stick limit */
  in.hist.xi_anchor  = out.xi_anchor;
  in.hist.eta_anchor = out.eta_anchor;
  PetscCall(TslContactElement3(&law, &in, R, NULL, &out));
  tmag = PetscSqrtReal(out.shear * out.shear + out.shear_circ * out.shear_circ);
  CheckRel(log, tmag, mup, 1e-9, 1, "%s %s penalty: from the updated anchor |tT| = mu pN (elastic slip mu pN / eps_t)", fam, shape);
  PetscFunctionReturn(PETSC_SUCCESS);
}

int main(int argc, char **argv)
{
  TestLog log = {0, 0};

  PetscCall(PetscInitialize(&argc, &argv, NULL, NULL));
  for (PetscInt kind = 0; kind < 3; kind++) {
    PetscCall(CheckTangents(&log, kind, 0));
    PetscCall(CheckTangents(&log, kind, 0.2));
    PetscCall(CheckFlat(&log, kind));
    PetscCall(CheckProjection(&log, kind));
    PetscCall(CheckFriction(&log, kind, PETSC_FALSE));
    PetscCall(CheckFriction(&log, kind, PETSC_TRUE));
  }
  PetscCall(CheckFaceTools(&log));
  PetscCall(PetscFinalize());
  return Summary(&log);
}
