/* Kinematic contact enforcement in explicit steps (*CONTACT PAIR, MECHANICAL CONSTRAINT=KINEMATIC;
 * docs/explicit.md, "Kinematic contact").
 *
 * A predictor-corrector (src/solve/explicit.c): the increment is first advanced without the kinematic
 * pairs' forces; their nodes are then evaluated at that predicted state by the ordinary node-to-surface
 * kernels, each node with its own penalty k_s / A_s, and the resulting forces correct the accelerations of
 * the same increment. With the nodal masses of the lumped mass matrix, a force f on the secondary node s
 * (and -N_j f on the main face's nodes j) changes the gap in one increment by
 *   f h h_avg (1/m_s + sum_j N_j^2 / m_j)   (h the new increment, h_avg the mean of the last two),
 * i.e. the gaps of all nodes respond to their forces through the compliance matrix
 *   A = h h_avg (M_s^-1 + B M_m^-1 B^T),   B_sj = N_j(s).
 * Closing every gap exactly would need A^-1 (a solve coupling the nodes that share main nodes). This
 * corrector uses A lumped by rows, k_s = 1 / (A 1)_s = 1 / (h h_avg (1/m_s + sum_j N_j(s) w_j / m_j)) with
 * w_j = sum_s N_j(s) the load of main node j: exact for a node alone on its face and for a uniform
 * penetration of a whole surface (the quasi-static case), and contracting (A has non-negative entries,
 * so diag(A 1) - A is diagonally dominant and the remaining gap (I - A diag(A 1)^-1) g has eigenvalues in
 * [0, 1): smaller in norm, though a node may end slightly open next to one still penetrating): what is left
 * is closed by the next increments, and the corrector adds no spring to the stable increment. Prescribed
 * directions count as infinitely heavy (1/m = 0).
 *
 * The same stiffness holds a sticking node (penalty friction's stick stiffness k_s / A_s, no elastic-slip
 * tolerance; TslContactKinematicLaw), so its predicted slip is undone in the increment up to the Coulomb
 * limit. The heat terms (gap conductance at the corrector's pressure, radiation at the predicted gap,
 * frictional heat of the corrected slip) come from the same kernel evaluation. */
#include "problem_impl.h"

/* The face shape functions of node cn at the projection its history starts from (last: at its last
 * evaluation instead), inside the face, non-negative, summing to 1; *n of them, main face nodes main[]
 * (local, -1 padded). */
static void FaceWeights(TslProblem p, const TslContactNode *cn, PetscBool last, PetscReal N[], PetscInt main[], PetscInt *n)
{
  const TslContactSurface *cs  = &p->csurf[cn->pair];
  PetscReal                sum = 0;

  *n = cs->nper;
  for (PetscInt a = 0; a < cs->nper; a++) main[a] = cs->main_lnode[cs->nper * cn->seg + a], N[a] = 0;
  if (cs->dim == 3) {
    PetscReal xi[2] = {last ? cn->out.xi : cn->hist.xi_old, last ? cn->out.eta : cn->hist.eta_old};
    TslContactFace3ShapeValues(cs->kind[cn->seg], xi, N);
  } else {
    PetscReal dN[TSL_CONTACT_MAX_FACE_NODES], d2N[TSL_CONTACT_MAX_FACE_NODES];
    TslContactFaceShape(TslContactFaceGet(cs->face), PetscMin(1, PetscMax(0, last ? cn->out.xi : cn->hist.xi_old)), N, dN, d2N);
  }
  for (PetscInt a = 0; a < cs->nper; a++) {
    if (main[a] < 0) N[a] = 0;
    N[a] = PetscMax(0, N[a]);
    sum += N[a];
  }
  for (PetscInt a = 0; a < cs->nper; a++) N[a] = sum > 0 ? N[a] / sum : 0;
}

/* Inverse mass of local node l along the unit vector n (dim components): sum_d n_d^2 / m_d, a prescribed
 * direction counting as infinitely heavy. */
static PetscReal InverseMass(TslProblem p, const TslContactSurface *cs, const PetscScalar *m, const PetscScalar *mask, PetscInt l, const PetscReal n[])
{
  PetscReal inv = 0;
  for (PetscInt d = 0; d < p->dim; d++) {
    const PetscInt  i  = l * p->ndof + cs->slot[d];
    const PetscReal md = PetscRealPart(m[i]);
    if (PetscRealPart(mask[i]) == 0 && md > 0) inv += n[d] * n[d] / md;
  }
  return inv;
}

/* The unit normal of node cn's last evaluation. */
static void LastNormal(TslProblem p, const TslContactNode *cn, PetscReal nrm[3])
{
  nrm[0] = cn->out.normal[0], nrm[1] = cn->out.normal[1], nrm[2] = p->dim == 3 ? cn->out.normal_z : 0;
}

/* Read access to the local form (ghosts included) of a ghosted vector. */
typedef struct {
  Vec                v, l;
  const PetscScalar *a;
} LocalRead;

