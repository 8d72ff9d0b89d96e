/* The formulation table: what distinguishes full, reduced (R), hybrid (H) and modified (M) elements.
 *
 *   full       the family's full rule for every term; lumping by row sums (linear families) or HRZ
 *              (quadratic families, whose row sums are negative at the corners); the implicit capacity of
 *              the quadratic families is consistent (consistent_capacity, TslElementHeatContent): their
 *              lumped weights do not match the conduction's and the face flux's across an element
 *   reduced    one mechanical point (the family's reduced rule) with stiffness-based hourglass control;
 *              conduction keeps the full rule, so there is no thermal hourglass mode
 *   hybrid     an independent pressure, constant (linear families) or linear (quadratic families),
 *              condensed in the element (kernels.c)
 *   continuum shell  one point in the shell plane, Simpson points along the stack direction, hourglass
 *              control of the modes they miss (ShellHourglass); conduction keeps the full rule
 *   modified   second-order triangles and tetrahedra that behave well in contact: mass (and the explicit
 *              capacity) and 3D pressure loads are lumped over the linear sub-elements (tri6 -> 4 tri3, tet10 -> 8 tet4),
 *              so every nodal weight is positive (the plain tet10 face gives zero corner forces under a
 *              uniform pressure and negative corner capacities)
 *
 * Surface flux and film use the face family's own shape functions and its as_face rule in every
 * formulation (the modified rows too): lumped on the linear sub-faces of a tet10 face they cost C3D10MT
 * its order at a film or flux boundary (L2 rate 1.4 instead of 3, tests/element/face_convergence.c),
 * since the composite linear functions are not the quadratic face's and the film matrix int h N_a N_b dA
 * is of degree 4; and no contact condition asks positive nodal weights of a heat load. The body flux is
 * not lumped either: the kernel integrates it with the family's full rule and shape functions in every
 * formulation (kernels.c, BodyFlux), so the lumping weights here are the capacity's and the mass's only.
 */
#include "element_impl.h"

/* Hourglass stiffness scale s: kappa = s mu V sum_a |b_a|^2 with the vectors gamma normalised by the
 * node count (see HourglassStiffness below). 0.05 keeps the hourglass energy of a bending mesh with four
 * layers at 0.35-0.5 % of the strain energy (tests/element/bending.c, element_bending), suppresses every
 * zero-energy mode, and costs 6 % of tip deflection there; on two layers the control carries 5-8 % of
 * the energy, the bending that one point cannot see. The dialect's *HOURGLASS STIFFNESS is not read yet. */
#define TSL_HOURGLASS_SCALE 0.05

PetscReal TslElementHourglassKappa(PetscReal mu, PetscReal dV, PetscReal bb)
{
  return TSL_HOURGLASS_SCALE * mu * dV * bb;
}

static const TslQuadrature *FullRule(const TslGeometry *g, const TslElementSection *sec)
{
  (void)sec;
  return &g->full;
}

static const TslQuadrature *ReducedRule(const TslGeometry *g, const TslElementSection *sec)
{
  (void)sec;
  return &g->reduced;
}

/* Continuum shell: the centre of the reference surface (hex8: (0, 0); wedge6: the triangle's centroid) times
 * n Simpson points along the stack direction (the section's reference direction, the third by default; a wedge
 * stacks along its third only) (the section's points, odd, 3 to TSL_SHELL_MAX_POINTS; 5 by default as in
 * Abaqus). Built once per family, count and direction. */
#define TSL_SHELL_MAX_POINTS 15
static const TslQuadrature *ShellRule(const TslGeometry *g, const TslElementSection *sec)
{
  static TslQuadrature rules[2][3][TSL_SHELL_MAX_POINTS + 1];
  static PetscBool     built[2][3][TSL_SHELL_MAX_POINTS + 1];
  const PetscInt       n = sec && sec->shell_points > 0 ? sec->shell_points : 5, f = g->nnode == 8 ? 0 : 1, s = TslElementShellStack(sec);
  TslQuadrature       *q;

  PetscCheckAbort(n >= 3 && n <= TSL_SHELL_MAX_POINTS && n % 2 == 1 && g->dim == 3 && (f == 0 || s == 2), PETSC_COMM_SELF, PETSC_ERR_PLIB,
                  "continuum shell rule with %d points along direction %d", (int)n, (int)s + 1);
  q = &rules[f][s][n];
  if (built[f][s][n]) return q;
  q->n      = n;
  q->degree = 1; /* in the shell plane; Simpson's rule is exact for cubics along the stack direction */
  for (PetscInt k = 0; k < n; k++) {
    const PetscReal h = 2.0 / (n - 1), w = k == 0 || k == n - 1 ? 1 : (k % 2 ? 4 : 2);
    for (PetscInt d = 0; d < 3; d++) q->xi[k][d] = f == 0 || d == 2 ? 0 : 1.0 / 3;
    q->xi[k][s] = -1 + k * h;
    q->w[k]     = (f == 0 ? 4 : 0.5) * h / 3 * w;
  }
  built[f][s][n] = PETSC_TRUE;
  return q;
}

