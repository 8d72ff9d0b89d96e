/* Contact with circumferential slip (axisymmetric with twist, CGAX): the relative circumferential
 * displacement w = R_s phi_s - R_m(xi) phi_m(xi) as the second slip component of Coulomb friction.
 *   - laws on a flat cylindrical interface: a pure twist dissipates mu p |dw| and loads the phi rows with
 *     the moments +-A R tW (balanced), a combined axial + circumferential slide of the same magnitude
 *     dissipates what the pure axial one does, the penalty return is radial (along the trial traction,
 *     |t| = mu p) and dissipates mu p (|e| - e_max), a rigid twist of both bodies does not slip, and
 *     TslContactStateStart anchors a new contact at the current relative twist;
 *   - a twist element without twist (phi = 0) gives the rows and columns of the plain axisymmetric one;
 *   - the tangent against central differences of the residual, block by block (u, theta, phi rows and
 *     columns, each block relative to its own scale), in stick and slip for penalty (constant and automatic
 *     stick stiffness) and LAGRANGE friction, on a straight line2 and a curved line3 segment, with the
 *     smoothing neighbours in one case. */
#include "check.h"

#define NO (TSL_CONTACT_MAX_FACE_NODES - 1) /* other nodes of a neighbouring segment */
#define NU 4                                /* unknowns per node with twist: u_r, u_z, theta, phi */

/* ---------------------------------------------------------------------------------------------------
 * Laws on a flat cylindrical interface r = Rc: main segment m1 = (Rc, 0) -> m2 = (Rc, 1) (tau = +z, outward
 * normal +r, the main body inside), secondary node at (Rc, 0.5) pressed in by 0.01 (p = 100 for
 * eps_n = 1e4), area = length 2 pi Rc.
 * ------------------------------------------------------------------------------------------------- */
#define RC 1.25

static TslContactInput CylinderInput(void)
{
  const PetscReal xs[2] = {RC, 0.5}, x1[2] = {RC, 0}, x2[2] = {RC, 1};
  TslContactInput in = InputSetUp(xs, x1, x2);

  in.kin            = TSL_KIN_AXISYMMETRIC_TWIST;
  in.length         = 0.2;
  in.dt             = 0.5;
  in.u[0][0]        = -0.01;
  in.hist.xi_old    = 0.5;
  in.hist.xi_anchor = 0.5;
  return in;
}

