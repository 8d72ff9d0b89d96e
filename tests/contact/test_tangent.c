/* The consistent tangent of the contact element against central finite differences of its residual,
 * compared block by block (uu, u-theta, theta-u, theta-theta), each relative to its own scale, in open,
 * stick and slip states, with pressure- and clearance-dependent conductance, radiation, frictional heating,
 * augmented Lagrange, axisymmetry and a smoothed corner, on a straight line2 segment (5-node element with
 * both neighbours) and on a curved line3 segment (the same cases; 8 nodes with both neighbours). */
#include "check.h"

#define NO (TSL_CONTACT_MAX_FACE_NODES - 1) /* other nodes of a neighbouring segment */

typedef struct {
  TslContactInput in;
  PetscReal       x_prev[2 * NO], u_prev[3 * NO], x_next[2 * NO], u_next[3 * NO];
} Case;

/* Address of unknown i of the element (node order s, the segment's nodes, [previous], [next]). */
static PetscReal *Unknown(Case *c, PetscInt i)
{
  PetscInt node = i / 3, comp = i % 3, nper = TslContactFaceGet(c->in.face)->geom->nnode;

  if (node <= nper) return &c->in.u[node][comp];
  node -= 1 + nper;
  if (c->in.x_prev) {
    if (node < nper - 1) return &c->u_prev[3 * node + comp];
    node -= nper - 1;
  }
  return &c->u_next[3 * node + comp];
}