/* Pressure space of a hybrid element: constant for linear families, 1 + xi (complete linear in the
 * reference coordinates) for quadratic ones. */
static PetscInt PressureBasis(const TslGeometry *g, const TslElementPoint *p, PetscReal P[])
{
  P[0] = 1;
  if (g->order < 2) return 1;
  for (PetscInt d = 0; d < g->dim; d++) P[1 + d] = p->xi[d];
  return 1 + g->dim;
}

/* Lumping weights V_a = int N_a dV (row sums): positive for linear families. */
static PetscBool RowSum(const TslElementInput *in, PetscReal vol[])
{
  const TslGeometry *g = in->type->geom;
  TslElementPoint    p;

  for (PetscInt a = 0; a < g->nnode; a++) vol[a] = 0;
  for (PetscInt q = 0; q < g->full.n; q++) {
    if (!TslElementPointEvaluate(in->type, in->sec, in->x, g->full.xi[q], g->full.w[q], &p)) return PETSC_FALSE;
    for (PetscInt a = 0; a < g->nnode; a++) vol[a] += p.N[a] * p.dV;
  }
  return PETSC_TRUE;
}

/* HRZ lumping (Hinton, Rock and Zienkiewicz 1976): V_a = V int N_a^2 dV / sum_b int N_b^2 dV; positive
 * for every family, exact total volume. Row sums when the family is linear. The integrals with the family's
 * lumping rule where its full rule is not exact for N_a^2 (tri6, tet10): on a straight-sided element the
 * weights are then V/19 at the tri6 corners and 16V/57 at its midside nodes, V/36 at the tet10 corners and
 * 4V/27 at its midside nodes (row sums would give 0 and V/3, -V/20 and V/5). */
static PetscBool Lump(const TslElementInput *in, PetscReal vol[])
{
  const TslGeometry *g = in->type->geom;
  TslElementPoint    p;
  const TslQuadrature *rule = g->lump.n ? &g->lump : &g->full;
  PetscReal            V = 0, sum = 0;

  if (g->order < 2) return RowSum(in, vol);
  for (PetscInt a = 0; a < g->nnode; a++) vol[a] = 0;
  for (PetscInt q = 0; q < rule->n; q++) {
    if (!TslElementPointEvaluate(in->type, in->sec, in->x, rule->xi[q], rule->w[q], &p)) return PETSC_FALSE;
    V += p.dV;
    for (PetscInt a = 0; a < g->nnode; a++) vol[a] += p.N[a] * p.N[a] * p.dV;
  }
  for (PetscInt a = 0; a < g->nnode; a++) sum += vol[a];
  for (PetscInt a = 0; a < g->nnode; a++) vol[a] *= V / sum;
  return PETSC_TRUE;
}

/* Row sums over the linear sub-elements: each sub-element's nodal volumes go to the parent's nodes. The
 * sub-element is evaluated as a linear element of the same kinematics on its own nodes' coordinates. */
static PetscBool SubElementLump(const TslElementInput *in, PetscReal vol[])
{
  const TslGeometry *g = in->type->geom, *sg = g->sub_geom;
  TslElementType     sub = *in->type;
  PetscReal          xs[4 * 3];
  TslElementPoint    p;

  if (!g->nsub) return Lump(in, vol);
  sub.geom = sg;
  for (PetscInt a = 0; a < g->nnode; a++) vol[a] = 0;
  for (PetscInt s = 0; s < g->nsub; s++) {
    for (PetscInt c = 0; c < sg->nnode; c++)
      for (PetscInt d = 0; d < 3; d++) xs[3 * c + d] = in->x[3 * g->sub_node[s][c] + d];
    for (PetscInt q = 0; q < sg->full.n; q++) {
      if (!TslElementPointEvaluate(&sub, in->sec, xs, sg->full.xi[q], sg->full.w[q], &p)) return PETSC_FALSE;
      for (PetscInt c = 0; c < sg->nnode; c++) vol[g->sub_node[s][c]] += p.N[c] * p.dV;
    }
  }
  return PETSC_TRUE;
}

