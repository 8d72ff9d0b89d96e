/* The interface's share of the explicit stable increment (src/solve/explicit.c), for node-to-surface and
 * surface-to-surface pairs alike.
 *
 * Each contact point (an owned secondary node of a node-to-surface pair, a point of a surface-to-surface
 * face inserted by this rank) couples its nodes through a rank-one operator: the normal penalty
 * K_p = k_p a a^T (x) n n^T with k_p = eps_n A_p, and the interface heat exchange H_p = h_p a a^T with
 * h_p = (k + 4 C (theta - theta_Z)^3) A_p (gap conductance and the gap radiation's linearisation at the
 * hotter side), where a holds the point's weights on its nodes: +1 at a node-to-surface secondary node,
 * +N_b at the nodes of a surface-to-surface point's secondary face, and -N_a(xi) at its main face's nodes.
 *
 * The forward-difference limits need the largest eigenvalue of M^{-1} sum_p K_p (M the lumped masses) and of
 * C^{-1} sum_p H_p (C the lumped capacities). Block Gershgorin (a node's block M^{-1} K_ii is symmetric, its
 * coupling blocks have norm k_p |a_i| |a_j|) bounds both by the largest nodal row sum
 *     lambda <= max_i (1/m_i) sum_p k_p |a_pi| S_p,   S_p = sum_j |a_pj|,
 * summed over every point that touches node i, on whichever rank the point lives (a ghost update adds them
 * up): a main node loaded by several secondary nodes, or a node shared by several faces, gets all of them.
 * The main weights are bounded independently of where the point projects (|N_a| <= 1 on every face family,
 * S_p <= sum_b |a_b| + the family's largest sum_a |N_a|), so the bound holds wherever the point slides on
 * its current face; it is recomputed at every pairing search. Not counted: the nodes of the neighbouring
 * faces that 2D smoothing blends in within its band at a face's ends, and the tangential stiffness of
 * friction.
 */
#include "problem_impl.h"
#include "contact_s2s_impl.h"

/* Largest sum_a |N_a| over a face of a family: sampled on a fine grid (the functions are at most
 * quadratic, so the sample misses the maximum by less than 1e-3); 1 for linear faces. */
static PetscReal AbsSum2(TslContactFaceKind kind)
{
  const TslContactFace *face = TslContactFaceGet(kind);
  PetscReal             best = 1, N[TSL_MAX_ELEM_NODES], dN[TSL_MAX_ELEM_NODES], d2N[TSL_MAX_ELEM_NODES];

  if (!face) return best;
  for (PetscInt i = 0; i <= 200; i++) {
    PetscReal s = 0;
    TslContactFaceShape(face, i / 200.0, N, dN, d2N);
    for (PetscInt a = 0; a < face->geom->nnode; a++) s += PetscAbsReal(N[a]);
    best = PetscMax(best, s);
  }
  return best;
}

static PetscReal AbsSum3(PetscInt kind)
{
  PetscReal best = 1, N[TSL_MAX_ELEM_NODES];
  PetscInt  n    = TslContactFace3Nodes(kind);

  for (PetscInt i = 0; i <= 100; i++)
    for (PetscInt j = 0; j <= 100; j++) {
      PetscReal xi[2] = {-1 + i / 50.0, -1 + j / 50.0}, s = 0;
      if (!TslContactFace3Inside(kind, xi, 0)) continue;
      TslContactFace3ShapeValues(kind, xi, N);
      for (PetscInt a = 0; a < n; a++) s += PetscAbsReal(N[a]);
      best = PetscMax(best, s);
    }
  return best;
}

/* The main face of a pair's face seg: its nodes (-1 padded) and their count, and the largest sum of |N_a|
 * of its family (sampled once per family: the searches call this for every point). */
static void MainFace(const TslContactSurface *cs, PetscInt seg, const PetscInt **nodes, PetscInt *n, PetscReal *sigma)
{
  enum { MEMO3 = 16 }; /* 3D families memoised (more than contact/face3.c has; a larger kind is sampled each time) */
  static PetscReal sum2[TSL_CONTACT_FACE_NKINDS], sum3[MEMO3]; /* 0: not sampled yet (a sum is at least 1) */
  const PetscInt   kind = cs->dim == 3 ? cs->kind[seg] : (PetscInt)cs->face;
  PetscReal       *memo = cs->dim == 3 ? (kind >= 0 && kind < MEMO3 ? &sum3[kind] : NULL) : (kind >= 0 && kind < TSL_CONTACT_FACE_NKINDS ? &sum2[kind] : NULL);

  *nodes = &cs->main_lnode[cs->nper * seg];
  *n     = cs->nper;
  if (memo && *memo > 0) *sigma = *memo;
  else {
    *sigma = cs->dim == 3 ? AbsSum3(kind) : AbsSum2(cs->face);
    if (memo) *memo = *sigma;
  }
}