static PetscErrorCode CheckCase(TestLog *log, const char *name, const TslContactLaw *law, Case *c, TslContactStatus status)
{
  PetscReal        K[TSL_CONTACT_MAX_DOF * TSL_CONTACT_MAX_DOF], Kfd[TSL_CONTACT_MAX_DOF * TSL_CONTACT_MAX_DOF];
  PetscReal        Rp[TSL_CONTACT_MAX_DOF], Rm[TSL_CONTACT_MAX_DOF], R0[TSL_CONTACT_MAX_DOF];
  TslContactOutput out, outp, outm;
  PetscInt         nd;
  PetscInt         kind[TSL_CONTACT_MAX_DOF];
  const char      *kname[2] = {"u", "theta"};

  PetscFunctionBeginUser;
  if (c->in.x_prev) c->in.u_prev = c->u_prev;
  if (c->in.x_next) c->in.u_next = c->u_next;
  PetscCall(TslContactElement(law, &c->in, R0, K, &out));
  nd = 3 * out.nnode;
  Check(log, (PetscReal)out.status, status, 0, "%s: status (gap %g, p %g, tT %g)", name, (double)out.gap, (double)out.pressure, (double)out.shear);
  for (PetscInt j = 0; j < nd; j++) {
    PetscReal *v = Unknown(c, j), v0 = *v, h = (j % 3 == 2) ? 1e-5 * PetscMax(1, PetscAbsReal(v0)) : 1e-7;

    *v = v0 + h;
    PetscCall(TslContactElement(law, &c->in, Rp, NULL, &outp));
    *v = v0 - h;
    PetscCall(TslContactElement(law, &c->in, Rm, NULL, &outm));
    *v = v0;
    PetscCheck(outp.status == out.status && outm.status == out.status, PETSC_COMM_SELF, PETSC_ERR_PLIB,
               "%s: perturbation of unknown %d changes the contact status", name, (int)j);
    for (PetscInt i = 0; i < nd; i++) Kfd[i * nd + j] = (Rp[i] - Rm[i]) / (2 * h);
  }
  for (PetscInt i = 0; i < nd; i++) kind[i] = i % 3 == 2;
  CheckTangentBlocks(log, name, nd, K, Kfd, kind, 2, kname);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Inclined main segment (body below-right), secondary slightly displaced, non-trivial temperatures.
 * line2: the straight segment (2, 0.3) -> (0, 0), s at (0.8, 0.12 + gap), i.e. gap ~ that along y.
 * line3: the same ends, the midside node 0.08 out of the chord's middle (a convex arc) and moved, s put
 * at the given gap from the curved segment along its normal at xi = 0.6. */
static PetscErrorCode CaseSetUp(Case *c, PetscReal gap, TslContactFaceKind face)
{
  PetscReal xi;

  PetscFunctionBeginUser;
  const PetscReal x1[2] = {2, 0.3}, x2[2] = {0, 0}, xs[2] = {0.8, 0.12 + gap};

  memset(c, 0, sizeof(*c));
  c->in           = InputSetUp(xs, x1, x2);
  c->in.face      = face;
  c->in.thickness = 1.5;
  c->in.length    = 0.4;
  c->in.dt        = 0.2;
  c->in.u[0][0]   = 0.01;
  c->in.u[0][1]   = -0.004;
  c->in.u[1][0]   = 0.002;
  c->in.u[2][1]   = 0.003;
  c->in.u[0][2]   = 40;
  c->in.u[1][2]   = 120;
  c->in.u[2][2]   = 90;
  if (face == TSL_CONTACT_FACE_LINE3) {
    const PetscReal n[2] = {-0.3 / PetscSqrtReal(4.09), 2 / PetscSqrtReal(4.09)};
    PetscReal       xm[2], nm[2];

    for (PetscInt d = 0; d < 2; d++) c->in.x[3][d] = 0.5 * (x1[d] + x2[d]) + 0.08 * n[d];
    c->in.u[3][0] = -0.001;
    c->in.u[3][1] = 0.002;
    c->in.u[3][2] = 100;
    PetscCall(TslContactSurfacePoint(&c->in, 0.6, xm, nm));
    for (PetscInt d = 0; d < 2; d++) c->in.x[0][d] = xm[d] + gap * nm[d] - c->in.u[0][d];
  }
  PetscCall(TslContactProject(&c->in, &xi, NULL, NULL));
  c->in.hist.xi_old = c->in.hist.xi_anchor = xi + 0.003;
  PetscFunctionReturn(PETSC_SUCCESS);
}

static const char *Name(char buf[128], const char *family, const char *name)
{
  snprintf(buf, 128, "%s: %s", family, name);
  return buf;
}

/* Every case of the law table on a segment of family face; names are prefixed with the family. */
static PetscErrorCode CheckAll(TestLog *log, TslContactFaceKind face)
{
  TslContactLaw   law;
  Case            c;
  const PetscReal kp[2] = {100, 400}, kv[2] = {20, 5};
  char            name[128];
  const char     *fam = TslContactFaceGet(face)->geom->name;

  PetscFunctionBeginUser;
  /* open: clearance conductance and radiation */
  TestLawSetUp(&law, PETSC_TRUE);
  PetscCall(CaseSetUp(&c, 0.03, face));
  PetscCall(CheckCase(log, Name(name, fam, "open, clearance conductance + radiation"), &law, &c, TSL_CONTACT_OPEN));

  /* stick with pressure-dependent conductance */
  law.conductance = TSL_CONTACT_CONDUCTANCE_PRESSURE;
  law.k_n         = 2;
  law.k_arg       = kp;
  law.k_value     = kv;
  law.F_n         = 0;
  PetscCall(CaseSetUp(&c, -0.01, face));
  c.in.hist.xi_anchor = c.in.hist.xi_old - 0.0015;
  PetscCall(CheckCase(log, Name(name, fam, "stick, pressure conductance"), &law, &c, TSL_CONTACT_STICK));

  /* slip with pressure conductance, radiation and frictional heating */
  law.F_n = 2;
  PetscCall(CaseSetUp(&c, -0.01, face));
  c.in.hist.xi_anchor = c.in.hist.xi_old + 0.02;
  PetscCall(CheckCase(log, Name(name, fam, "slip, pressure conductance + radiation + heating"), &law, &c, TSL_CONTACT_SLIP));

  /* axisymmetric slip the other way */
  PetscCall(CaseSetUp(&c, -0.012, face));
  c.in.kin            = TSL_KIN_AXISYMMETRIC;
  c.in.hist.xi_anchor = c.in.hist.xi_old - 0.03;
  PetscCall(CheckCase(log, Name(name, fam, "axisymmetric slip, reversed"), &law, &c, TSL_CONTACT_SLIP));

  /* automatic penalty friction (plain *FRICTION): stick stiffness mu pN / elastic slip, stick and slip */
  law.eps_t        = 0;
  law.elastic_slip = 0.004;
  PetscCall(CaseSetUp(&c, -0.01, face));
  c.in.hist.xi_anchor = c.in.hist.xi_old - 0.0015;
  PetscCall(CheckCase(log, Name(name, fam, "automatic penalty, stick"), &law, &c, TSL_CONTACT_STICK));
  PetscCall(CaseSetUp(&c, -0.01, face));
  c.in.hist.xi_anchor = c.in.hist.xi_old + 0.02;
  PetscCall(CheckCase(log, Name(name, fam, "automatic penalty, slip + heating"), &law, &c, TSL_CONTACT_SLIP));
  law.eps_t        = 5e3;
  law.elastic_slip = 0;

  /* Lagrange friction, all motion dissipated */
  law.friction = TSL_CONTACT_FRICTION_LAGRANGE;
  law.slip_tol = 1e-10;
  PetscCall(CaseSetUp(&c, -0.01, face));
  PetscCall(CheckCase(log, Name(name, fam, "Lagrange slip + heating"), &law, &c, TSL_CONTACT_SLIP));

  /* augmented Lagrange normal, penalty stick */
  law.friction = TSL_CONTACT_FRICTION_PENALTY;
  law.normal   = TSL_CONTACT_NORMAL_AUGMENTED;
  PetscCall(CaseSetUp(&c, 0.001, face));
  c.in.hist.lambda    = 150;
  c.in.hist.xi_anchor = c.in.hist.xi_old - 0.0005;
  PetscCall(CheckCase(log, Name(name, fam, "augmented Lagrange, stick"), &law, &c, TSL_CONTACT_STICK));
  law.normal = TSL_CONTACT_NORMAL_PENALTY;

  /* smoothed corner: secondary over the rounded zone near m1 and near m2 (line2: 5-node element; line3:
   * curved neighbours too, 8 nodes) */
  for (PetscInt end = 0; end < 2; end++) {
    PetscCall(CaseSetUp(&c, -0.01, face));
    c.in.smoothing = 0.2;
    c.x_prev[0]    = 3.0;
    c.x_prev[1]    = 0.9; /* previous segment m0 -> m1 turns up: a convex corner at m1 */
    c.x_next[0]    = -1.0;
    c.x_next[1]    = -0.2;
    c.u_prev[0]    = 0.001;
    c.u_next[1]    = -0.002;
    if (face == TSL_CONTACT_FACE_LINE3) {
      /* midside nodes of the neighbours, 0.03 out of their chords' middles (convex arcs), slightly moved */
      const PetscReal np[2] = {-0.6 / PetscSqrtReal(1.36), 1 / PetscSqrtReal(1.36)}, nn[2] = {-0.2 / PetscSqrtReal(1.04), 1 / PetscSqrtReal(1.04)};
      for (PetscInt d = 0; d < 2; d++) {
        c.x_prev[2 + d] = 0.5 * (c.x_prev[d] + c.in.x[1][d]) + 0.03 * np[d];
        c.x_next[2 + d] = 0.5 * (c.x_next[d] + c.in.x[2][d]) + 0.03 * nn[d];
      }
      c.u_prev[4] = 0.0005;
      c.u_next[3] = -0.0007;
    }
    c.in.x_prev = c.x_prev;
    c.in.x_next = c.x_next;
    c.in.u_prev = c.u_prev;
    c.in.u_next = c.u_next;
    /* put s over the zone, 0.01 inside the main body: xi ~ 0.08 (near m1) or 0.93 (near m2); the segment
     * x1 -> x2 runs along (-2, -0.3), so its outward normal is (-0.3, 2)/|.| (line2) */
    {
      PetscReal xi = end == 0 ? 0.08 : 0.93, n[2] = {-0.3 / PetscSqrtReal(4.09), 2 / PetscSqrtReal(4.09)}, xr, xm[2];

      if (face == TSL_CONTACT_FACE_LINE2) {
        for (PetscInt d = 0; d < 2; d++) c.in.x[0][d] = (1 - xi) * c.in.x[1][d] + xi * c.in.x[2][d] - 0.01 * n[d] - c.in.u[0][d];
      } else {
        PetscCall(TslContactSurfacePoint(&c.in, xi, xm, n));
        for (PetscInt d = 0; d < 2; d++) c.in.x[0][d] = xm[d] - 0.01 * n[d] - c.in.u[0][d];
      }
      PetscCall(TslContactProject(&c.in, &xr, NULL, NULL));
      c.in.hist.xi_old    = xr + (end == 0 ? 0.01 : -0.01);
      c.in.hist.xi_anchor = c.in.hist.xi_old;
      Check(log, (PetscReal)(end == 0 ? xr < 0.2 : xr > 0.8), 1, 0, "%s: smoothed case %d: xi = %g in rounded zone", fam, (int)end, (double)xr);
    }
    {
      TslContactOutput out;
      PetscInt         nper = TslContactFaceGet(face)->geom->nnode;

      PetscCall(TslContactElement(&law, &c.in, NULL, NULL, &out));
      Check(log, (PetscReal)out.nnode, 1 + nper + 2 * (nper - 1), 0, "%s: smoothed case %d: element nodes (s, segment, both neighbours)", fam,
            (int)end);
    }
    PetscCall(CheckCase(log, Name(name, fam, end == 0 ? "smoothed corner at m1, slip" : "smoothed corner at m2, slip"), &law, &c, TSL_CONTACT_SLIP));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

int main(int argc, char **argv)
{
  TestLog log = {0, 0};

  PetscCall(PetscInitialize(&argc, &argv, NULL, NULL));
  PetscCall(CheckAll(&log, TSL_CONTACT_FACE_LINE2));
  PetscCall(CheckAll(&log, TSL_CONTACT_FACE_LINE3));
  PetscCall(PetscFinalize());
  return Summary(&log);
}
