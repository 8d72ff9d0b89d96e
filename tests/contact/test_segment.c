/* Surface-to-surface contact points (contact/segment.c):
 *  - the expanded element's tangent (the kernel at a point of a secondary face, chain rule to the face's
 *    nodes) against central finite differences, in stick, slip, open and smoothed states, line2 and line3
 *    secondary faces on line2 and line3 main segments, plane and axisymmetric;
 *  - the expanded residual's sums: force and heat of the secondary face's nodes = the virtual node's;
 *  - segmentation: the break points are the projections of the main nodes, and the Gauss weights of the
 *    pieces sum to the face length (all pieces) and to the overlap length (the pieces over the main
 *    surface), for a straight line2 face and a line3 face with an off-centre midside node. */
#include "check.h"
#include <thermoslide/contact_s2s.h>

#define NS TSL_CONTACT_MAX_FACE_NODES

typedef struct {
  TslContactInput    in;
  TslContactFaceKind skind;
  PetscReal          zeta;
  PetscReal          X[2 * NS], U[TSL_CONTACT_MAX_NODE_DOF * NS]; /* secondary face */
  PetscReal          x_prev[2 * NS], u_prev[3 * NS], x_next[2 * NS], u_next[3 * NS];
} Case;

/* Address of expanded unknown i: secondary face nodes, then the kernel's nodes 1.. (segment, prev, next). */
static PetscReal *Unknown(Case *c, PetscInt i)
{
  PetscInt node = i / 3, comp = i % 3, nsn = TslContactFaceGet(c->skind)->geom->nnode, nper = TslContactFaceGet(c->in.face)->geom->nnode;

  if (node < nsn) return &c->U[3 * node + comp];
  node -= nsn;
  if (node < nper) return &c->in.u[1 + node][comp];
  node -= nper;
  if (c->in.x_prev) {
    if (node < nper - 1) return &c->u_prev[3 * node + comp];
    node -= nper - 1;
  }
  return &c->u_next[3 * node + comp];
}