/* The face family's own shape functions at the points of its as_face rule: exact for N_a N_b on a flat
 * face (the film matrix), N_a N_b r on an axisymmetric one. */
static void FaceRuleOwn(const TslGeometry *g, PetscInt face, TslFaceRule *rule)
{
  const TslGeometry   *fg   = g->face_geom[face];
  const TslQuadrature *quad = &fg->as_face;
  PetscReal            dN[TSL_MAX_FACE_NODES * 3];

  rule->n = quad->n;
  for (PetscInt q = 0; q < quad->n; q++) {
    fg->shape(quad->xi[q], rule->N[q], dN);
    for (PetscInt f = 0; f < fg->nnode; f++)
      for (PetscInt j = 0; j < fg->dim; j++) rule->dN[q][f][j] = dN[fg->dim * f + j];
    rule->w[q] = quad->w[q];
  }
}

/* The linear sub-faces of a quadratic 3D face (tri6 -> 4 tri3): composite linear shape functions, so
 * the nodal weights of a uniform pressure are all positive. 2D faces (line3) keep their own rule, whose
 * weights (1/6, 2/3, 1/6) already are. */
static void FaceRuleSub(const TslGeometry *g, PetscInt face, TslFaceRule *rule)
{
  const TslGeometry *fg = g->face_geom[face], *sg = fg->sub_geom;
  PetscReal          N[TSL_MAX_FACE_NODES], dN[TSL_MAX_FACE_NODES * 3];

  if (!fg->nsub || fg->dim < 2) {
    FaceRuleOwn(g, face, rule);
    return;
  }
  rule->n = 0;
  for (PetscInt s = 0; s < fg->nsub; s++)
    for (PetscInt q = 0; q < sg->full.n; q++) {
      PetscInt k = rule->n++;
      sg->shape(sg->full.xi[q], N, dN);
      for (PetscInt f = 0; f < fg->nnode; f++) {
        rule->N[k][f] = 0;
        for (PetscInt j = 0; j < 2; j++) rule->dN[k][f][j] = 0;
      }
      for (PetscInt c = 0; c < sg->nnode; c++) {
        const PetscInt f = fg->sub_node[s][c];
        rule->N[k][f]    = N[c];
        for (PetscInt j = 0; j < sg->dim; j++) rule->dN[k][f][j] = dN[sg->dim * c + j];
      }
      rule->w[k] = sg->full.w[q];
    }
}

/* Hourglass control of the one-point quad4 and hex8 (Flanagan and Belytschko 1981, stiffness form).
 * The hourglass base vectors h^k are the nodal values of the products of reference coordinates that
 * the one-point rule cannot see (xi eta in 2D; xi eta, eta zeta, zeta xi, xi eta zeta in 3D);
 *   gamma^k_a = [h^k_a - (sum_b h^k_b x_b) . b_a] / n,   b_a = grad N_a at the centre, n nodes,
 * are orthogonal to every linear field, so rigid motion and uniform strain (the patch test) produce no
 * hourglass force. With q^k_i = sum_a gamma^k_a u_ia:
 *   f_ia = kappa sum_k gamma^k_a q^k_i,  energy = kappa/2 sum_k,i (q^k_i)^2,  kappa = s mu V sum_a |b_a|^2,
 * mu taken at the centre temperature (its derivative enters the temperature columns of the tangent). */
PetscInt TslElementHourglassVectors(const TslGeometry *g, PetscReal h[4][TSL_MAX_ELEM_NODES])
{
  const PetscInt n  = g->nnode;
  PetscInt       nh = 0;

  /* base vectors: products of two or more reference coordinates at the nodes */
  for (PetscInt mask = 3; mask < (1 << g->dim); mask++) {
    PetscInt bits = 0;
    for (PetscInt d = 0; d < g->dim; d++) bits += (mask >> d) & 1;
    if (bits < 2) continue;
    for (PetscInt a = 0; a < n; a++) {
      h[nh][a] = 1;
      for (PetscInt d = 0; d < g->dim; d++)
        if ((mask >> d) & 1) h[nh][a] *= g->node_xi[a][d];
    }
    nh++;
  }
  return nh;
}