static PetscErrorCode LocalReadGet(Vec v, LocalRead *r)
{
  PetscFunctionBeginUser;
  r->v = v;
  PetscCall(VecGhostGetLocalForm(v, &r->l));
  PetscCall(VecGetArrayRead(r->l, &r->a));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode LocalReadRestore(LocalRead *r)
{
  PetscFunctionBeginUser;
  PetscCall(VecRestoreArrayRead(r->l, &r->a));
  PetscCall(VecGhostRestoreLocalForm(r->v, &r->l));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TslProblemContactKinematicStiffness(TslProblem p, Vec M, Vec Mask, Vec W, PetscReal hh)
{
  Vec          wl;
  PetscScalar *w;
  LocalRead    m, mask, load;

  PetscFunctionBeginUser;
  /* the loads w_j of the main nodes, summed over the ranks that own secondary nodes on them */
  PetscCall(VecGhostGetLocalForm(W, &wl));
  PetscCall(VecZeroEntries(wl));
  PetscCall(VecGetArray(wl, &w));
  for (PetscInt i = 0; i < p->ncnode; i++) {
    const TslContactNode *cn = &p->cnode[i];
    PetscReal             N[TSL_CONTACT3_MAX_FACE_NODES];
    PetscInt              main[TSL_CONTACT3_MAX_FACE_NODES], n;
    if (cn->seg < 0 || !p->csurf[cn->pair].kinematic) continue;
    FaceWeights(p, cn, PETSC_FALSE, N, main, &n);
    for (PetscInt a = 0; a < n; a++)
      if (main[a] >= 0) w[main[a] * p->ndof] += N[a];
  }
  PetscCall(VecRestoreArray(wl, &w));
  PetscCall(VecGhostRestoreLocalForm(W, &wl));
  PetscCall(TslGhostUpdate(W, ADD_VALUES, SCATTER_REVERSE));
  PetscCall(TslGhostUpdate(W, INSERT_VALUES, SCATTER_FORWARD)); /* M's ghosts: kept current by the caller */

  PetscCall(LocalReadGet(W, &load));
  PetscCall(LocalReadGet(M, &m));
  PetscCall(LocalReadGet(Mask, &mask));
  for (PetscInt i = 0; i < p->ncnode; i++) {
    TslContactNode          *cn = &p->cnode[i];
    const TslContactSurface *cs = &p->csurf[cn->pair];
    PetscReal                N[TSL_CONTACT3_MAX_FACE_NODES], nrm[3], len, inv;
    PetscInt                 main[TSL_CONTACT3_MAX_FACE_NODES], n;

    cn->k_kin   = 0;
    cn->settled = PETSC_FALSE;
    if (cn->seg < 0 || !cs->kinematic) continue;
    /* the direction of the correction: the normal of the node's last evaluation (any, before the first) */
    LastNormal(p, cn, nrm);
    len = PetscSqrtReal(nrm[0] * nrm[0] + nrm[1] * nrm[1] + nrm[2] * nrm[2]);
    for (PetscInt d = 0; d < 3; d++) nrm[d] = len > 0 ? nrm[d] / len : (d < p->dim ? 1 / PetscSqrtReal((PetscReal)p->dim) : 0);
    FaceWeights(p, cn, PETSC_FALSE, N, main, &n);
    inv = InverseMass(p, cs, m.a, mask.a, cn->lnode, nrm);
    for (PetscInt a = 0; a < n; a++)
      if (main[a] >= 0 && N[a] > 0) inv += N[a] * PetscRealPart(load.a[main[a] * p->ndof]) * InverseMass(p, cs, m.a, mask.a, main[a], nrm);
    cn->k_kin = inv > 0 ? 1 / (hh * inv) : 0;
  }
  PetscCall(LocalReadRestore(&mask));
  PetscCall(LocalReadRestore(&m));
  PetscCall(LocalReadRestore(&load));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Displacement correction -hh Fk / m of local node l along nrm (prescribed directions do not move). */
static PetscReal Correction(TslProblem p, const TslContactSurface *cs, const PetscScalar *fk, const PetscScalar *m, const PetscScalar *mask, PetscInt l,
                            const PetscReal nrm[], PetscReal hh)
{
  PetscReal du = 0;
  for (PetscInt d = 0; d < p->dim; d++) {
    const PetscInt i = l * p->ndof + cs->slot[d];
    if (PetscRealPart(mask[i]) == 0 && PetscRealPart(m[i]) > 0) du += nrm[d] * (-hh * PetscRealPart(fk[i]) / PetscRealPart(m[i]));
  }
  return du;
}

/* The linearised gap of kinematic node cn after the correction -hh M^-1 Fk (fk: its local form, ghosts
 * updated), the node's unit normal nrm, its face weights N and main nodes main[] (*n). */
static PetscReal LinearGap(TslProblem p, const TslContactNode *cn, const PetscScalar *fk, const PetscScalar *m, const PetscScalar *mask, PetscReal hh,
                           PetscReal nrm[3], PetscReal N[], PetscInt main[], PetscInt *n)
{
  const TslContactSurface *cs = &p->csurf[cn->pair];
  PetscReal                g;

  LastNormal(p, cn, nrm);
  FaceWeights(p, cn, PETSC_TRUE, N, main, n);
  g = cn->out.gap + Correction(p, cs, fk, m, mask, cn->lnode, nrm, hh);
  for (PetscInt a = 0; a < *n; a++)
    if (main[a] >= 0 && N[a] > 0) g -= N[a] * Correction(p, cs, fk, m, mask, main[a], nrm, hh);
  return g;
}

PetscErrorCode TslProblemContactKinematicPass(TslProblem p, Vec Fk, Vec M, Vec Mask, Vec W, PetscReal hh, PetscReal tol, PetscReal gap_tol,
                                              PetscReal *residual, PetscReal change[3], PetscBool *applied)
{
  Vec          wl;
  PetscScalar *w;
  LocalRead    fk, m, mask;
  PetscReal    loc[3] = {0, 0, 0};

  PetscFunctionBeginUser;
  *applied = PETSC_FALSE;
  PetscCall(TslGhostUpdate(Fk, INSERT_VALUES, SCATTER_FORWARD));
  PetscCall(LocalReadGet(Fk, &fk));
  PetscCall(LocalReadGet(M, &m));
  PetscCall(LocalReadGet(Mask, &mask));
  for (PetscInt pass = 0; pass < 2; pass++) { /* the changes, then (if any is worth it) their forces */
    if (pass == 1) {
      PetscBool go;
      PetscCall(MPIU_Allreduce(loc, change, 3, MPIU_REAL, MPIU_MAX, p->comm));
      /* the pressures still moving, or (gap_tol > 0) gaps (penetrations, pressed nodes gone open) above gap_tol that
       * the passes still close: the pressure criterion alone leaves overlaps in proportion to tol on triangle faces */
      go        = (PetscBool)(change[0] > tol * change[1] || (gap_tol > 0 && change[2] > gap_tol && change[2] < 0.9 * *residual));
      *residual = change[2];
      if (!go) break;
      *applied = PETSC_TRUE;
      PetscCall(VecGhostGetLocalForm(W, &wl));
      PetscCall(VecZeroEntries(wl));
      PetscCall(VecGetArray(wl, &w));
    }
    for (PetscInt i = 0; i < p->ncnode; i++) {
      TslContactNode          *cn = &p->cnode[i];
      const TslContactSurface *cs = &p->csurf[cn->pair];
      PetscReal                N[TSL_CONTACT3_MAX_FACE_NODES], nrm[3], A, g, dp;
      PetscInt                 main[TSL_CONTACT3_MAX_FACE_NODES], n;

      if (cn->seg < 0 || !cs->kinematic || !(cn->k_kin > 0)) continue;
      A  = TslProblemContactNodeArea(p, cn);
      g  = LinearGap(p, cn, fk.a, m.a, mask.a, hh, nrm, N, main, &n);
      dp = PetscMax(-cn->k_kin / A * g, -cn->out.pressure);
      if (pass == 0) {
        loc[0] = PetscMax(loc[0], PetscAbsReal(dp));
        loc[1] = PetscMax(loc[1], cn->out.pressure);
        loc[2] = PetscMax(loc[2], (g < 0 ? -g : cn->out.pressure > 0 ? g : 0) / cs->search_radius);
        continue;
      }
      /* residual form, as the kernels: R_s = -A dp n, R_j = +A dp N_j n */
      cn->out.pressure += dp;
      for (PetscInt d = 0; d < p->dim; d++) {
        w[cn->lnode * p->ndof + cs->slot[d]] -= A * dp * nrm[d];
        for (PetscInt a = 0; a < n; a++)
          if (main[a] >= 0) w[main[a] * p->ndof + cs->slot[d]] += A * dp * N[a] * nrm[d];
      }
    }
  }
  PetscCall(LocalReadRestore(&mask));
  PetscCall(LocalReadRestore(&m));
  PetscCall(LocalReadRestore(&fk));
  if (*applied) {
    PetscCall(VecRestoreArray(wl, &w));
    PetscCall(VecGhostRestoreLocalForm(W, &wl));
    PetscCall(TslGhostUpdate(W, ADD_VALUES, SCATTER_REVERSE));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Each node the passes left pressed, or that penetrates at the predicted state, gets the pressure offset that makes
 * its normal law p = <p_kin + (k_s / A) (-g)> give the passes' pressure at its predicted gap: the node's own
 * stiffness, whatever the gap (a node pressed by the passes while its predicted gap is open, or a gap at round-off,
 * keeps its pressure; a penalty p / -g could do neither). A node open at the predicted state that the passes left
 * without pressure stays open (no gap conductance). */
PetscErrorCode TslProblemContactKinematicSettle(TslProblem p)
{
  PetscFunctionBeginUser;
  for (PetscInt i = 0; i < p->ncnode; i++) {
    TslContactNode *cn = &p->cnode[i];
    if (cn->seg < 0 || !p->csurf[cn->pair].kinematic || !(cn->k_kin > 0) || !(cn->out.gap < 0 || cn->out.pressure > 0)) continue;
    cn->settled = PETSC_TRUE;
    cn->p_kin   = cn->out.pressure + TslProblemContactKinematicPenalty(p, cn) * cn->out.gap;
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}