/* Adds one point's row sums: weights ws[] at its secondary nodes sec[], |N| <= 1 at its main nodes. */
static void AddPoint(PetscReal r[], PetscInt ndof, PetscInt slot, PetscInt ns, const PetscInt sec[], const PetscReal ws[], PetscInt nm, const PetscInt main[],
                     PetscReal sigma, PetscReal k)
{
  PetscReal S = sigma;
  if (!(k > 0)) return;
  for (PetscInt b = 0; b < ns; b++) S += PetscAbsReal(ws[b]);
  for (PetscInt b = 0; b < ns; b++) r[sec[b] * ndof + slot] += k * PetscAbsReal(ws[b]) * S;
  for (PetscInt a = 0; a < nm; a++)
    if (main[a] >= 0) r[main[a] * ndof + slot] += k * S;
}

/* The interface heat coefficient (per area) of a point from its last evaluation: conductance plus the
 * radiation's linearisation at the hottest of its nodes. */
static PetscReal HeatCoefficient(const TslProblem p, const TslContactSurface *cs, const TslContactOutput *out, const PetscScalar *xa, PetscInt ns,
                                 const PetscInt sec[], PetscInt nm, const PetscInt main[])
{
  const PetscInt th    = p->ndof - 1;
  PetscReal      theta = -PETSC_MAX_REAL;
  for (PetscInt b = 0; b < ns; b++) theta = PetscMax(theta, PetscRealPart(xa[sec[b] * p->ndof + th]));
  for (PetscInt a = 0; a < nm; a++)
    if (main[a] >= 0) theta = PetscMax(theta, PetscRealPart(xa[main[a] * p->ndof + th]));
  return out->conductance + 4 * out->radiation_C * PetscPowRealInt(PetscMax(0, theta - cs->law.theta_zero), 3);
}