PetscInt TslElementHourglassBase(const TslElementInput *in, const TslElementPoint *p, PetscReal gamma[4][TSL_MAX_ELEM_NODES], PetscReal hx[4][3],
                                 PetscReal *bb)
{
  const PetscInt dim = in->type->dim, n = in->type->geom->nnode, nh = TslElementHourglassVectors(in->type->geom, gamma);

  for (PetscInt k = 0; k < nh; k++) {
    PetscReal hk[3] = {0, 0, 0};
    for (PetscInt b = 0; b < n; b++)
      for (PetscInt d = 0; d < dim; d++) hk[d] += gamma[k][b] * in->x[3 * b + d];
    for (PetscInt a = 0; a < n; a++) {
      for (PetscInt d = 0; d < dim; d++) gamma[k][a] -= hk[d] * p->dNdx[a][d];
      gamma[k][a] /= n; /* Flanagan-Belytschko's normalisation (1/4 in 2D, 1/8 in 3D) */
    }
    if (hx)
      for (PetscInt d = 0; d < dim; d++) hx[k][d] = hk[d];
  }
  *bb = 0;
  for (PetscInt a = 0; a < n; a++)
    for (PetscInt d = 0; d < dim; d++) *bb += p->dNdx[a][d] * p->dNdx[a][d];
  return nh;
}