static PetscErrorCode Eval(const TslContactLaw *law, Case *c, PetscReal R[], PetscReal K[], TslContactOutput *out)
{
  PetscFunctionBeginUser;
  PetscCall(TslContactPointSetUp(c->skind, c->X, c->U, c->zeta, &c->in));
  if (R) PetscCall(PetscArrayzero(R, TSL_CONTACT_S2S_MAX_DOF)); /* the point's block is added to R, K */
  if (K) PetscCall(PetscArrayzero(K, TSL_CONTACT_S2S_MAX_DOF * TSL_CONTACT_S2S_MAX_DOF));
  PetscCall(TslContactPointElement(law, &c->in, c->skind, c->zeta, R, K, out));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode CheckCase(TestLog *log, const char *name, const TslContactLaw *law, Case *c, TslContactStatus status)
{
  static PetscReal K[TSL_CONTACT_S2S_MAX_DOF * TSL_CONTACT_S2S_MAX_DOF], Kfd[TSL_CONTACT_S2S_MAX_DOF * TSL_CONTACT_S2S_MAX_DOF];
  PetscReal        Rp[TSL_CONTACT_S2S_MAX_DOF], Rm[TSL_CONTACT_S2S_MAX_DOF], R0[TSL_CONTACT_S2S_MAX_DOF], Rk[TSL_CONTACT_MAX_DOF];
  TslContactOutput out, o;
  PetscInt         nd, nsn = TslContactFaceGet(c->skind)->geom->nnode;
  PetscReal        scale = 0, err = 0, sum[3] = {0, 0, 0};

  PetscFunctionBeginUser;
  if (c->in.x_prev) c->in.u_prev = c->u_prev;
  if (c->in.x_next) c->in.u_next = c->u_next;
  PetscCall(Eval(law, c, R0, K, &out));
  nd = 3 * out.nnode;
  Check(log, (PetscReal)out.status, status, 0, "%s: status (gap %g, p %g)", name, (double)out.gap, (double)out.pressure);
  /* the secondary face's rows add up to the virtual node's */
  PetscCall(TslContactElement(law, &c->in, Rk, NULL, &o));
  for (PetscInt b = 0; b < nsn; b++)
    for (PetscInt k = 0; k < 3; k++) sum[k] += R0[3 * b + k];
  for (PetscInt k = 0; k < 3; k++) Check(log, sum[k], Rk[k], 1e-12 * (1 + PetscAbsReal(Rk[k])), "%s: sum of the face's rows %d = kernel's", name, (int)k);
  for (PetscInt j = 0; j < nd; j++) {
    PetscReal *v = Unknown(c, j), v0 = *v, h = (j % 3 == 2) ? 1e-5 * PetscMax(1, PetscAbsReal(v0)) : 1e-7;
    TslContactOutput op, om;

    *v = v0 + h;
    PetscCall(Eval(law, c, Rp, NULL, &op));
    *v = v0 - h;
    PetscCall(Eval(law, c, Rm, NULL, &om));
    *v = v0;
    PetscCheck(op.status == out.status && om.status == out.status, PETSC_COMM_SELF, PETSC_ERR_PLIB, "%s: perturbation %d changes the status", name, (int)j);
    for (PetscInt i = 0; i < nd; i++) Kfd[i * nd + j] = (Rp[i] - Rm[i]) / (2 * h);
  }
  for (PetscInt i = 0; i < nd * nd; i++) {
    scale = PetscMax(scale, PetscAbsReal(Kfd[i]));
    err   = PetscMax(err, PetscAbsReal(K[i] - Kfd[i]));
  }
  Check(log, err / scale, 0, 1e-6, "%s: max|K - K_fd| / max|K_fd| (%d dofs, scale %.3g)", name, (int)nd, (double)scale);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Main segment (2, 0.3) -> (0, 0) (body below), its midside node 0.08 out for line3; the secondary face
 * runs the other way above it (body above: its first end on the right), midside node 0.02 out of the
 * middle for line3, moved along the normal so that the point at zeta has the given gap. */
static PetscErrorCode CaseSetUp(Case *c, PetscReal gap, TslContactFaceKind mface, TslContactFaceKind sface, PetscReal zeta)
{
  const PetscReal x1[2] = {2, 0.3}, x2[2] = {0, 0}, n[2] = {-0.3 / PetscSqrtReal(4.09), 2 / PetscSqrtReal(4.09)};
  PetscReal       xi;

  PetscFunctionBeginUser;
  memset(c, 0, sizeof(*c));
  c->in           = InputSetUp(x1, x1, x2);
  c->in.face      = mface;
  c->skind        = sface;
  c->zeta         = zeta;
  c->in.thickness = 1.5;
  c->in.length    = 0.13;
  c->in.dt        = 0.2;
  c->in.u[1][0]   = 0.002;
  c->in.u[2][1]   = 0.003;
  c->in.u[1][2]   = 120;
  c->in.u[2][2]   = 90;
  if (mface == TSL_CONTACT_FACE_LINE3) {
    for (PetscInt d = 0; d < 2; d++) c->in.x[3][d] = 0.5 * (x1[d] + x2[d]) + 0.08 * n[d];
    c->in.u[3][0] = -0.001;
    c->in.u[3][2] = 100;
  }
  /* secondary face: first end (1.9, 0.285), second (0.3, 0.045), shifted by gap along n */
  for (PetscInt d = 0; d < 2; d++) {
    c->X[d]     = (d ? 0.285 : 1.9) + gap * n[d];
    c->X[2 + d] = (d ? 0.045 : 0.3) + gap * n[d];
    if (sface == TSL_CONTACT_FACE_LINE3) c->X[4 + d] = 0.5 * (c->X[d] + c->X[2 + d]) - 0.02 * n[d];
  }
  c->U[0] = 0.01, c->U[1] = -0.004, c->U[2] = 40;
  c->U[3] = 0.008, c->U[4] = -0.006, c->U[5] = 45;
  if (sface == TSL_CONTACT_FACE_LINE3) c->U[6] = 0.009, c->U[7] = -0.003, c->U[8] = 43;
  /* move the secondary face along the normal until the point's gap is the one asked for */
  for (PetscInt it = 0; it < 3; it++) {
    PetscReal g, nm[2];
    PetscCall(TslContactPointSetUp(sface, c->X, c->U, zeta, &c->in));
    PetscCall(TslContactProject(&c->in, &xi, &g, nm));
    for (PetscInt b = 0; b < NS; b++)
      for (PetscInt d = 0; d < 2; d++) c->X[2 * b + d] += (gap - g) * nm[d];
  }
  PetscCall(TslContactPointSetUp(sface, c->X, c->U, zeta, &c->in));
  PetscCall(TslContactProject(&c->in, &xi, NULL, NULL));
  c->in.hist.xi_old = c->in.hist.xi_anchor = xi + 0.003;
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode CheckTangents(TestLog *log, TslContactFaceKind mface, TslContactFaceKind sface)
{
  TslContactLaw   law;
  Case            c;
  const PetscReal kp[2] = {100, 400}, kv[2] = {20, 5}, kd[3] = {0, 0.05, 0.2}, kdv[3] = {50, 30, 4}, Fd[2] = {0, 0.1}, Fv[2] = {1, 0.5};
  char            name[160];
  const char     *mf = TslContactFaceGet(mface)->geom->name, *sf = TslContactFaceGet(sface)->geom->name;

  PetscFunctionBeginUser;
  PetscCall(TslContactLawSetDefaults(&law));
  law.eps_n = 2e4, law.mu = 0.3, law.eps_t = 5e3, law.eta = 0.9, law.f = 0.3, law.theta_zero = -273.16;
  law.friction    = TSL_CONTACT_FRICTION_PENALTY;
  law.conductance = TSL_CONTACT_CONDUCTANCE_CLEARANCE, law.k_n = 3, law.k_arg = kd, law.k_value = kdv;
  law.F_n = 2, law.F_clearance = Fd, law.F_value = Fv, law.sigma = 5.67e-8, law.eps_main = 0.8, law.eps_secondary = 0.6;
  PetscCall(CaseSetUp(&c, 0.03, mface, sface, 0.3));
  snprintf(name, sizeof(name), "%s on %s: open, clearance conductance + radiation", sf, mf);
  PetscCall(CheckCase(log, name, &law, &c, TSL_CONTACT_OPEN));

  law.conductance = TSL_CONTACT_CONDUCTANCE_PRESSURE, law.k_n = 2, law.k_arg = kp, law.k_value = kv;
  PetscCall(CaseSetUp(&c, -0.01, mface, sface, 0.62));
  c.in.hist.xi_anchor = c.in.hist.xi_old - 0.0015;
  snprintf(name, sizeof(name), "%s on %s: stick, pressure conductance + radiation", sf, mf);
  PetscCall(CheckCase(log, name, &law, &c, TSL_CONTACT_STICK));

  PetscCall(CaseSetUp(&c, -0.01, mface, sface, 0.45));
  c.in.hist.xi_anchor = c.in.hist.xi_old + 0.1;
  snprintf(name, sizeof(name), "%s on %s: slip + heating", sf, mf);
  PetscCall(CheckCase(log, name, &law, &c, TSL_CONTACT_SLIP));

  PetscCall(CaseSetUp(&c, -0.012, mface, sface, 0.8));
  c.in.kin            = TSL_KIN_AXISYMMETRIC;
  c.in.hist.xi_anchor = c.in.hist.xi_old - 0.1;
  snprintf(name, sizeof(name), "%s on %s: axisymmetric slip", sf, mf);
  PetscCall(CheckCase(log, name, &law, &c, TSL_CONTACT_SLIP));

  law.friction = TSL_CONTACT_FRICTION_LAGRANGE, law.slip_tol = 1e-10;
  PetscCall(CaseSetUp(&c, -0.01, mface, sface, 0.2));
  snprintf(name, sizeof(name), "%s on %s: Lagrange slip + heating", sf, mf);
  PetscCall(CheckCase(log, name, &law, &c, TSL_CONTACT_SLIP));

  /* smoothed corner at m1 (the main segment's first end (2, 0.3)): the point near the secondary face's
   * first end lies over the rounded zone */
  law.friction = TSL_CONTACT_FRICTION_PENALTY;
  PetscCall(CaseSetUp(&c, -0.01, mface, sface, 0.02));
  c.in.smoothing = 0.2;
  c.x_prev[0] = 3.0, c.x_prev[1] = 0.9, c.x_next[0] = -1.0, c.x_next[1] = -0.2;
  c.u_prev[0] = 0.001, c.u_next[1] = -0.002;
  if (mface == TSL_CONTACT_FACE_LINE3)
    for (PetscInt d = 0; d < 2; d++) {
      c.x_prev[2 + d] = 0.5 * (c.x_prev[d] + c.in.x[1][d]);
      c.x_next[2 + d] = 0.5 * (c.x_next[d] + c.in.x[2][d]);
    }
  c.in.x_prev = c.x_prev, c.in.x_next = c.x_next;
  c.in.u_prev = c.u_prev, c.in.u_next = c.u_next;
  {
    PetscReal xi;
    c.in.u_prev = c.u_prev, c.in.u_next = c.u_next;
    PetscCall(TslContactProject(&c.in, &xi, NULL, NULL));
    c.in.hist.xi_old = c.in.hist.xi_anchor = xi + 0.05;
    Check(log, (PetscReal)(xi < 0.2), 1, 0, "%s on %s: smoothed case: xi = %g in the rounded zone", sf, mf, (double)xi);
  }
  snprintf(name, sizeof(name), "%s on %s: smoothed corner, slip", sf, mf);
  PetscCall(CheckCase(log, name, &law, &c, TSL_CONTACT_SLIP));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Secondary face from (3, 1) to (-0.2, 1) (line3: midside node at 0.3 of the way, so the parameter is not
 * proportional to arc length); main nodes along y = 0 at x = -1, 0.5, 1.1, 2.2, 2.9 and 4: the breaks are
 * the projections of the four that fall inside, and the weights of the pieces sum to the face length 3.2
 * and, over the pieces between x = 0.5 and 2.9, to the overlap 2.4. */
static PetscErrorCode CheckSegmentation(TestLog *log, TslContactFaceKind kind)
{
  const PetscReal main_x[6] = {-1, 0.5, 1.1, 2.2, 2.9, 4};
  PetscReal       X[6] = {3, 1, -0.2, 1, 0, 0}, pts[12], zeta[16], zq[TSL_CONTACT_S2S_MAX_GAUSS], wq[TSL_CONTACT_S2S_MAX_GAUSS];
  PetscReal       total = 0, over = 0, len, w[3];
  PetscInt        n, nq;
  const char     *name = TslContactFaceGet(kind)->geom->name;

  PetscFunctionBeginUser;
  if (kind == TSL_CONTACT_FACE_LINE3) X[4] = 3 + 0.3 * (-3.2), X[5] = 1;
  for (PetscInt i = 0; i < 6; i++) pts[2 * i] = main_x[i], pts[2 * i + 1] = 0;
  PetscCall(TslContactSegmentBreaks(kind, X, 6, pts, 1e-9, 16, zeta, &n));
  Check(log, (PetscReal)n, 6, 0, "%s: break count (ends + 4 projections)", name);
  PetscCall(TslContactFaceIntegrate(kind, X, w, &len));
  for (PetscInt i = 0; i + 1 < n; i++) {
    PetscReal mid[2], tx = 0;
    PetscCall(TslContactFaceEvaluate(kind, X, 0.5 * (zeta[i] + zeta[i + 1]), mid, NULL));
    PetscCall(TslContactSegmentRule(kind, X, zeta[i], zeta[i + 1], &nq, zq, wq));
    for (PetscInt q = 0; q < nq; q++) tx += wq[q];
    total += tx;
    if (mid[0] > 0.5 && mid[0] < 2.9) over += tx;
    /* the projection of a main node on the face is the face point whose normal passes through it */
    if (i > 0) {
      PetscReal t[2], p[2];
      PetscCall(TslContactFaceEvaluate(kind, X, zeta[i], p, t));
      for (PetscInt k = 1; k < 5; k++)
        if (PetscAbsReal((main_x[k] - p[0]) * t[0] + (0 - p[1]) * t[1]) < 1e-9 * (1 + PetscAbsReal(t[0]))) tx = -1;
      Check(log, tx, -1, 0, "%s: break %d (%g) is the projection of a main node", name, (int)i, (double)zeta[i]);
    }
  }
  CheckRel(log, over, 2.4, 1e-12, 0, "%s: weights over the main surface = overlap length 2.4", name);
  CheckRel(log, total, len, 1e-12, 0, "%s: weights of all pieces = face length", name);
  PetscFunctionReturn(PETSC_SUCCESS);
}

int main(int argc, char **argv)
{
  TestLog log = {0, 0};

  PetscCall(PetscInitialize(&argc, &argv, NULL, NULL));
  for (PetscInt m = 0; m < 2; m++)
    for (PetscInt s = 0; s < 2; s++) PetscCall(CheckTangents(&log, (TslContactFaceKind)m, (TslContactFaceKind)s));
  PetscCall(CheckSegmentation(&log, TSL_CONTACT_FACE_LINE2));
  PetscCall(CheckSegmentation(&log, TSL_CONTACT_FACE_LINE3));
  PetscCall(PetscFinalize());
  return Summary(&log);
}
