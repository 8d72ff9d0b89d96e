/* Contact interaction laws and the node-to-segment contact element (residual, consistent tangent,
 * diagnostics). Formulas, units and signs: include/thermoslide/contact.h and docs/contact.md. */
#include "contact_impl.h"

PetscErrorCode TslTableEvaluate(PetscInt n, const PetscReal x[], const PetscReal y[], PetscReal arg, PetscReal *value, PetscReal *dvalue)
{
  PetscReal v = 0, dv = 0;

  PetscFunctionBeginUser;
  PetscCheck(n >= 1, PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE, "Table needs at least one point");
  for (PetscInt i = 1; i < n; i++)
    PetscCheck(x[i] > x[i - 1], PETSC_COMM_SELF, PETSC_ERR_ARG_WRONG, "Table arguments must increase strictly (%g after %g)", (double)x[i],
               (double)x[i - 1]);
  if (n == 1 || arg < x[0]) {
    v = y[0];
  } else if (arg >= x[n - 1]) {
    v = y[n - 1];
  } else {
    PetscInt i = 0;
    while (arg >= x[i + 1]) i++; /* x[i] <= arg < x[i+1]: a breakpoint takes the slope on its right */
    dv = (y[i + 1] - y[i]) / (x[i + 1] - x[i]);
    v  = y[i] + dv * (arg - x[i]);
  }
  if (value) *value = v;
  if (dvalue) *dvalue = dv;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TslContactLawSetDefaults(TslContactLaw *law)
{
  PetscFunctionBeginUser;
  PetscCall(PetscMemzero(law, sizeof(*law)));
  law->normal        = TSL_CONTACT_NORMAL_PENALTY;
  law->friction      = TSL_CONTACT_FRICTION_NONE;
  law->slip_tol      = 1e-12;
  law->conductance   = TSL_CONTACT_CONDUCTANCE_NONE;
  law->eps_main      = 1;
  law->eps_secondary = 1;
  law->eta           = 1;
  law->f             = 0.5;
  PetscFunctionReturn(PETSC_SUCCESS);
}

void TslContactKinematicLaw(TslContactLaw *law, PetscReal eps, PetscReal eps_t, PetscReal p_offset)
{
  law->normal   = TSL_CONTACT_NORMAL_PENALTY;
  law->eps_n    = eps;
  law->p_offset = p_offset;
  if (law->friction == TSL_CONTACT_FRICTION_PENALTY) law->eps_t = eps_t, law->elastic_slip = 0;
}

/* Abaqus Theory Guide, "Thermal contact properties" (radiation across a gap between surfaces A and B):
 *   q = C [(theta_A - theta_Z)^4 - (theta_B - theta_Z)^4],  C = F sigma / (1/eps_A + 1/eps_B - 1),
 * exact for two close infinite grey plates with F = 1; otherwise F scales the exchange. */
PetscErrorCode TslGapRadiationCoefficient(PetscReal sigma, PetscReal F, PetscReal eps_A, PetscReal eps_B, PetscReal *C, PetscReal *dC_dF)
{
  PetscReal den;

  PetscFunctionBeginUser;
  PetscCheck(eps_A > 0 && eps_A <= 1 && eps_B > 0 && eps_B <= 1, PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE, "Emissivities must lie in (0, 1]: %g, %g",
             (double)eps_A, (double)eps_B);
  den = 1 / eps_A + 1 / eps_B - 1;
  if (C) *C = F * sigma / den;
  if (dC_dF) *dC_dF = sigma / den;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TslContactAugmentedUpdate(PetscReal eps_n, PetscReal g, PetscReal *lambda, PetscReal *change)
{
  PetscReal l = PetscMax(0, *lambda - eps_n * g);

  PetscFunctionBeginUser;
  if (change) *change = PetscAbsReal(l - *lambda);
  *lambda = l;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TslContactStateUpdate(const TslContactOutput *out, TslContactState *h)
{
  PetscFunctionBeginUser;
  h->xi_old    = out->xi;
  h->xi_anchor = out->xi_anchor;
  h->w_old     = out->w;
  h->w_anchor  = out->w_anchor;
  /* 3D: the second surface parameter (zero in 2D) */
  h->eta_old    = out->eta;
  h->eta_anchor = out->eta_anchor;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Contact pressure: penalty pN = eps_n <-g>, augmented pN = <lambda + eps_n (-g)>. Exactly touching
 * (argument 0) takes the closed branch: zero pressure but the penalty stiffness, so bodies that start
 * in contact are held from the first Newton iteration. */
/* *closed: touching or pressed, with "touching" up to the round-off of the gap (1e-12 of the segment
 * length L), so that node-on-node meshes whose coordinates differ in the last digit still start closed. */
TslDual TslContactNormalPressure(const TslContactLaw *law, const TslContactState *h, TslDual g, PetscReal L, PetscBool *closed)
{
  TslDual a = DScale(-law->eps_n, g);

  if (law->normal == TSL_CONTACT_NORMAL_AUGMENTED) a = DAddC(a, h->lambda);
  if (law->p_offset != 0) a = DAddC(a, law->p_offset);
  *closed = (PetscBool)(a.v >= -1e-12 * law->eps_n * L);
  return a.v >= 0 ? a : DConst(0);
}

/* What contact needs of a kinematics it asks the element module (TslKinematicsRevolves, ...Twists): does
 * the area revolve (2 pi r instead of the thickness), and does the slip have a circumferential component
 * (the twist phi among the unknowns, u_theta = R phi)? */
PetscInt TslContactNodeUnknowns(TslKinematics kin)
{
  return (PetscInt)kin >= 0 && kin < TSL_NKIN && TslKinematicsTwists(kin) ? 4 : 3;
}

/* |v| of an nc-component slip or traction (value only: no derivative of the norm at v = 0). */
static PetscReal MagnitudeValue(PetscInt nc, const TslDual v[2])
{
  return nc == 1 ? PetscAbsReal(v[0].v) : PetscSqrtReal(v[0].v * v[0].v + v[1].v * v[1].v);
}

/* Unit direction v/|v| of a nonzero vector. One component: the sign, a constant, exactly what the scalar
 * law used, so plane and plain axisymmetric models keep their answers to the last digit. */
static void Direction(PetscInt nc, const TslDual v[2], TslDual dir[2])
{
  if (nc == 1) {
    dir[0] = DConst(v[0].v >= 0 ? 1 : -1);
    dir[1] = DConst(0);
  } else {
    TslDual len = DSqrt(DDot(v, v));

    for (PetscInt c = 0; c < 2; c++) dir[c] = DDiv(v[c], len);
  }
}

/* Coulomb friction on the slip vector (one component, or two with twist and in 3D: the isotropic law,
 * |t| <= mu pN, slip along the trial traction). PENALTY: elastic predictor t* = eps_t e, radial return onto
 * the circle |t| = mu pN; the plastic slip (t* - t)/eps_t dissipates. LAGRANGE: t = mu pN e/|e|, e the slip
 * from an anchor that trails the node by slip_tol along the slip direction, e/|e| replaced by e/slip_tol for
 * |e| < slip_tol; the dissipation is t . ds over the increment's whole slip ds, so t . ds = mu pN |ds|
 * exactly while the node slips in a fixed direction (all relative motion becomes heat, as the spec's
 * frictional-heating tests require). The law returns the elastic slip left after the return; each kernel
 * turns it into an anchor on its own face (2D: a parameter xi, 3D: a point (xi, eta)). */
PetscErrorCode TslContactFrictionLaw(const TslContactLaw *law, PetscReal dt, TslDual pN, const TslContactSlip *sl, TslContactFriction *fs)
{
  const PetscInt nc = sl->nc;

  PetscFunctionBeginUser;
  for (PetscInt c = 0; c < 2; c++) {
    fs->t[c]         = DConst(0);
    fs->slip_diss[c] = 0;
    fs->elastic[c]   = 0; /* open or frictionless: a new contact starts stress-free */
  }
  fs->D           = DConst(0);
  fs->keep_anchor = PETSC_FALSE;
  fs->status      = pN.v > 0 ? TSL_CONTACT_SLIP : TSL_CONTACT_OPEN;
  if (pN.v <= 0 || law->friction == TSL_CONTACT_FRICTION_NONE || law->mu == 0) PetscFunctionReturn(PETSC_SUCCESS);
  if (law->friction == TSL_CONTACT_FRICTION_PENALTY) {
    /* elastic slip e from the anchor; stick stiffness eps_t, or mu pN / e_max (automatic: the stick limit is
     * an elastic slip of e_max whatever the pressure, the dialect's SLIP TOLERANCE) */
    TslDual eps_t = law->elastic_slip > 0 ? DScale(law->mu / law->elastic_slip, pN) : DConst(law->eps_t);
    TslDual limit = DScale(law->mu, pN), trial[2];

    PetscCheck(law->eps_t > 0 || law->elastic_slip > 0, PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE,
               "Penalty friction needs eps_t > 0 or elastic_slip > 0");
    for (PetscInt c = 0; c < nc; c++) trial[c] = DMul(eps_t, sl->e[c]);
    if (MagnitudeValue(nc, trial) <= limit.v) {
      for (PetscInt c = 0; c < nc; c++) fs->t[c] = trial[c];
      fs->keep_anchor = PETSC_TRUE;
      fs->status      = TSL_CONTACT_STICK;
    } else {
      TslDual dir[2], slip[2];

      /* radial return: t = mu pN t_trial / |t_trial|; plastic slip = e minus the elastic part t / eps_t (= e_max along
       * the direction in the automatic form) */
      Direction(nc, trial, dir);
      for (PetscInt c = 0; c < nc; c++) {
        fs->t[c]         = DMul(limit, dir[c]);
        slip[c]          = law->elastic_slip > 0 ? DSub(sl->e[c], DScale(law->elastic_slip, dir[c])) : DScale(1 / law->eps_t, DSub(trial[c], fs->t[c]));
        fs->slip_diss[c] = slip[c].v;
        fs->elastic[c]   = sl->e[c].v - slip[c].v;
        fs->D            = c == 0 ? DMul(fs->t[c], slip[c]) : DAdd(fs->D, DMul(fs->t[c], slip[c]));
      }
    }
  } else {
    /* the regularised direction is measured from the anchor, which trails the node by slip_tol while it
     * slips: a node that slipped in the last increment starts the next one on the slip branch (|t| = mu pN,
     * no tangential stiffness along the slip) instead of at ds = 0 in the middle of the steep ramp, whose
     * tangent mu pN / slip_tol made the first Newton step predict a shear hundreds of times mu pN (tilting
     * the block, opening the contact: issue 8, item 7). A node starting to slip (anchor = start of the
     * increment) sees e = ds, as before. */
    PetscReal tol = law->slip_tol;
    TslDual   dir[2], mup = DScale(law->mu, pN);

    PetscCheck(tol > 0, PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE, "Lagrange friction needs slip_tol > 0");
    if (MagnitudeValue(nc, sl->e) >= tol) {
      Direction(nc, sl->e, dir);
      /* just beyond the ramp, so that round-off in the next increment's e does not fall back onto it */
      for (PetscInt c = 0; c < nc; c++) fs->elastic[c] = dir[c].v * tol * (1 + 1e-6);
    } else {
      for (PetscInt c = 0; c < nc; c++) dir[c] = DScale(1 / tol, sl->e[c]);
      fs->keep_anchor = PETSC_TRUE;
      fs->status      = TSL_CONTACT_STICK;
    }
    for (PetscInt c = 0; c < nc; c++) {
      fs->t[c]         = DMul(mup, dir[c]);
      fs->slip_diss[c] = sl->ds[c].v;
      fs->D            = c == 0 ? DMul(fs->t[c], sl->ds[c]) : DAdd(fs->D, DMul(fs->t[c], sl->ds[c]));
    }
  }
  /* dissipated energy per area over the increment -> rate */
  if (law->eta != 0) PetscCheck(dt > 0, PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE, "Frictional heating needs dt > 0");
  fs->D = dt > 0 ? DScale(1 / dt, fs->D) : DConst(0);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Gap conductance k: by pressure (only while in contact) or by clearance d = <g> (zero beyond the last
 * tabulated clearance, as the dialect specifies). "In contact" is the closed branch of the normal law,
 * exact touching included: there the pressure is zero and k is the table's value at p = 0 (its first
 * value, the table extends flat below its first point). Requiring p > 0 left bodies that start exactly
 * touching without any conductance at the first Newton iteration, and in a steady step a body held
 * only through the interface then had no determined temperature: a singular thermal block, and every
 * cutback diverged (issue 8, item 2). */
static PetscErrorCode Conductance(const TslContactLaw *law, TslDual pN, PetscBool closed, TslDual g, TslDual *k)
{
  PetscReal v, dv;

  PetscFunctionBeginUser;
  *k = DConst(0);
  if (law->conductance == TSL_CONTACT_CONDUCTANCE_PRESSURE && closed) {
    PetscCall(TslTableEvaluate(law->k_n, law->k_arg, law->k_value, pN.v, &v, &dv));
    *k = DChain(pN, v, dv);
  } else if (law->conductance == TSL_CONTACT_CONDUCTANCE_CLEARANCE) {
    TslDual d = g.v > 0 ? g : DConst(0);

    PetscCheck(law->k_n >= 1, PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE, "Conductance table is empty");
    if (d.v <= law->k_arg[law->k_n - 1]) {
      PetscCall(TslTableEvaluate(law->k_n, law->k_arg, law->k_value, d.v, &v, &dv));
      *k = DChain(d, v, dv);
    }
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Gap radiation constant C(F(d)), d = <g>; like clearance conductance, the view factor is zero beyond
 * the last tabulated clearance (docs/keywords.md) and keeps its first value below the first. */
static PetscErrorCode RadiationConstant(const TslContactLaw *law, TslDual g, TslDual *C)
{
  TslDual   d = g.v > 0 ? g : DConst(0);
  PetscReal F, dF, c, dc;

  PetscFunctionBeginUser;
  *C = DConst(0);
  if (law->F_n < 1 || d.v > law->F_clearance[law->F_n - 1]) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(TslTableEvaluate(law->F_n, law->F_clearance, law->F_value, d.v, &F, &dF));
  PetscCall(TslGapRadiationCoefficient(law->sigma, F, law->eps_main, law->eps_secondary, &c, &dc));
  *C = DChain(d, c, dc * dF);
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TslContactHeatFlux(const TslContactLaw *law, TslDual pN, PetscBool closed, TslDual g, TslDual theta_s, TslDual theta_m, TslDual *k,
                                  TslDual *C, TslDual *q)
{
  PetscFunctionBeginUser;
  PetscCall(Conductance(law, pN, closed, g, k));
  PetscCall(RadiationConstant(law, g, C));
  *q = DMul(*k, DSub(theta_m, theta_s));
  if (C->v != 0) *q = DAdd(*q, DMul(*C, DSub(DPow4(DAddC(theta_m, -law->theta_zero)), DPow4(DAddC(theta_s, -law->theta_zero)))));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Residual = internal - external: the contact force and the heat inflow are external to each node. The
 * sum of the thermal rows is -A heat: conduction and radiation move heat across, friction adds it. */
void TslContactResidualRows(PetscReal area, PetscReal f, PetscInt dim, PetscInt nu, PetscInt nnode, PetscInt nper, const TslDual N[],
                            const TslDual traction[], TslDual q, TslDual heat, TslDual Rd[])
{
  const TslDual qs = DAdd(q, DScale(f, heat)), qm = DSub(q, DScale(1 - f, heat));

  /* each row formed in place, the operations of DScale(area, DMul(N_a, x)) (the temporaries were most of its cost) */
  for (PetscInt a = 0; a < nnode; a++) /* rows no law writes: twist, and the smoothing neighbours' nodes */
    for (PetscInt k = a > nper ? 0 : dim + 1; k < nu; k++) Rd[nu * a + k] = DConst(0);
  for (PetscInt c = 0; c <= dim; c++) {
    const TslDual *x = c < dim ? &traction[c] : &qs;
    TslDual       *r = &Rd[c];
    r->v             = -area * x->v;
    for (PetscInt i = 0; i < TSL_DUAL_N; i++) r->d[i] = -area * x->d[i];
    if (c == dim) x = &qm;
    for (PetscInt a = 0; a < nper; a++) {
      const TslDual *n = &N[a];
      r                = &Rd[nu * (a + 1) + c];
      r->v             = area * (n->v * x->v);
      for (PetscInt i = 0; i < TSL_DUAL_N; i++) r->d[i] = area * (n->d[i] * x->v + n->v * x->d[i]);
    }
  }
}

void TslContactDualExtract(PetscInt ndof, const TslDual Rd[], PetscReal R[], PetscReal K[])
{
  if (R)
    for (PetscInt i = 0; i < ndof; i++) R[i] = Rd[i].v;
#if !defined(TSL_DUAL_VALUES) /* the values' copy has no derivatives to give */
  if (K)
    for (PetscInt i = 0; i < ndof; i++)
      for (PetscInt j = 0; j < ndof; j++) K[i * ndof + j] = Rd[i].d[TSL_DUAL_DOF + j];
#else
  (void)K;
#endif
}

/* Contact area of the secondary node: its tributary length times the thickness (plane), or times 2 pi r
 * at its reference radius for both axisymmetric kinematics. */
static PetscReal NodeArea(const TslContactInput *in)
{
  return TslKinematicsRevolves(in->kin) ? in->length * 2 * PETSC_PI * in->x[0][0] : in->length * in->thickness;
}

/* Twist: the reference radius R_m(xi) = N_a R_a of the main point and the relative circumferential
 * displacement w = R_s phi_s - R_m(xi) phi_m(xi), phi_m = N_a phi_a, of the secondary node against it
 * (u_theta = R phi, the elements' small-strain twist: reference radii, so that the moments R f_theta the
 * friction puts on the phi rows are work-conjugate to phi exactly as the elements' own). N[] are the
 * segment's shape functions at xi; phi of node k is seeded in slot nu k + 3 when seed is set. */
static TslDual RelativeTwist(const TslContactInput *in, PetscInt nper, const TslDual N[], PetscBool seed, TslDual *Rm)
{
  const PetscInt nu = 4;
  TslDual        phi_m = DConst(0);

  *Rm = DConst(0);
  for (PetscInt a = 0; a < nper; a++) {
    *Rm   = DAdd(*Rm, DScale(in->x[1 + a][0], N[a]));
    phi_m = DAdd(phi_m, DMul(N[a], DVar(in->u[1 + a][3], seed ? TSL_DUAL_DOF + nu * (1 + a) + 3 : -1)));
  }
  return DSub(DScale(in->x[0][0], DVar(in->u[0][3], seed ? TSL_DUAL_DOF + 3 : -1)), DMul(*Rm, phi_m));
}

PetscErrorCode TslContactElement(const TslContactLaw *law, const TslContactInput *in, PetscReal R[], PetscReal K[], TslContactOutput *out)
{
  TslContactGeom     geo;
  PetscInt           nnode, ndof, nper, nu;
  PetscReal          xi_raw, area, Nv[TSL_CONTACT_MAX_FACE_NODES], dNv[TSL_CONTACT_MAX_FACE_NODES], d2Nv[TSL_CONTACT_MAX_FACE_NODES];
  PetscReal          anchor = in->hist.xi_anchor, w_anchor = in->hist.w_anchor;
  TslDual            xi, n[2], tau[2], r[2], xm[2], t[2], g, L, pN, traction[2], k, C, q, theta_s, theta_m, heat, w, Rm = DConst(0);
  TslDual            N[TSL_CONTACT_MAX_FACE_NODES], Rd[TSL_CONTACT_MAX_DOF];
  TslContactSlip     sl;
  TslContactFriction fs;
  PetscBool          closed;

  PetscFunctionBeginUser;
  PetscCheck(in->length > 0, PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE, "Tributary length must be positive");
  PetscCheck((PetscInt)in->kin >= 0 && in->kin < TSL_NKIN, PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE, "Unknown kinematics %d", (int)in->kin);
#if !defined(TSL_DUAL_VALUES)
  if (!K) { /* values alone: the copy without the unknowns' derivatives (contact/values/) */
    PetscCall(TslContactElement_Values(law, in, R, NULL, out));
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  {
    const TslContactFace *f = TslContactFaceGet(in->face);
    if (f) { /* the element's unknowns: the secondary node, the segment, the neighbours' other nodes */
      const PetscInt np = f->geom->nnode, nn = 1 + np + (in->x_prev ? np - 1 : 0) + (in->x_next ? np - 1 : 0);
#if defined(TSL_DUAL_SHORT)
      PetscCheck(nn * TslContactNodeUnknowns(in->kin) <= TSL_DUAL_SHORT_DOF, PETSC_COMM_SELF, PETSC_ERR_PLIB,
                 "contact element with %" PetscInt_FMT " unknowns in the short kernels", nn * TslContactNodeUnknowns(in->kin));
#else
      if (nn * TslContactNodeUnknowns(in->kin) <= TSL_DUAL_SHORT_DOF) { /* its tangent fits fewer slots (contact/short/) */
        PetscCall(TslContactElement_Short(law, in, R, K, out));
        PetscFunctionReturn(PETSC_SUCCESS);
      }
#endif
    }
  }
#endif
  PetscCall(TslContactGeomSetUp(in, PETSC_TRUE, &geo, &nnode));
  nu   = geo.nu;
  ndof = nu * nnode;
  nper = geo.face->geom->nnode;
  area = NodeArea(in);

  /* kinematics: projection, normal, gap, slip increment along the segment's metric |t| at xi */
  PetscCall(TslContactProjectDual(&geo, &xi, &xi_raw));
  TslContactSurfaceDual(&geo, xi, xm, n, tau);
  for (PetscInt d = 0; d < 2; d++) r[d] = DSub(geo.xs[d], xm[d]);
  g = DDot(r, n);
  TslContactFacePointDual(geo.face, geo.seg, xi, xm, t);
  L = DSqrt(DDot(t, t));
  TslContactFaceShape(geo.face, xi.v, Nv, dNv, d2Nv);
  for (PetscInt a = 0; a < nper; a++) N[a] = DChain(xi, Nv[a], dNv[a]);
  sl.nc    = TslKinematicsTwists(in->kin) ? 2 : 1;
  sl.ds[0] = DMul(L, DAddC(xi, -in->hist.xi_old));
  sl.e[0]  = DMul(L, DAddC(xi, -in->hist.xi_anchor));
  w        = DConst(0);
  sl.ds[1] = sl.e[1] = DConst(0);
  if (sl.nc == 2) {
    /* circumferential slip: the relative circumferential displacement w from the start of the increment
     * and from the anchor */
    w        = RelativeTwist(in, nper, N, PETSC_TRUE, &Rm);
    sl.ds[1] = DAddC(w, -in->hist.w_old);
    sl.e[1]  = DAddC(w, -in->hist.w_anchor);
  }

  /* mechanical laws; a moved anchor lies the elastic slip behind the node along the segment (in xi: the
   * slip over the metric L) and around the circumference */
  pN = TslContactNormalPressure(law, &in->hist, g, L.v, &closed);
  PetscCall(TslContactFrictionLaw(law, in->dt, pN, &sl, &fs));
  if (!fs.keep_anchor) {
    anchor   = xi.v - fs.elastic[0] / L.v;
    w_anchor = w.v - fs.elastic[1];
  }
  for (PetscInt d = 0; d < 2; d++) traction[d] = DSub(DMul(pN, n[d]), DMul(fs.t[0], tau[d]));

  /* thermal laws */
  theta_s = DVar(in->u[0][2], TSL_DUAL_DOF + 2);
  theta_m = DConst(0);
  for (PetscInt a = 0; a < nper; a++) theta_m = DAdd(theta_m, DMul(N[a], DVar(in->u[1 + a][2], TSL_DUAL_DOF + nu * (1 + a) + 2)));
  PetscCall(TslContactHeatFlux(law, pN, closed, g, theta_s, theta_m, &k, &C, &q));
  heat = DScale(law->eta, fs.D);

  /* residual. With twist the circumferential friction force -A tW on s (+A tW at the main point) does the
   * virtual work -A tW (R_s dphi_s - R_m N_a dphi_a): moments on the phi rows. */
  TslContactResidualRows(area, law->f, 2, nu, nnode, nper, N, traction, q, heat, Rd);
  if (sl.nc == 2) {
    Rd[3] = DScale(area * in->x[0][0], fs.t[1]);
    for (PetscInt a = 0; a < nper; a++) Rd[nu * (a + 1) + 3] = DScale(-area, DMul(DMul(N[a], Rm), fs.t[1]));
  }
  TslContactDualExtract(ndof, Rd, R, K);
  if (out) {
    out->nnode                 = nnode;
    out->nu                    = nu;
    out->xi                    = xi.v;
    out->xi_raw                = xi_raw;
    out->side                  = TslContactProjectionSide(xi_raw, 0);
    out->normal[0]             = n[0].v;
    out->normal[1]             = n[1].v;
    out->gap                   = g.v;
    out->area                  = area;
    out->pressure              = pN.v;
    out->slip                  = sl.ds[0].v;
    out->shear                 = fs.t[0].v;
    out->slip_dissipative      = fs.slip_diss[0];
    out->w                     = w.v;
    out->slip_circ             = sl.ds[1].v;
    out->shear_circ            = fs.t[1].v;
    out->slip_dissipative_circ = fs.slip_diss[1];
    out->conductance           = k.v;
    out->radiation_C           = C.v;
    out->heat_flux             = q.v;
    out->dissipation_rate      = fs.D.v;
    out->heat_generation       = heat.v;
    out->status                = fs.status;
    out->xi_anchor             = anchor;
    out->w_anchor              = w_anchor;
    out->eta = out->eta_raw = out->eta_anchor = out->normal_z = 0;
    out->outside                                              = 0;
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TslContactStateStart(const TslContactInput *in, PetscReal xi, TslContactState *h)
{
  const TslContactFace *face = TslContactFaceGet(in->face);
  PetscReal             Nv[TSL_CONTACT_MAX_FACE_NODES], dNv[TSL_CONTACT_MAX_FACE_NODES], d2Nv[TSL_CONTACT_MAX_FACE_NODES];
  TslDual               N[TSL_CONTACT_MAX_FACE_NODES], Rm;

  PetscFunctionBeginUser;
  PetscCheck(face, PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE, "Unknown contact face family %d", (int)in->face);
  PetscCheck((PetscInt)in->kin >= 0 && in->kin < TSL_NKIN, PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE, "Unknown kinematics %d", (int)in->kin);
  h->xi_old = h->xi_anchor = xi;
  h->lambda                = 0;
  h->w_old = h->w_anchor = 0;
  if (TslKinematicsTwists(in->kin)) {
    TslContactFaceShape(face, xi, Nv, dNv, d2Nv);
    for (PetscInt a = 0; a < face->geom->nnode; a++) N[a] = DConst(Nv[a]);
    h->w_old = h->w_anchor = RelativeTwist(in, face->geom->nnode, N, PETSC_FALSE, &Rm).v;
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}