/* Row sums of this rank's points into r[] (local form: slot 0 the penalty's, slot ndof-1 the heat's). */
static PetscErrorCode RowSums(TslProblem p, const PetscScalar *xa, PetscReal r[])
{
  const PetscInt th = p->ndof - 1;

  PetscFunctionBeginUser;
  for (PetscInt i = 0; i < p->ncnode; i++) {
    const TslContactNode    *cn  = &p->cnode[i];
    const TslContactSurface *cs  = &p->csurf[cn->pair];
    const PetscReal          one = 1, A = TslProblemContactNodeArea(p, cn);
    const PetscInt          *mf  = NULL;
    PetscInt                 nm  = 0;
    PetscReal                sigma = 1; /* unpaired: as if paired with a face as heavy as the node */

    if (cn->seg >= 0) MainFace(cs, cn->seg, &mf, &nm, &sigma);
    if (!cs->kinematic) AddPoint(r, p->ndof, 0, 1, &cn->lnode, &one, nm, mf, sigma, cs->law.eps_n * A);
    if (cn->seg >= 0) AddPoint(r, p->ndof, th, 1, &cn->lnode, &one, nm, mf, sigma, A * HeatCoefficient(p, cs, &cn->out, xa, 1, &cn->lnode, nm, mf));
  }
  if (p->s2s) {
    const TslContactS2S s = p->s2s;
    for (PetscInt f = 0; f < s->nface; f++) {
      const S2SFace           *fc = &s->face[f];
      const TslContactSurface *cs = &p->csurf[fc->pair];
      PetscReal                rmax = 0;

      if (!fc->assemble) continue; /* the rank that inserts the face counts it */
      if (cs->dim != 3 && TslKinematicsRevolves(cs->kin))
        for (PetscInt b = 0; b < fc->nsn; b++) rmax = PetscMax(rmax, p->m->node_xyz[3 * fc->lnode[b]]);
      for (PetscInt q = fc->first; q < fc->first + fc->npt; q++) {
        const S2SPoint *pt = &s->pt[q];
        const PetscInt *mf;
        PetscInt        nm;
        PetscReal       sigma, N[TSL_CONTACT3_MAX_FACE_NODES], A = pt->length;

        if (pt->seg < 0) continue;
        MainFace(cs, pt->seg, &mf, &nm, &sigma);
        if (cs->dim == 3) {
          for (PetscInt b = 0; b < fc->nsn; b++) N[b] = pt->N[b];
        } else {
          PetscReal dN[TSL_CONTACT3_MAX_FACE_NODES], d2N[TSL_CONTACT3_MAX_FACE_NODES];
          TslContactFaceShape(TslContactFaceGet(fc->kind), pt->zeta, N, dN, d2N);
          A *= TslKinematicsRevolves(cs->kin) ? 2 * PETSC_PI * rmax : cs->thickness;
        }
        AddPoint(r, p->ndof, 0, fc->nsn, fc->lnode, N, nm, mf, sigma, cs->law.eps_n * A);
        AddPoint(r, p->ndof, th, fc->nsn, fc->lnode, N, nm, mf, sigma, A * HeatCoefficient(p, cs, &pt->out, xa, fc->nsn, fc->lnode, nm, mf));
      }
    }
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Collective. The interface's limits dt_mech = 2 / sqrt(lambda_K) and dt_heat = 2 / lambda_H (the bounds of the
 * file's head) and the global ids of the nodes that set them (-1: no interface stiffness, dt PETSC_MAX_REAL).
 * M: the lumped (scaled) masses and capacities; W: a work vector of the same layout. */
PetscErrorCode TslProblemContactIncrements(TslProblem p, Vec M, Vec W, PetscReal *dt_mech, PetscInt *node_mech, PetscReal *dt_heat, PetscInt *node_heat)
{
  struct {
    double v;
    int    id;
  } loc[2] = {{PETSC_MAX_REAL, -1}, {PETSC_MAX_REAL, -1}}, g[2];
  Vec                xl, wl;
  const PetscScalar *xa, *m, *w;
  PetscScalar       *wa;
  const PetscInt     th = p->ndof - 1;

  PetscFunctionBeginUser;
  PetscCall(VecGhostGetLocalForm(W, &wl));
  PetscCall(VecZeroEntries(wl));
  PetscCall(VecGetArray(wl, &wa));
  PetscCall(TslProblemGetLocalSolution(p, &xl, &xa));
  PetscCall(RowSums(p, xa, (PetscReal *)wa));
  PetscCall(TslProblemRestoreLocalSolution(p, &xl, &xa));
  PetscCall(VecRestoreArray(wl, &wa));
  PetscCall(VecGhostRestoreLocalForm(W, &wl));
  PetscCall(TslGhostUpdate(W, ADD_VALUES, SCATTER_REVERSE));
  PetscCall(VecGetArrayRead(W, &w));
  PetscCall(VecGetArrayRead(M, &m));
  for (PetscInt l = 0; l < p->nown; l++) {
    PetscReal       rk = PetscRealPart(w[l * p->ndof]), rh = PetscRealPart(w[l * p->ndof + th]);
    const PetscReal mk = PetscRealPart(m[l * p->ndof]), ch = PetscRealPart(m[l * p->ndof + th]);
    PetscBool       moves = PETSC_FALSE;
    /* prescribed rows leave the operator (Gershgorin on what remains only drops terms) */
    for (PetscInt c = 0; c < th; c++) moves = (PetscBool)(moves || !(p->pinned[l * p->ndof + c] || p->bc[l * p->ndof + c].active));
    if (!moves) rk = 0;
    if (p->pinned[l * p->ndof + th] || p->bc[l * p->ndof + th].active) rh = 0;
    if (rk > 0 && mk > 0 && 2 / PetscSqrtReal(rk / mk) < loc[0].v) loc[0].v = 2 / PetscSqrtReal(rk / mk), loc[0].id = (int)p->m->node_id[l];
    if (rh > 0 && ch > 0 && 2 / (rh / ch) < loc[1].v) loc[1].v = 2 / (rh / ch), loc[1].id = (int)p->m->node_id[l];
  }
  PetscCall(VecRestoreArrayRead(M, &m));
  PetscCall(VecRestoreArrayRead(W, &w));
  PetscCallMPI(MPI_Allreduce(loc, g, 2, MPI_DOUBLE_INT, MPI_MINLOC, p->comm));
  *dt_mech = g[0].v, *node_mech = g[0].id;
  *dt_heat = g[1].v, *node_heat = g[1].id;
  PetscFunctionReturn(PETSC_SUCCESS);
}