static PetscErrorCode FrictionLaw(TslContactFrictionMethod method, TslContactLaw *law)
{
  PetscFunctionBeginUser;
  PetscCall(TslContactLawSetDefaults(law));
  law->eps_n    = 1e4;
  law->friction = method;
  law->mu       = 0.1;
  law->slip_tol = 1e-9;
  law->eta      = 1;
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode CheckLaws(TestLog *log)
{
  TslContactLaw     law;
  TslContactInput   in;
  TslContactOutput  out, ref;
  TslContactState h;
  PetscReal         R[NU * 3], A, d = 0.004, mup;

  PetscFunctionBeginUser;
  PetscCall(FrictionLaw(TSL_CONTACT_FRICTION_LAGRANGE, &law));
  Check(log, (PetscReal)TslContactNodeUnknowns(TSL_KIN_AXISYMMETRIC_TWIST), 4, 0, "unknowns per node with twist");
  Check(log, (PetscReal)TslContactNodeUnknowns(TSL_KIN_AXISYMMETRIC), 3, 0, "unknowns per node, axisymmetric");
  Check(log, (PetscReal)TslContactNodeUnknowns(TSL_KIN_PLANE_STRAIN), 3, 0, "unknowns per node, plane strain");

  /* pure twist of the secondary node by d / Rc: circumferential slip d */
  in         = CylinderInput();
  in.u[0][3] = d / RC;
  PetscCall(TslContactElement(&law, &in, R, NULL, &out));
  A   = in.length * 2 * PETSC_PI * RC;
  mup = law.mu * out.pressure;
  Check(log, out.nu, NU, 0, "twist: unknowns per node in the output");
  CheckRel(log, out.pressure, 100, 1e-12, 1, "twist: pressure");
  CheckRel(log, out.w, d, 1e-13, 1, "twist: relative circumferential displacement w = Rc phi_s");
  CheckRel(log, out.slip_circ, d, 1e-13, 1, "twist: circumferential slip increment");
  Check(log, out.slip, 0, 1e-15, "twist: no in-plane slip");
  CheckRel(log, out.shear_circ, mup, 1e-12, 1, "twist: tW = mu p");
  Check(log, out.shear, 0, 1e-12, "twist: tT = 0");
  CheckRel(log, out.dissipation_rate * in.dt, mup * d, 1e-12, 1, "twist: dissipation = mu p |dw|");
  CheckRel(log, R[3], A * mup * RC, 1e-12, 1, "twist: moment on phi_s = +A Rc tW (resists the twist)");
  CheckRel(log, R[NU + 3] + R[2 * NU + 3], -A * mup * RC, 1e-12, 1, "twist: moments on the main phi rows = -A Rc tW");
  CheckRel(log, R[NU + 3] / R[2 * NU + 3], 1, 1e-12, 1, "twist: main moments split by N_a (xi = 1/2)");
  Check(log, R[1], 0, 1e-12, "twist: no axial force");

  /* the same slip magnitude along z only, and split 0.6 / 0.8 between z and theta: the same dissipation */
  in         = CylinderInput();
  in.u[0][1] = d;
  PetscCall(TslContactElement(&law, &in, R, NULL, &ref));
  CheckRel(log, ref.dissipation_rate * in.dt, mup * d, 1e-12, 1, "axial: dissipation = mu p |ds|");
  in         = CylinderInput();
  in.u[0][1] = 0.6 * d;
  in.u[0][3] = 0.8 * d / RC;
  PetscCall(TslContactElement(&law, &in, R, NULL, &out));
  CheckRel(log, out.dissipation_rate, ref.dissipation_rate, 1e-12, 1, "combined 0.6/0.8: dissipation = the pure axial one");
  CheckRel(log, out.shear, 0.6 * mup, 1e-12, 1, "combined: tT = 0.6 mu p (along the slip)");
  CheckRel(log, out.shear_circ, 0.8 * mup, 1e-12, 1, "combined: tW = 0.8 mu p");
  Check(log, (PetscReal)out.status, TSL_CONTACT_SLIP, 0, "combined: slip");
  /* the anchor trails the node by slip_tol along the slip direction */
  CheckRel(log, (out.xi - out.xi_anchor) * 1, 0.6 * law.slip_tol * (1 + 1e-6), 1e-6, 1e-30, "combined: in-plane anchor trails by 0.6 slip_tol");
  CheckRel(log, out.w - out.w_anchor, 0.8 * law.slip_tol * (1 + 1e-6), 1e-6, 1e-30, "combined: circumferential anchor trails by 0.8 slip_tol");

  /* a rigid twist of both bodies by 0.3 rad: no slip (w = 0 on a cylindrical interface) */
  in = CylinderInput();
  for (PetscInt a = 0; a < 3; a++) in.u[a][3] = 0.3;
  PetscCall(TslContactElement(&law, &in, R, NULL, &out));
  Check(log, out.w, 0, 1e-15, "rigid twist: w = 0");
  Check(log, out.dissipation_rate, 0, 1e-12, "rigid twist: no dissipation");

  /* a new contact starts at the current relative twist: no circumferential slip in its first increment */
  in         = CylinderInput();
  in.u[0][3] = 0.01;
  in.u[1][3] = 0.002;
  in.u[2][3] = 0.004;
  PetscCall(TslContactStateStart(&in, 0.5, &h));
  CheckRel(log, h.w_old, RC * 0.01 - RC * 0.003, 1e-13, 1, "history start: w_old = R_s phi_s - R_m phi_m");
  Check(log, h.w_anchor, h.w_old, 0, "history start: anchor at w_old");
  in.hist = h;
  PetscCall(TslContactElement(&law, &in, R, NULL, &out));
  Check(log, out.slip_circ, 0, 1e-15, "history start: no circumferential slip");

  /* penalty, automatic stick stiffness (e_max = 0.002): stick inside the circle, radial return outside */
  PetscCall(FrictionLaw(TSL_CONTACT_FRICTION_PENALTY, &law));
  law.elastic_slip = 0.002;
  in               = CylinderInput();
  in.u[0][1]       = 0.0009;
  in.u[0][3]       = 0.0012 / RC; /* |e| = 0.0015 < e_max */
  PetscCall(TslContactElement(&law, &in, R, NULL, &out));
  mup = law.mu * out.pressure;
  Check(log, (PetscReal)out.status, TSL_CONTACT_STICK, 0, "penalty 2D: stick inside the circle");
  CheckRel(log, out.shear_circ, mup * 0.0012 / 0.002, 1e-12, 1, "penalty 2D stick: tW = eps_t e_W");
  Check(log, out.dissipation_rate, 0, 0, "penalty 2D stick: no dissipation");
  in.u[0][1] = 0.006;
  in.u[0][3] = 0.008 / RC; /* |e| = 0.01 */
  PetscCall(TslContactElement(&law, &in, R, NULL, &out));
  Check(log, (PetscReal)out.status, TSL_CONTACT_SLIP, 0, "penalty 2D: slip outside the circle");
  CheckRel(log, PetscHypotReal(out.shear, out.shear_circ), mup, 1e-12, 1, "penalty 2D slip: |t| = mu p");
  CheckRel(log, out.shear_circ / out.shear, 0.8 / 0.6, 1e-12, 1, "penalty 2D slip: t along the trial traction");
  CheckRel(log, out.dissipation_rate * in.dt, mup * (0.01 - 0.002), 1e-12, 1, "penalty 2D slip: dissipation = mu p (|e| - e_max)");
  CheckRel(log, PetscHypotReal(out.slip_dissipative, out.slip_dissipative_circ), 0.008, 1e-12, 1, "penalty 2D slip: plastic slip |e| - e_max");
  /* the next increment from the returned anchor starts on the stick limit */
  in.hist.xi_anchor = out.xi_anchor;
  in.hist.w_anchor  = out.w_anchor;
  PetscCall(TslContactElement(&law, &in, R, NULL, &out));
  CheckRel(log, PetscHypotReal(out.shear, out.shear_circ), mup, 1e-9, 1, "penalty 2D: anchor returned onto the stick limit");
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* A twist element with phi = 0 is the plain axisymmetric element plus phi rows and columns: the same
 * u/theta rows and columns, and phi rows without force (no circumferential slip). */
static PetscErrorCode CheckReduction(TestLog *log)
{
  TslContactLaw    law;
  TslContactInput  in;
  TslContactOutput out;
  PetscReal        Rt[NU * 3], Kt[NU * 3 * NU * 3], Ra[9], Ka[81], errR = 0, scaleR = 0, errK = 0, scaleK = 0, phirow = 0;

  PetscFunctionBeginUser;
  PetscCall(FrictionLaw(TSL_CONTACT_FRICTION_PENALTY, &law));
  law.elastic_slip = 0.002;
  law.eta          = 0.5;
  in               = CylinderInput();
  in.u[0][1]       = 0.004; /* slipping axially */
  in.u[0][2]       = 10;
  in.u[1][2]       = 30;
  PetscCall(TslContactElement(&law, &in, Rt, Kt, &out));
  Check(log, (PetscReal)out.status, TSL_CONTACT_SLIP, 0, "phi = 0: slipping axially");
  in.kin = TSL_KIN_AXISYMMETRIC;
  PetscCall(TslContactElement(&law, &in, Ra, Ka, NULL));
  for (PetscInt i = 0; i < 3 * 3; i++) {
    PetscInt it = NU * (i / 3) + i % 3;

    scaleR = PetscMax(scaleR, PetscAbsReal(Ra[i]));
    errR   = PetscMax(errR, PetscAbsReal(Rt[it] - Ra[i]));
    for (PetscInt j = 0; j < 3 * 3; j++) {
      PetscInt jt = NU * (j / 3) + j % 3;

      scaleK = PetscMax(scaleK, PetscAbsReal(Ka[i * 9 + j]));
      errK   = PetscMax(errK, PetscAbsReal(Kt[it * NU * 3 + jt] - Ka[i * 9 + j]));
    }
  }
  for (PetscInt a = 0; a < 3; a++) phirow = PetscMax(phirow, PetscAbsReal(Rt[NU * a + 3]));
  Check(log, errR / scaleR, 0, 1e-14, "phi = 0: residual rows u, theta = the axisymmetric ones");
  Check(log, errK / scaleK, 0, 1e-14, "phi = 0: tangent rows and columns u, theta = the axisymmetric ones");
  Check(log, phirow, 0, 0, "phi = 0: no moments");
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* ---------------------------------------------------------------------------------------------------
 * Tangent against central differences
 * ------------------------------------------------------------------------------------------------- */
typedef struct {
  TslContactInput in;
  PetscReal       x_prev[2 * NO], u_prev[NU * NO], x_next[2 * NO], u_next[NU * NO];
} Case;

static PetscReal *Unknown(Case *c, PetscInt i)
{
  PetscInt node = i / NU, comp = i % NU, nper = TslContactFaceGet(c->in.face)->geom->nnode;

  if (node <= nper) return &c->in.u[node][comp];
  node -= 1 + nper;
  if (c->in.x_prev) {
    if (node < nper - 1) return &c->u_prev[NU * node + comp];
    node -= nper - 1;
  }
  return &c->u_next[NU * node + comp];
}

/* kind of unknown: 0 displacement, 1 temperature, 2 twist */
static PetscInt Kind(PetscInt i)
{
  return i % NU < 2 ? 0 : i % NU - 1;
}

static PetscErrorCode CheckCase(TestLog *log, const char *name, const TslContactLaw *law, Case *c, TslContactStatus status)
{
  static PetscReal K[TSL_CONTACT_MAX_DOF * TSL_CONTACT_MAX_DOF], Kfd[TSL_CONTACT_MAX_DOF * TSL_CONTACT_MAX_DOF];
  PetscReal        Rp[TSL_CONTACT_MAX_DOF], Rm[TSL_CONTACT_MAX_DOF], R0[TSL_CONTACT_MAX_DOF];
  TslContactOutput out, outp, outm;
  PetscInt         nd;
  const char      *kname[3] = {"u", "theta", "phi"};
  PetscInt         kind[TSL_CONTACT_MAX_DOF];

  PetscFunctionBeginUser;
  if (c->in.x_prev) c->in.u_prev = c->u_prev;
  if (c->in.x_next) c->in.u_next = c->u_next;
  PetscCall(TslContactElement(law, &c->in, R0, K, &out));
  nd = NU * out.nnode;
  Check(log, (PetscReal)out.status, status, 0, "%s: status (p %g, tT %g, tW %g, slip %g, slip_circ %g)", name, (double)out.pressure, (double)out.shear,
        (double)out.shear_circ, (double)out.slip, (double)out.slip_circ);
  for (PetscInt j = 0; j < nd; j++) {
    PetscReal *v = Unknown(c, j), v0 = *v, h = (j % NU == 2) ? 1e-5 * PetscMax(1, PetscAbsReal(v0)) : 1e-7;

    *v = v0 + h;
    PetscCall(TslContactElement(law, &c->in, Rp, NULL, &outp));
    *v = v0 - h;
    PetscCall(TslContactElement(law, &c->in, Rm, NULL, &outm));
    *v = v0;
    PetscCheck(outp.status == out.status && outm.status == out.status, PETSC_COMM_SELF, PETSC_ERR_PLIB,
               "%s: perturbation of unknown %d changes the contact status", name, (int)j);
    for (PetscInt i = 0; i < nd; i++) Kfd[i * nd + j] = (Rp[i] - Rm[i]) / (2 * h);
  }
  for (PetscInt i = 0; i < nd; i++) kind[i] = Kind(i);
  CheckTangentBlocks(log, name, nd, K, Kfd, kind, 3, kname);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The inclined segment of test_tangent.c moved out to r >= 1: (3, 0.3) -> (1, 0), s near (1.8, 0.12) at the
 * given gap; line3: the midside node 0.08 off the chord, s put along the normal at xi = 0.6. Every node
 * twisted differently. History: in-plane slip increment about -0.006 (xi_old = xi + 0.003), circumferential
 * slip increment 0.004 (w_old = w - 0.004); anchors at the start of the increment unless a case moves them. */
static PetscErrorCode CaseSetUp(Case *c, PetscReal gap, TslContactFaceKind face)
{
  const PetscReal   x1[2] = {3, 0.3}, x2[2] = {1, 0}, xs[2] = {1.8, 0.12 + gap};
  TslContactState h;
  PetscReal         xi;

  PetscFunctionBeginUser;
  memset(c, 0, sizeof(*c));
  c->in           = InputSetUp(xs, x1, x2);
  c->in.kin       = TSL_KIN_AXISYMMETRIC_TWIST;
  c->in.face      = face;
  c->in.length    = 0.4;
  c->in.dt        = 0.2;
  c->in.u[0][0]   = 0.01;
  c->in.u[0][1]   = -0.004;
  c->in.u[1][0]   = 0.002;
  c->in.u[2][1]   = 0.003;
  c->in.u[0][2]   = 40;
  c->in.u[1][2]   = 120;
  c->in.u[2][2]   = 90;
  c->in.u[0][3]   = 0.012;
  c->in.u[1][3]   = -0.004;
  c->in.u[2][3]   = 0.007;
  if (face == TSL_CONTACT_FACE_LINE3) {
    const PetscReal n[2] = {-0.3 / PetscSqrtReal(4.09), 2 / PetscSqrtReal(4.09)};
    PetscReal       xm[2], nm[2];

    for (PetscInt d = 0; d < 2; d++) c->in.x[3][d] = 0.5 * (x1[d] + x2[d]) + 0.08 * n[d];
    c->in.u[3][0] = -0.001;
    c->in.u[3][1] = 0.002;
    c->in.u[3][2] = 100;
    c->in.u[3][3] = 0.003;
    PetscCall(TslContactSurfacePoint(&c->in, 0.6, xm, nm));
    for (PetscInt d = 0; d < 2; d++) c->in.x[0][d] = xm[d] + gap * nm[d] - c->in.u[0][d];
  }
  PetscCall(TslContactProject(&c->in, &xi, NULL, NULL));
  PetscCall(TslContactStateStart(&c->in, xi, &h));
  c->in.hist.xi_old = c->in.hist.xi_anchor = xi + 0.003;
  c->in.hist.w_old = c->in.hist.w_anchor = h.w_old - 0.004;
  PetscFunctionReturn(PETSC_SUCCESS);
}

static const char *Name(char buf[128], const char *family, const char *name)
{
  snprintf(buf, 128, "twist %s: %s", family, name);
  return buf;
}

static PetscErrorCode CheckTangents(TestLog *log, TslContactFaceKind face)
{
  TslContactLaw   law;
  Case            c;
  const PetscReal kp[2] = {100, 400}, kv[2] = {20, 5};
  char            name[128];
  const char     *fam = TslContactFaceGet(face)->geom->name;

  PetscFunctionBeginUser;
  PetscCall(TslContactLawSetDefaults(&law));
  law.eps_n       = 2e4;
  law.mu          = 0.3;
  law.eps_t       = 5e3;
  law.eta         = 0.9;
  law.f           = 0.3;
  law.conductance = TSL_CONTACT_CONDUCTANCE_PRESSURE;
  law.k_n         = 2;
  law.k_arg       = kp;
  law.k_value     = kv;
  law.friction    = TSL_CONTACT_FRICTION_PENALTY;

  /* penalty, constant stick stiffness: stick (|e| ~ 0.0036, |t*| ~ 18 < mu p ~ 60) and slip (|e| ~ 0.055) */
  PetscCall(CaseSetUp(&c, -0.01, face));
  c.in.hist.xi_anchor = c.in.hist.xi_old - 0.0015;
  c.in.hist.w_anchor  = c.in.hist.w_old + 0.002;
  PetscCall(CheckCase(log, Name(name, fam, "penalty stick"), &law, &c, TSL_CONTACT_STICK));
  PetscCall(CaseSetUp(&c, -0.01, face));
  c.in.hist.xi_anchor = c.in.hist.xi_old + 0.02;
  c.in.hist.w_anchor  = c.in.hist.w_old - 0.026;
  PetscCall(CheckCase(log, Name(name, fam, "penalty slip + heating"), &law, &c, TSL_CONTACT_SLIP));

  /* automatic stick stiffness mu pN / elastic slip */
  law.eps_t        = 0;
  law.elastic_slip = 0.004;
  PetscCall(CaseSetUp(&c, -0.01, face));
  c.in.hist.xi_anchor = c.in.hist.xi_old - 0.0015;
  c.in.hist.w_anchor  = c.in.hist.w_old + 0.002;
  PetscCall(CheckCase(log, Name(name, fam, "automatic penalty stick"), &law, &c, TSL_CONTACT_STICK));
  PetscCall(CaseSetUp(&c, -0.01, face));
  c.in.hist.xi_anchor = c.in.hist.xi_old + 0.02;
  c.in.hist.w_anchor  = c.in.hist.w_old - 0.026;
  PetscCall(CheckCase(log, Name(name, fam, "automatic penalty slip + heating"), &law, &c, TSL_CONTACT_SLIP));
  law.eps_t        = 5e3;
  law.elastic_slip = 0;

  /* LAGRANGE: slip from the start of the increment (e = ds), and on the regularised ramp (|e| < slip_tol) */
  law.friction = TSL_CONTACT_FRICTION_LAGRANGE;
  law.slip_tol = 1e-10;
  PetscCall(CaseSetUp(&c, -0.01, face));
  PetscCall(CheckCase(log, Name(name, fam, "Lagrange slip + heating"), &law, &c, TSL_CONTACT_SLIP));
  law.slip_tol = 0.02;
  PetscCall(CaseSetUp(&c, -0.01, face));
  c.in.hist.xi_anchor = c.in.hist.xi_old - 0.0025;
  c.in.hist.w_anchor  = c.in.hist.w_old + 0.001;
  PetscCall(CheckCase(log, Name(name, fam, "Lagrange ramp (stick) + heating"), &law, &c, TSL_CONTACT_STICK));
  law.slip_tol = 1e-10;

  /* augmented Lagrange normal with LAGRANGE friction, reversed circumferential slip */
  law.normal = TSL_CONTACT_NORMAL_AUGMENTED;
  PetscCall(CaseSetUp(&c, 0.001, face));
  c.in.hist.lambda = 150;
  c.in.hist.w_old  = c.in.hist.w_anchor = c.in.hist.w_old + 0.009;
  PetscCall(CheckCase(log, Name(name, fam, "augmented Lagrange, reversed twist slip"), &law, &c, TSL_CONTACT_SLIP));
  law.normal = TSL_CONTACT_NORMAL_PENALTY;

  /* smoothed corner near m1 with both neighbours (their phi columns are present, and empty), penalty slip */
  law.friction = TSL_CONTACT_FRICTION_PENALTY;
  PetscCall(CaseSetUp(&c, -0.01, face));
  c.in.smoothing = 0.2;
  c.x_prev[0]    = 4.0;
  c.x_prev[1]    = 0.9;
  c.x_next[0]    = 0.5;
  c.x_next[1]    = -0.2;
  c.u_prev[0]    = 0.001;
  c.u_prev[3]    = 0.02;
  c.u_next[1]    = -0.002;
  c.u_next[3]    = -0.01;
  if (face == TSL_CONTACT_FACE_LINE3) {
    const PetscReal np[2] = {-0.6 / PetscSqrtReal(1.36), 1 / PetscSqrtReal(1.36)}, nn[2] = {-0.2 / PetscSqrtReal(1.04), 1 / PetscSqrtReal(1.04)};
    for (PetscInt d = 0; d < 2; d++) {
      c.x_prev[2 + d] = 0.5 * (c.x_prev[d] + c.in.x[1][d]) + 0.03 * np[d];
      c.x_next[2 + d] = 0.5 * (c.x_next[d] + c.in.x[2][d]) + 0.03 * nn[d];
    }
  }
  c.in.x_prev = c.x_prev;
  c.in.x_next = c.x_next;
  c.in.u_prev = c.u_prev;
  c.in.u_next = c.u_next;
  {
    PetscReal         xi = 0.08, n[2], xm[2], xr;
    TslContactState h;

    PetscCall(TslContactSurfacePoint(&c.in, xi, xm, n));
    for (PetscInt d = 0; d < 2; d++) c.in.x[0][d] = xm[d] - 0.01 * n[d] - c.in.u[0][d];
    PetscCall(TslContactProject(&c.in, &xr, NULL, NULL));
    PetscCall(TslContactStateStart(&c.in, xr, &h));
    c.in.hist.xi_old = c.in.hist.xi_anchor = xr + 0.01;
    c.in.hist.w_old = c.in.hist.w_anchor = h.w_old + 0.01;
    Check(log, (PetscReal)(xr < 0.2), 1, 0, "twist %s: smoothed case: xi = %g in the rounded zone", fam, (double)xr);
  }
  PetscCall(CheckCase(log, Name(name, fam, "smoothed corner at m1, penalty slip"), &law, &c, TSL_CONTACT_SLIP));
  PetscFunctionReturn(PETSC_SUCCESS);
}

int main(int argc, char **argv)
{
  TestLog log = {0, 0};

  PetscCall(PetscInitialize(&argc, &argv, NULL, NULL));
  PetscCall(CheckLaws(&log));
  PetscCall(CheckReduction(&log));
  PetscCall(CheckTangents(&log, TSL_CONTACT_FACE_LINE2));
  PetscCall(CheckTangents(&log, TSL_CONTACT_FACE_LINE3));
  PetscCall(PetscFinalize());
  return Summary(&log);
}