/* f_ia = kappa sum_k gamma^k_a q^k_i for the vectors gamma[0..nh) (a zero vector skipped), kappa from bb. */
static PetscErrorCode HourglassApply(const TslElementInput *in, const TslMaterialPoint *mp, const TslElementPoint *p,
                                     PetscReal gamma[4][TSL_MAX_ELEM_NODES], PetscInt nh, PetscReal bb, PetscReal R[], PetscReal K[],
                                     PetscReal *energy)
{
  const TslElementType *t   = in->type;
  const PetscInt        dim = t->dim, ndof = t->ndof, th = ndof - 1, nu = ndof - 1, n = t->geom->nnode, nd = TslElementTypeNodes(t) * ndof;
  const PetscBool       twist = TslKinematicsRowGet(t->kin)->twist;
  const PetscReal       mu    = mp->E / (2 * (1 + mp->nu));
  const PetscReal       dmu   = mp->dE / (2 * (1 + mp->nu)) - mp->dnu * mp->E / (2 * (1 + mp->nu) * (1 + mp->nu));
  const PetscReal       kappa = TslElementHourglassKappa(mu, p->dV, bb), dkappa = TslElementHourglassKappa(dmu, p->dV, bb);

  PetscFunctionBeginUser;
  *energy = 0;
  for (PetscInt k = 0; k < nh; k++) {
    PetscReal gg = 0;
    for (PetscInt a = 0; a < n; a++) gg += gamma[k][a] * gamma[k][a];
    if (gg == 0) continue; /* a product of coordinates that vanishes at every node (wedge6: xi eta) */
    for (PetscInt i = 0; i < nu; i++) {
      /* a twist unknown is an angle: its hourglass displacement is r phi (r at the centre) */
      const PetscReal s  = i < dim ? 1 : p->x[0] * p->x[0];
      PetscReal       qk = 0;
      if (i >= dim && !twist) continue; /* an unused slot (generalized plane strain) */
      for (PetscInt a = 0; a < n; a++) qk += gamma[k][a] * in->u[ndof * a + i];
      *energy += 0.5 * s * kappa * qk * qk;
      for (PetscInt a = 0; a < n; a++) {
        R[ndof * a + i] += s * kappa * gamma[k][a] * qk;
        if (!K) continue;
        for (PetscInt b = 0; b < n; b++) {
          K[(ndof * a + i) * nd + ndof * b + i] += s * kappa * gamma[k][a] * gamma[k][b];
          K[(ndof * a + i) * nd + ndof * b + th] += s * dkappa * gamma[k][a] * qk * p->N[b];
        }
      }
    }
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscReal TslElementShellHourglassSum(const TslElementSection *sec, const TslGeometry *g, const TslElementPoint *p)
{
  const PetscInt s = TslElementShellStack(sec);
  PetscReal      nrm[3], len = 0, bb = 0;

  for (PetscInt d = 0; d < 3; d++) nrm[d] = p->Ji[s][d], len += nrm[d] * nrm[d];
  len = PetscSqrtReal(len);
  for (PetscInt a = 0; a < g->nnode; a++) {
    PetscReal gn = 0, gg = 0;
    for (PetscInt d = 0; d < 3; d++) gn += p->dNdx[a][d] * nrm[d] / len, gg += p->dNdx[a][d] * p->dNdx[a][d];
    bb += gg - gn * gn;
  }
  return bb;
}

/* The control at the element centre; inplane: bb over the gradients' parts normal to the continuum shell's
 * stack direction (ShellHourglass), else the whole gradients. */
static PetscErrorCode HourglassAtCentre(const TslElementInput *in, const TslMaterialPoint *mp, PetscBool inplane, PetscReal R[], PetscReal K[],
                                        PetscReal *energy)
{
  const TslGeometry *g = in->type->geom;
  PetscReal          xi0[3], gamma[4][TSL_MAX_ELEM_NODES], bb;
  TslElementPoint    p;
  PetscInt           nh;

  PetscFunctionBeginUser;
  TslElementCentre(g, xi0);
  PetscCheck(TslElementPointEvaluate(in->type, in->sec, in->x, xi0, g->ref_volume, &p), PETSC_COMM_SELF, PETSC_ERR_PLIB,
             "hourglass control of an inverted element");
  nh = TslElementHourglassBase(in, &p, gamma, NULL, &bb);
  if (inplane) bb = TslElementShellHourglassSum(in->sec, g, &p);
  PetscCall(HourglassApply(in, mp, &p, gamma, nh, bb, R, K, energy));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode HourglassStiffness(const TslElementInput *in, const TslMaterialPoint *mp, PetscReal R[], PetscReal K[], PetscReal *energy)
{
  PetscFunctionBeginUser;
  PetscCall(HourglassAtCentre(in, mp, PETSC_FALSE, R, K, energy));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* A continuum shell's points lie on the line through the centre along the stack direction: besides the
 * in-plane hourglass modes (xi eta, xi eta zeta) the twist of the element about that line strains none of
 * them. All the Flanagan-Belytschko vectors are stabilised, but with bb summed over the gradients' in-plane
 * parts only: with the whole |grad N|^2, ~ 1/t^2, the control of a thin element would stiffen its
 * bending (the xi zeta, eta zeta modes the points do see) by (L/t)^2; in-plane it adds a few percent. */
static PetscErrorCode ShellHourglass(const TslElementInput *in, const TslMaterialPoint *mp, PetscReal R[], PetscReal K[], PetscReal *energy)
{
  PetscFunctionBeginUser;
  PetscCall(HourglassAtCentre(in, mp, PETSC_TRUE, R, K, energy));
  PetscFunctionReturn(PETSC_SUCCESS);
}

const TslFormulation TslFormFull    = {"full integration", FullRule, NULL, NULL, Lump, FaceRuleOwn, FaceRuleOwn, PETSC_TRUE, NULL};
const TslFormulation TslFormReduced = {
    "reduced integration, hourglass control", ReducedRule, NULL, HourglassStiffness, Lump, FaceRuleOwn, FaceRuleOwn, PETSC_FALSE, NULL};
/* Reduced integration of a second-order brick (C3D20RT: 2 x 2 x 2): no hourglass control, as in the dialect (its
 * one spurious mode does not propagate through a mesh). */
const TslFormulation TslFormReducedQuadratic = {"reduced integration", ReducedRule, NULL, NULL, Lump, FaceRuleOwn, FaceRuleOwn, PETSC_TRUE, NULL};
/* the expanded S8RT (src/deck/shell.c): C3D20RT with its pressure on the faces' linear pieces (quad8: six tri3),
 * as the modified types take theirs: the serendipity face's consistent corner weights (-A/12) lift a thin
 * shell's corners off a contact surface under pressure */
const TslFormulation TslFormReducedQuadraticShell = {
    "reduced integration, pressure on linear sub-faces", ReducedRule, NULL, NULL, Lump, FaceRuleSub, FaceRuleOwn, PETSC_TRUE, NULL};
/* Full integration with the 3D pressure on the faces' linear pieces (tri6 -> 4 tri3, quad8 -> 6 tri3), as the
 * modified types take theirs: the full quadratic tetrahedron and wedge (C3D10T, C3D15T), whose consistent face
 * weights are zero (tri6) or negative (quad8) at the corners; contact takes those faces as the same pieces.
 * Mass (and the explicit capacity) by HRZ lumping (positive), the implicit capacity consistent, the rest as full. */
const TslFormulation TslFormFullSubFace = {
    "full integration, pressure on linear sub-faces", FullRule, NULL, NULL, Lump, FaceRuleSub, FaceRuleOwn, PETSC_TRUE, NULL};
/* C3D10HT: the full tet10 with the linear hybrid pressure of the other second-order hybrids and C3D10T's faces. */
const TslFormulation TslFormHybridSubFace = {
    "hybrid, pressure on linear sub-faces", FullRule, PressureBasis, NULL, Lump, FaceRuleSub, FaceRuleOwn, PETSC_TRUE, NULL};
/* CPE8RHT, CAX8RHT: the 2 x 2 quad8 with the linear hybrid pressure of CPE8HT (3 terms at 4 points). */
const TslFormulation TslFormReducedQuadraticHybrid = {
    "reduced integration, hybrid", ReducedRule, PressureBasis, NULL, Lump, FaceRuleOwn, FaceRuleOwn, PETSC_TRUE, NULL};
const TslFormulation TslFormHybrid        = {"hybrid", FullRule, PressureBasis, NULL, Lump, FaceRuleOwn, FaceRuleOwn, PETSC_TRUE, NULL};
const TslFormulation TslFormReducedHybrid = {
    "reduced integration, hourglass control, hybrid", ReducedRule, PressureBasis, HourglassStiffness, Lump, FaceRuleOwn, FaceRuleOwn, PETSC_FALSE, NULL};
const TslFormulation TslFormModified       = {"modified second order", FullRule, NULL, NULL, SubElementLump, FaceRuleSub, FaceRuleOwn, PETSC_TRUE, NULL};
const TslFormulation TslFormModifiedHybrid = {
    "modified second order, hybrid", FullRule, PressureBasis, NULL, SubElementLump, FaceRuleSub, FaceRuleOwn, PETSC_TRUE, NULL};
const TslFormulation TslFormContinuumShell = {"continuum shell: reduced in-plane, Simpson through the thickness, hourglass control",
                                              ShellRule,
                                              NULL,
                                              ShellHourglass,
                                              Lump,
                                              FaceRuleOwn,
                                              FaceRuleOwn,
                                              PETSC_FALSE,
                                              NULL};

/* Incompatible modes (C3D8I, CPE4I, CPS4I, CAX4I; Wilson, Taylor et al.): the full rule with the bubble
 * displacements P_k = 1 - xi_k^2 (one per reference direction, each in every displacement component) condensed in
 * the element (kernels.c, MechanicsIncompatible): dP[k][j] = dP_k / dxi_j at xi; returns their number. */
static PetscInt IncompatibleModes(const TslGeometry *g, const PetscReal xi[], PetscReal dP[][3])
{
  for (PetscInt k = 0; k < g->dim; k++)
    for (PetscInt j = 0; j < 3; j++) dP[k][j] = j == k ? -2 * xi[k] : 0;
  return g->dim;
}
const TslFormulation TslFormIncompatible = {
    "full integration, incompatible modes", FullRule, NULL, NULL, Lump, FaceRuleOwn, FaceRuleOwn, PETSC_TRUE, IncompatibleModes};

PetscBool TslElementTypeSubdividedFace(const TslElementType *t, PetscInt face)
{
  const TslGeometry *fg = face >= 0 && face < t->geom->nface ? t->geom->face_geom[face] : NULL;
  return (PetscBool)(t->form->pressure_face_rule == FaceRuleSub && fg && fg->nsub > 0 && fg->dim >= 2);
}

const char *TslElementTypeFormulationName(const TslElementType *t)
{
  return t->form->name;
}

PetscBool TslElementTypeFiniteStrain(const TslElementType *t)
{
  return t->form->incompatible ? PETSC_FALSE : PETSC_TRUE;
}

PetscBool TslElementTypePlasticSupported(const TslElementType *t, const char **why)
{
  (void)t; /* every kinematics and formulation takes *PLASTIC now (a future one without it names itself here) */
  *why = NULL;
  return PETSC_TRUE;
}
