/* What the explicit procedure (src/solve/explicit.c) needs of the problem: nodal force and heat vectors,
 * lumped mass and capacity, element stable increments and the mask of prescribed dofs. Vectors only: an
 * explicit increment never builds a matrix. Every per-element computation goes through the one element
 * loop (TslProblemElementLoop) and the time-agnostic kernels (TslElementInternal, TslElementLumped,
 * TslElementFaceLoad), as the implicit assembly does. */
#include "problem_impl.h"
#include <thermoslide/lanes.h>
#include <stdint.h>

PetscErrorCode TslProblemSetMatrixFree(TslProblem p, PetscBool matrix_free)
{
  PetscFunctionBeginUser;
  p->matrix_free = matrix_free;
  PetscFunctionReturn(PETSC_SUCCESS);
}

typedef struct {
  PetscScalar       *fi, *fe;
  PetscScalar       *qp;          /* local form of the plastic heat sources (NULL: in fi) */
  const PetscScalar *v;           /* local form of the half-step velocity (NULL: no bulk viscosity from v, no damping) */
  const PetscReal   *eta, *eta2;  /* [nelem] b1 L_e / c_d and (b2 L_e / c_d)^2 (with q) */
  PetscReal         *q;           /* [nelem] q = p V of each element's viscosity: the last pass's in, this pass's out (NULL: no bulk viscosity) */
  PetscReal          power, prev; /* this rank's sum of q eps_vol_dot, and of the last pass's q times this pass's eps_vol_dot
                                     (and of the *DAMPING, BETA forces' power v . f_d in both: DampingElement) */
  PetscBool          damped;      /* some material has *DAMPING, BETA: v is gathered */
  PetscReal          hinv;        /* > 0: the records' rate from their centre strains over 1 / hinv (no gather of v); 0: from v */
  AsmHeat           *heat;
  PetscInt           bad;
} ForceCtx;

/* One element's face loads: mechanical rows (pressure, body forces) as forces into fe, heat rows (flux, film,
 * radiation) in residual form into fi. */
static PetscErrorCode FaceLoads(TslProblem p, PetscInt e, TslElemData *d, ForceCtx *c)
{
  PetscReal R[TSL_MAX_ELEM_DOF];
  PetscInt  th = p->ndof - 1;

  PetscFunctionBeginUser;
  for (PetscInt i = p->face_start[e]; i < p->face_start[e + 1]; i++) {
    const TslFaceRecord *rec = &p->face[i];
    PetscReal            h   = 0;
    PetscCall(PetscArrayzero(R, d->nd));
    PetscCall(TslProblemRecordLoad(p, rec, &d->in, R, NULL, &h));
    for (PetscInt r = 0; r < d->nd; r++) {
      if (r % p->ndof == th)
        c->fi[d->ld[r]] += R[r];
      else
        c->fe[d->ld[r]] -= R[r];
    }
    TslAsmHeatAdd(c->heat, rec->kind, h);
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* *DAMPING, BETA (docs/explicit.md "Damping"): the damping stress beta D^el : eps_dot of the velocity v, whose nodal forces
 * beta K v are the element's own small-strain elastic forces at u = v (the thermal strain taken away: the temperatures
 * and their reference both the current ones, so D is the current temperature's; no plastic state: D^el), added to the
 * mechanical rows of R; *power gets v . f_d = beta v^T K v >= 0. The extra nodes' slots (CPEG's reference node) are
 * mechanical: all of them take v. */
static PetscErrorCode DampingElement(const TslElemData *d, const PetscScalar *v, PetscReal beta, PetscInt ndof, PetscReal R[], PetscReal *power)
{
  TslElementInput in = d->in;
  PetscReal       uv[TSL_MAX_ELEM_DOF], tv[TSL_MAX_ELEM_NODES], Rd[TSL_MAX_ELEM_DOF];
  const PetscInt  ng = in.type->geom->nnode, th = ndof - 1;
  PetscBool       inverted = PETSC_FALSE;

  PetscFunctionBeginUser;
  for (PetscInt a = 0; a < d->n; a++) {
    for (PetscInt i = 0; i < ndof; i++) uv[a * ndof + i] = a < ng && i == th ? d->u[a * ndof + i] : PetscRealPart(v[d->ld[a * ndof + i]]);
    tv[a] = a < ng ? d->u[a * ndof + th] : d->ti[a];
  }
  in.u = uv, in.theta_init = tv, in.pstate = NULL, in.pstate_new = NULL, in.inelastic_rate = 0, in.nlgeom = PETSC_FALSE;
  PetscCall(TslElementInternal(&in, Rd, NULL, &inverted)); /* the element's geometry passed: never inverted here */
  for (PetscInt r = 0; r < d->nd; r++) {
    if (r / ndof < ng && r % ndof == th) continue;
    R[r] += beta * Rd[r];
    *power += beta * Rd[r] * uv[r];
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* One element's internal forces and heat flow, and its bulk viscosity and damping forces added to them, into fi (one
 * gather of the element's data per increment and one scatter), by the generic kernels. */
static PetscErrorCode ForceElement(PetscInt e, TslElemData *d, ForceCtx *c, PetscBool *stop)
{
  PetscReal R[TSL_MAX_ELEM_DOF];
  PetscBool inverted = PETSC_FALSE;

  PetscFunctionBeginUser;
  if (d->in.pstate) { /* a plastic element: its work and heat over the move, and the state it reaches (pstate_new) */
    PetscReal en[4], qh[TSL_MAX_ELEM_NODES];
    if (c->qp) {
      const PetscInt ndof = d->nd / d->n, th = ndof - 1;
      PetscCall(TslElementInternalPlasticHeat(&d->in, R, &inverted, en, qh)); /* its heat apart: c->qp */
      for (PetscInt a = 0; a < d->n && !inverted; a++) c->qp[d->ld[a * ndof + th]] += qh[a];
    } else PetscCall(TslElementInternalEnergy(&d->in, R, NULL, &inverted, en));
    c->heat->plastic_work += en[2], c->heat->plastic_heat += en[3];
  } else
    PetscCall(TslElementInternal(&d->in, R, NULL, &inverted));
  if (inverted) {
    c->bad = e;
    *stop  = PETSC_TRUE;
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  if (c->q && c->v && (c->eta[e] > 0 || c->eta2[e] > 0)) {
    PetscReal v[TSL_MAX_ELEM_DOF], w, qr[2];
    for (PetscInt r = 0; r < d->nd; r++) v[r] = PetscRealPart(c->v[d->ld[r]]);
    PetscCall(TslElementBulkViscosity(&d->in, v, c->eta[e], c->eta2[e], R, &w, qr)); /* added to R */
    c->power += w, c->prev += c->q[e] * qr[1], c->q[e] = qr[0];
  }
  if (c->damped && d->in.sec->mat->damp_beta > 0) {
    PetscReal w = 0;
    PetscCall(DampingElement(d, c->v, d->in.sec->mat->damp_beta, d->nd / d->n, R, &w));
    c->power += w, c->prev += w; /* its work over an increment: the trapezoid of the two evaluations' power (explicit.c) */
  }
  for (PetscInt r = 0; r < d->nd; r++) c->fi[d->ld[r]] += R[r];
  PetscFunctionReturn(PETSC_SUCCESS);
}

#define W TSL_FAST_LANES

/* The elements of batch b's lanes: e[j] (an empty lane computes lane 0's element again), used[j] whether
 * lane j is an element of its own (scattered). */
static inline void BatchElements(TslProblem p, PetscInt b, PetscInt e[W], PetscBool used[W])
{
  for (PetscInt j = 0; j < W; j++) {
    const PetscInt ej = p->fast_batch[W * b + j];
    e[j] = ej >= 0 ? ej : p->fast_batch[W * b], used[j] = ej >= 0 ? PETSC_TRUE : PETSC_FALSE;
  }
}

/* The local nodes of the batch's lanes' elements (ln[j] for lane j); returns the nodes per element. */
static inline PetscInt BatchNodes(TslProblem p, const PetscInt e[W], const PetscInt *ln[W])
{
  for (PetscInt j = 0; j < W; j++) ln[j] = &p->elem_lnode[p->m->elem_ptr[e[j]]];
  return p->m->elem_ptr[e[0] + 1] - p->m->elem_ptr[e[0]];
}

/* The batch's unknowns from the local form xa, nd unknowns per node (a constant where inlined), interleaved by
 * lane as TslElementFastForceBatch takes them: with four unknowns per node each node's four rows are loaded
 * whole and transposed (lanes.h). Returns the initial temperatures to pass with them (ti not NULL): ti, gathered,
 * or, on a rank whose nodes all start at one temperature, fast_ti, that constant (no gather). */
static inline __attribute__((always_inline)) const PetscReal *GatherBatch(TslProblem p, const PetscInt e[W], const PetscScalar *restrict xa,
                                                                          PetscReal u[], PetscReal ti[], const PetscInt nd)
{
  const PetscInt *ln[W];
  const PetscInt  n = BatchNodes(p, e, ln);

  for (PetscInt a = 0; a < n; a++) {
#if defined(TSL_HAVE_TRANSPOSE4)
    if (nd == 4) {
      const TslV r0 = TslLd(&xa[4 * ln[0][a]]), r1 = TslLd(&xa[4 * ln[1][a]]), r2 = TslLd(&xa[4 * ln[2][a]]), r3 = TslLd(&xa[4 * ln[3][a]]);
      TSL_TRANSPOSE4(r0, r1, r2, r3, c0, c1, c2, c3);
      TslStA(&u[(4 * a + 0) * W], c0), TslStA(&u[(4 * a + 1) * W], c1), TslStA(&u[(4 * a + 2) * W], c2), TslStA(&u[(4 * a + 3) * W], c3);
    } else
#endif
      for (PetscInt j = 0; j < W; j++)
        for (PetscInt i = 0; i < nd; i++) u[(nd * a + i) * W + j] = PetscRealPart(xa[nd * ln[j][a] + i]);
    if (ti && !p->fast_ti_uniform)
      for (PetscInt j = 0; j < W; j++) ti[a * W + j] = p->theta_init[ln[j][a]];
  }
  return ti && p->fast_ti_uniform ? p->fast_ti : ti;
}

/* The used lanes' results added into their elements' rows of f (in lane order: lanes may share a node). */
static inline __attribute__((always_inline)) void ScatterBatch(TslProblem p, const PetscInt e[W], const PetscBool used[W], const PetscReal R[],
                                                               PetscScalar *restrict f, const PetscInt nd)
{
  const PetscInt *ln[W];
  const PetscInt  n = BatchNodes(p, e, ln);

  for (PetscInt a = 0; a < n; a++) {
#if defined(TSL_HAVE_TRANSPOSE4)
    if (nd == 4) {
      const TslV c0 = TslLdA(&R[(4 * a + 0) * W]), c1 = TslLdA(&R[(4 * a + 1) * W]), c2 = TslLdA(&R[(4 * a + 2) * W]),
                 c3 = TslLdA(&R[(4 * a + 3) * W]);
      TSL_TRANSPOSE4(c0, c1, c2, c3, r0, r1, r2, r3);
      /* in lane order (lanes may share a node) */
      if (used[0]) TslSt(&f[4 * ln[0][a]], TslLd(&f[4 * ln[0][a]]) + r0);
      if (used[1]) TslSt(&f[4 * ln[1][a]], TslLd(&f[4 * ln[1][a]]) + r1);
      if (used[2]) TslSt(&f[4 * ln[2][a]], TslLd(&f[4 * ln[2][a]]) + r2);
      if (used[3]) TslSt(&f[4 * ln[3][a]], TslLd(&f[4 * ln[3][a]]) + r3);
      continue;
    }
#endif
    for (PetscInt j = 0; j < W; j++)
      if (used[j])
        for (PetscInt i = 0; i < nd; i++) f[nd * ln[j][a] + i] += R[(nd * a + i) * W + j];
  }
}

void TslProblemFastBatchEnergy(TslProblem p, PetscInt b, const PetscScalar *xa, PetscReal *strain, PetscReal *hourglass)
{
  PetscReal u[TSL_MAX_ELEM_DOF * W] TSL_LANES_ALIGNED, ti[TSL_FAST_MAX_NODES * W], se[W], hg[W];
  const PetscReal *tib;
  PetscInt         e[W];
  PetscBool        used[W];

  BatchElements(p, b, e, used);
  tib = GatherBatch(p, e, xa, u, ti, p->ndof);
  TslElementFastEnergyBatch(&p->fast_shape[p->m->elem_type[e[0]]], p->nlgeom, &p->fast_rec[p->fast_boff[b]], u, tib, se, hg);
  *strain = *hourglass = 0;
  for (PetscInt j = 0; j < W; j++)
    if (used[j]) *strain += se[j], *hourglass += hg[j];
}

/* One batch's forces from its records (TslElementFastForceBatch): a gather of the unknowns alone, no
 * geometry. Inlined with the dofs per node a constant (FastBatch3, FastBatch4, each cloned for AVX2), so a
 * node's unknowns move as one short copy rather than a loop of run-time length. */
static inline __attribute__((always_inline)) void FastBatchNd(TslProblem p, PetscInt b, const PetscScalar *restrict xa, ForceCtx *c, const PetscInt nd)
{
  const TslElementFastShape *sh;
  /* the batch's arrays aligned to a vector: the gather's and scatter's transposes move whole vectors */
  PetscReal u[TSL_MAX_ELEM_DOF * W] TSL_LANES_ALIGNED, v[TSL_MAX_ELEM_DOF * W] TSL_LANES_ALIGNED, ti[TSL_FAST_MAX_NODES * W] TSL_LANES_ALIGNED,
      R[TSL_MAX_ELEM_DOF * W] TSL_LANES_ALIGNED, eta[W], eta2[W], w[W], qr[2 * W];
  const PetscReal *tib;
  PetscInt         e[W];
  PetscBool        used[W], visc[W], bv = PETSC_FALSE;
  int              inv;

  BatchElements(p, b, e, used);
  sh = &p->fast_shape[p->m->elem_type[e[0]]];
  tib = GatherBatch(p, e, xa, u, ti, nd);
  for (PetscInt j = 0; j < W; j++) {
    eta[j] = c->q ? c->eta[e[j]] : 0, eta2[j] = c->q ? c->eta2[e[j]] : 0;
    visc[j] = used[j] && (eta[j] > 0 || eta2[j] > 0) ? PETSC_TRUE : PETSC_FALSE;
    if (visc[j]) bv = PETSC_TRUE;
  }
  PetscReal beta[W];
  PetscBool damp = PETSC_FALSE;
  for (PetscInt j = 0; j < W; j++) {
    beta[j] = c->damped && used[j] ? p->esec[e[j]].mat->damp_beta : 0;
    if (beta[j] > 0) damp = PETSC_TRUE;
  }
  if ((bv && c->hinv == 0) || damp) GatherBatch(p, e, c->v, v, NULL, nd);
  if (b + 1 < p->fast_nbatch) { /* the next batch: its records past the caches (non-temporal), its nodal rows into them */
    const PetscReal *next = &p->fast_rec[p->fast_boff[b + 1]],
                    *end  = b + 2 < p->fast_nbatch ? &p->fast_rec[p->fast_boff[b + 2]] : p->fast_rec + p->fast_total;
    const PetscInt nrec   = (PetscInt)(end - next); /* the next batch's reals, whatever its type */
    for (PetscInt k = 0; k < nrec; k += 8) __builtin_prefetch(next + k, 0, 0);
    for (PetscInt j = 0; j < W; j++) {
      const PetscInt en = p->fast_batch[W * (b + 1) + j], k0 = en >= 0 ? p->m->elem_ptr[en] : 0, n = en >= 0 ? p->m->elem_ptr[en + 1] - k0 : 0;
      for (PetscInt a = 0; a < n; a++) {
        const PetscInt l = p->elem_lnode[k0 + a];
        __builtin_prefetch(&xa[nd * l], 0, 3);
        __builtin_prefetch(&c->fi[nd * l], 1, 3);
        if (!p->fast_ti_uniform) __builtin_prefetch(&p->theta_init[l], 0, 3);
      }
    }
  }
  /* the viscous forces added to the internal ones in R (Rv = R; zero in lanes without viscosity): one scatter */
  inv = TslElementFastForceBatch(sh, p->nlgeom, &p->fast_rec[p->fast_boff[b]], u, tib, bv && c->hinv == 0 ? v : NULL, bv ? &p->fast_ev[W * b] : NULL,
                                 c->hinv, eta, eta2, R, bv ? R : NULL, w, bv ? qr : NULL);
  for (PetscInt j = 0; j < W; j++) /* finite strain: an element turned inside out, agreed on with the rates (TslProblemExplicitForces) */
    if (used[j] && (inv & (1 << j)) && c->bad < 0) c->bad = e[j];
  if (bv) {
    for (PetscInt j = 0; j < W; j++)
      if (visc[j]) c->power += w[j], c->prev += c->q[e[j]] * qr[W + j], c->q[e[j]] = qr[j];
  }
  if (damp) { /* *DAMPING, BETA: the records' elastic forces at u = v, the temperatures their own reference (DampingElement) */
    PetscReal uv[TSL_MAX_ELEM_DOF * W] TSL_LANES_ALIGNED, tv[TSL_FAST_MAX_NODES * W] TSL_LANES_ALIGNED, Rd[TSL_MAX_ELEM_DOF * W] TSL_LANES_ALIGNED,
        zero[W] = {0}, wd[W];
    const PetscInt *ln[W];
    const PetscInt  n = BatchNodes(p, e, ln);
    for (PetscInt a = 0; a < n; a++)
      for (PetscInt j = 0; j < W; j++) {
        for (PetscInt i = 0; i < nd - 1; i++) uv[(nd * a + i) * W + j] = v[(nd * a + i) * W + j];
        uv[(nd * a + nd - 1) * W + j] = tv[a * W + j] = u[(nd * a + nd - 1) * W + j];
      }
    (void)TslElementFastForceBatch(sh, PETSC_FALSE, &p->fast_rec[p->fast_boff[b]], uv, tv, NULL, NULL, 0, zero, zero, Rd, NULL, wd, NULL);
    for (PetscInt j = 0; j < W; j++) {
      PetscReal pw = 0;
      if (beta[j] == 0) continue;
      for (PetscInt a = 0; a < n; a++)
        for (PetscInt i = 0; i < nd - 1; i++) {
          const PetscInt k = (nd * a + i) * W + j;
          R[k] += beta[j] * Rd[k];
          pw += beta[j] * Rd[k] * uv[k];
        }
      c->power += pw, c->prev += pw;
    }
  }
  ScatterBatch(p, e, used, R, c->fi, nd);
}
TSL_CLONES static void FastBatch3(TslProblem p, PetscInt b, const PetscScalar *xa, ForceCtx *c) { FastBatchNd(p, b, xa, c, 3); }
TSL_CLONES static void FastBatch4(TslProblem p, PetscInt b, const PetscScalar *xa, ForceCtx *c) { FastBatchNd(p, b, xa, c, 4); }
static void            FastBatch(TslProblem p, PetscInt b, const PetscScalar *xa, ForceCtx *c)
{
  if (p->ndof == 4) FastBatch4(p, b, xa, c);
  else if (p->ndof == 3) FastBatch3(p, b, xa, c);
  else FastBatchNd(p, b, xa, c, p->ndof);
}

/* The face loads' integrals of the elements with a record (problem_impl.h, fcache): formed once per edit of
 * the face list by the generic kernels themselves at unit values (body forces: R_u = -int N_a rho b dV on the
 * reference configuration at the initial temperature; pressure: R_u = int N_a n dA; flux: R_theta =
 * -int N_a dA, heat = area; film: its tangent int N_a N_b dA, whose rows sum to int N_a dA, as the shape
 * functions sum to one), so FaceLoadsCached gives the generic results to rounding. Radiation, not linear in the
 * temperature, has no integrals here: its elements take the generic path. */
static PetscErrorCode FaceCache(TslProblem p, const PetscScalar *xa)
{
  const PetscInt dim = p->dim, nd = p->ndof, th = nd - 1;
  PetscInt       total = 0;
  PetscReal     *K;
  TslElemData    d;

  PetscFunctionBeginUser;
  PetscCall(PetscFree(p->fcache_off));
  PetscCall(PetscFree(p->fcache));
  PetscCall(PetscMalloc1(p->nface + 1, &p->fcache_off));
  for (PetscInt e = 0; e < p->m->nelem; e++) { /* the offsets: they need the face's node count only */
    const TslGeometry *g = TslElementTypeGet(p->m->elem_type[e])->geom;
    for (PetscInt i = p->face_start[e]; i < p->face_start[e + 1]; i++) {
      const TslFaceLoadKind k    = p->face[i].kind;
      const PetscInt        fn   = p->face[i].face < 1 ? 0 : g->face_nnode[p->face[i].face - 1]; /* body loads: face 0 */
      const PetscInt        size = !(p->fast_off && p->fast_off[e] >= 0) ? 0
                                   : k == TSL_FACE_PRESSURE              ? fn * dim
                                   : k == TSL_FACE_FLUX                  ? fn + 1
                                   : k == TSL_FACE_FILM                  ? fn * fn + fn + 1
                                   : TslFaceLoadKindIsBodyForce(k)       ? g->nnode * dim
                                                                         : 0;
      p->fcache_off[i]           = size ? total : -1;
      total += size;
    }
  }
  PetscCall(PetscMalloc1(total + 1, &p->fcache));
  PetscCall(PetscMalloc1(TSL_MAX_ELEM_DOF * TSL_MAX_ELEM_DOF, &K));
  for (PetscInt e = 0; e < p->m->nelem; e++) { /* the integrals */
    const TslGeometry *g;
    if (p->face_start[e] == p->face_start[e + 1] || !(p->fast_off && p->fast_off[e] >= 0)) continue;
    TslProblemGather(p, e, xa, xa, &d);
    g = d.in.type->geom;
    for (PetscInt i = p->face_start[e]; i < p->face_start[e + 1]; i++) {
      const TslFaceRecord *rec = &p->face[i];
      PetscReal            R[TSL_MAX_ELEM_DOF], heat = 0, *c;
      PetscInt             fn;
      const PetscInt      *fnode;
      if (p->fcache_off[i] < 0) continue;
      c = &p->fcache[p->fcache_off[i]];
      if (TslFaceLoadKindIsBodyForce(rec->kind)) { /* R_u = -int N_a rho b dV at unit magnitude (the load is linear in it) */
        PetscCall(PetscArrayzero(R, d.nd));
        PetscCall(TslElementBodyForce(&d.in, rec->kind, 1.0, rec->axis, R, NULL));
        for (PetscInt a = 0; a < g->nnode; a++)
          for (PetscInt k = 0; k < dim; k++) c[a * dim + k] = R[nd * a + k];
        continue;
      }
      fn = g->face_nnode[rec->face - 1], fnode = g->face_node[rec->face - 1];
      PetscCall(PetscArrayzero(R, d.nd));
      if (rec->kind == TSL_FACE_FILM) PetscCall(PetscArrayzero(K, d.nd * d.nd));
      PetscCall(TslElementFaceLoad(&d.in, rec->kind, rec->face, &(TslFaceLoadValue){1.0, 0.0, 0.0}, R, rec->kind == TSL_FACE_FILM ? K : NULL, &heat));
      if (rec->kind == TSL_FACE_PRESSURE)
        for (PetscInt f = 0; f < fn; f++)
          for (PetscInt k = 0; k < dim; k++) c[f * dim + k] = R[nd * fnode[f] + k];
      else if (rec->kind == TSL_FACE_FLUX) {
        for (PetscInt f = 0; f < fn; f++) c[f] = -R[nd * fnode[f] + th];
        c[fn] = heat;
      } else { /* film: M_fg, then m_f = sum_g M_fg, then the area */
        c[fn * fn + fn] = 0;
        for (PetscInt f = 0; f < fn; f++) {
          c[fn * fn + f] = 0;
          for (PetscInt gg = 0; gg < fn; gg++) {
            c[f * fn + gg] = K[(nd * fnode[f] + th) * d.nd + nd * fnode[gg] + th];
            c[fn * fn + f] += c[f * fn + gg];
          }
          c[fn * fn + fn] += c[fn * fn + f];
        }
      }
    }
  }
  PetscCall(PetscFree(K));
  p->fcache_gen = p->face_gen;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Element e's face loads from the cache, when it has every one of them there: no gather of the element, only
 * its face nodes' temperatures for a film. Returns *done = false otherwise. */
static PetscErrorCode FaceLoadsCached(TslProblem p, PetscInt e, const PetscScalar *xa, ForceCtx *c, PetscBool *done)
{
  const TslGeometry *g  = TslElementTypeGet(p->m->elem_type[e])->geom;
  const PetscInt    *ln = &p->elem_lnode[p->m->elem_ptr[e]], nd = p->ndof, th = nd - 1, dim = p->dim;

  PetscFunctionBeginUser;
  *done = PETSC_FALSE;
  for (PetscInt i = p->face_start[e]; i < p->face_start[e + 1]; i++) /* finite strain: a pressure follows the deformed face (generic) */
    if (p->fcache_off[i] < 0 || (p->nlgeom && p->face[i].kind == TSL_FACE_PRESSURE)) PetscFunctionReturn(PETSC_SUCCESS);
  for (PetscInt i = p->face_start[e]; i < p->face_start[e + 1]; i++) {
    const TslFaceRecord *rec = &p->face[i];
    const PetscInt       fn = rec->face < 1 ? 0 : g->face_nnode[rec->face - 1], *fnode = rec->face < 1 ? NULL : g->face_node[rec->face - 1];
    const PetscReal     *C = &p->fcache[p->fcache_off[i]];
    TslFaceLoadValue     v;
    PetscReal            value, sink;
    PetscCall(TslProblemFaceLoadValue(p, rec, &v));
    value = v.value, sink = v.sink;
    if (TslFaceLoadKindIsBodyForce(rec->kind))
      for (PetscInt a = 0; a < g->nnode; a++)
        for (PetscInt k = 0; k < dim; k++) c->fe[nd * ln[a] + k] -= value * C[a * dim + k];
    else if (rec->kind == TSL_FACE_PRESSURE)
      for (PetscInt f = 0; f < fn; f++)
        for (PetscInt k = 0; k < dim; k++) c->fe[nd * ln[fnode[f]] + k] -= value * C[f * dim + k];
    else if (rec->kind == TSL_FACE_FLUX) {
      for (PetscInt f = 0; f < fn; f++) c->fi[nd * ln[fnode[f]] + th] -= value * C[f];
      c->heat->flux_in += value * C[fn];
    } else {
      PetscReal t[TSL_MAX_ELEM_NODES], mt = 0;
      for (PetscInt f = 0; f < fn; f++) t[f] = PetscRealPart(xa[nd * ln[fnode[f]] + th]);
      for (PetscInt f = 0; f < fn; f++) {
        PetscReal Mt = 0;
        for (PetscInt gg = 0; gg < fn; gg++) Mt += C[f * fn + gg] * t[gg];
        c->fi[nd * ln[fnode[f]] + th] += value * (Mt - sink * C[fn * fn + f]);
        mt += C[fn * fn + f] * t[f];
      }
      c->heat->film -= value * (mt - sink * C[fn * fn + fn]);
    }
  }
  *done = PETSC_TRUE;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The element pass of an explicit force evaluation: the record batches, then the generic kernels on the
 * elements without a record; face loads (a gather) only on elements that carry them, from the cache where
 * the element has a record and its loads have integrals there. */
static PetscErrorCode ForcePass(TslProblem p, const PetscScalar *xa, ForceCtx *c)
{
  TslElemData d;

  PetscFunctionBeginUser;
  if (p->fast_built && p->nface && (!p->fcache_off || p->fcache_gen != p->face_gen)) PetscCall(FaceCache(p, xa));
  for (PetscInt b = 0; p->fast_built && b < p->fast_nbatch; b++) FastBatch(p, b, xa, c);
  for (PetscInt e = 0; e < p->m->nelem; e++) {
    const PetscBool fast = p->fast_off && p->fast_off[e] >= 0 ? PETSC_TRUE : PETSC_FALSE;
    PetscBool       stop = PETSC_FALSE, done = PETSC_FALSE;
    if (fast && p->face_start[e] == p->face_start[e + 1]) continue;
    if (fast && p->fcache_off) PetscCall(FaceLoadsCached(p, e, xa, c, &done));
    if (done) continue;
    TslProblemGather(p, e, xa, xa, &d);
    if (!fast) PetscCall(ForceElement(e, &d, c, &stop));
    if (stop) break;
    PetscCall(FaceLoads(p, e, &d, c));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode ElemCacheDestroy(struct TslElemCache **c);

PetscErrorCode TslProblemFastDestroy(TslProblem p)
{
  PetscFunctionBeginUser;
  PetscCall(ElemCacheDestroy(&p->elem_cache));
  PetscCall(PetscFree(p->stable_shape));
  PetscCall(PetscFree2(p->fast_shape, p->fast_off));
  PetscCall(PetscFree(p->fast_rec));
  PetscCall(PetscFree(p->fast_ev));
  PetscCall(PetscFree2(p->fast_batch, p->fast_boff));
  PetscCall(PetscFree(p->fcache_off));
  PetscCall(PetscFree(p->fcache));
  p->fast_built = PETSC_FALSE, p->fast_count = p->fast_total = p->fast_nbatch = 0;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TslProblemImplicitRecords(TslProblem p, PetscBool use, PetscInt *nfast, PetscReal *mbytes)
{
  PetscFunctionBeginUser;
  p->fast_implicit = use;
  if (use) PetscCall(TslProblemExplicitRecords(p, PETSC_TRUE, nfast, mbytes));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode StableShapesCreate(TslProblem p)
{
  PetscFunctionBeginUser;
  if (p->nlgeom && !p->stable_shape) { /* no shape seen yet: every element evaluated at the first call */
    PetscCall(PetscMalloc1(TSL_STABLE_SHAPE * p->m->nelem, &p->stable_shape));
    for (PetscInt k = 0; k < TSL_STABLE_SHAPE * p->m->nelem; k++) p->stable_shape[k] = PETSC_MAX_REAL;
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TslProblemStableShapes(TslProblem p, PetscReal **shape)
{
  PetscFunctionBeginUser;
  PetscCall(StableShapesCreate(p));
  *shape = p->nlgeom ? p->stable_shape : NULL;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TslProblemExplicitCarried(TslProblem p, PetscReal **ev, PetscInt *n, const PetscInt **lane)
{
  PetscFunctionBeginUser;
  *ev = p->fast_built ? p->fast_ev : NULL;
  *n  = p->fast_built ? W * p->fast_nbatch : 0;
  if (lane) *lane = p->fast_built ? p->fast_off : NULL;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Records are built in element order into batches of one type each (an open batch per type), so a batch's
 * elements are near one another in the mesh and successive batches walk it as the element order does. */
PetscErrorCode TslProblemExplicitRecords(TslProblem p, PetscBool use, PetscInt *nfast, PetscReal *mbytes)
{
  const PetscInt nelem = p->m->nelem, ntype = TslElementTypeCount();
  PetscReal      mb;
  TslElemData    d;

  PetscFunctionBeginUser;
  if (!use) PetscCall(TslProblemFastDestroy(p));
  if (use && !p->fast_built) { /* the records hold for the whole job: the geometry and the materials do not change */
    PetscInt *count, *open, *lanes, total = 0, maxbatch = 0;
    PetscReal rec[TSL_FAST_MAX_SIZE];
    PetscCall(PetscCalloc3(ntype, &count, ntype, &open, ntype, &lanes));
    PetscCall(PetscMalloc2(ntype, &p->fast_shape, nelem, &p->fast_off));
    for (PetscInt t = 0; t < ntype; t++) (void)TslElementFastShapeGet(TslElementTypeGet(t), &p->fast_shape[t]);
    for (PetscInt e = 0; e < nelem; e++) { /* which elements may have a record: an upper bound of the storage */
      const PetscInt t = p->m->elem_type[e];
      TslProblemGather(p, e, NULL, NULL, &d);
      p->fast_off[e] = d.in.type->ndof == p->ndof && TslElementFastSize(&d.in) > 0 ? 0 : -1;
      if (p->fast_off[e] == 0) count[t]++;
    }
    for (PetscInt t = 0; t < ntype; t++) {
      const PetscInt nb = (count[t] + W - 1) / W;
      total += nb * W * p->fast_shape[t].size, maxbatch += nb;
    }
    PetscCall(PetscMalloc1(total, &p->fast_rec));
    TslPrefault(p->fast_rec, sizeof(*p->fast_rec) * (size_t)total);
    PetscCall(PetscMalloc2(W * maxbatch, &p->fast_batch, maxbatch, &p->fast_boff));
    PetscCall(PetscCalloc1(W * maxbatch, &p->fast_ev));
    for (PetscInt t = 0; t < ntype; t++) open[t] = -1;
    for (PetscInt e = 0; e < nelem; e++) {
      const PetscInt t = p->m->elem_type[e];
      PetscInt       b;
      if (p->fast_off[e] < 0) continue;
      p->fast_off[e] = -1;
      TslProblemGather(p, e, NULL, NULL, &d);
      if (!TslElementFastBuild(&d.in, rec)) continue; /* inverted: the generic kernel reports it */
      if (open[t] < 0) { /* a new batch: every lane empty until filled */
        b = open[t] = p->fast_nbatch++, lanes[t] = 0;
        p->fast_boff[b] = p->fast_total, p->fast_total += W * p->fast_shape[t].size;
        for (PetscInt j = 0; j < W; j++) p->fast_batch[W * b + j] = -1;
      }
      b = open[t];
      TslElementFastInterleave(p->fast_shape[t].size, lanes[t], rec, &p->fast_rec[p->fast_boff[b]]);
      p->fast_batch[W * b + lanes[t]] = e, p->fast_off[e] = W * b + lanes[t], p->fast_count++;
      if (++lanes[t] == W) open[t] = -1;
    }
    for (PetscInt b = 0; b < p->fast_nbatch; b++) /* empty lanes: lane 0's record again (finite, never scattered) */
      for (PetscInt j = 1; j < W; j++)
        if (p->fast_batch[W * b + j] < 0) {
          const PetscInt size = p->fast_shape[p->m->elem_type[p->fast_batch[W * b]]].size;
          PetscReal     *r    = &p->fast_rec[p->fast_boff[b]];
          for (PetscInt k = 0; k < size; k++) r[k * W + j] = r[k * W];
        }
    PetscCall(PetscFree3(count, open, lanes));
    p->fast_built = PETSC_TRUE;
    p->fast_all   = (PetscBool)(p->fast_count == nelem);
    p->fast_ti_uniform = PETSC_TRUE; /* the deck's one initial temperature (or none): no gather of it per batch */
    for (PetscInt n = 1; n < p->nn && p->fast_ti_uniform; n++) p->fast_ti_uniform = (PetscBool)(p->theta_init[n] == p->theta_init[0]);
    for (PetscInt k = 0; k < TSL_FAST_MAX_NODES * W; k++) p->fast_ti[k] = p->nn ? p->theta_init[0] : 0;
    PetscCall(MPIU_Allreduce(MPI_IN_PLACE, &p->fast_all, 1, MPIU_BOOL, MPI_LAND, p->comm));
  }
  if (nfast) PetscCall(MPIU_Allreduce(&p->fast_count, nfast, 1, MPIU_INT, MPI_SUM, p->comm));
  mb = p->fast_total * sizeof(PetscReal) / 1048576.0;
  if (mbytes) PetscCall(MPIU_Allreduce(&mb, mbytes, 1, MPIU_REAL, MPI_MAX, p->comm));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Local form of a ghosted vector, zeroed, and its array. */
static PetscErrorCode BeginLocal(Vec V, Vec *vl, PetscScalar **a)
{
  PetscFunctionBeginUser;
  *a = NULL;
  if (!V) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(VecGhostGetLocalForm(V, vl));
  PetscCall(VecZeroEntries(*vl));
  PetscCall(VecGetArray(*vl, a));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Restores the local form and adds the ghosts' contributions to their owners (one vector at a time:
 * duplicated ghosted vectors share their scatter). */
static PetscErrorCode EndLocal(Vec V, Vec *vl, PetscScalar **a)
{
  PetscFunctionBeginUser;
  if (!V) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(VecRestoreArray(*vl, a));
  PetscCall(VecGhostRestoreLocalForm(V, vl));
  PetscCall(TslGhostUpdate(V, ADD_VALUES, SCATTER_REVERSE));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode InjectedInternal(void)
{
  PetscFunctionBeginUser;
  SETERRQ(PETSC_COMM_SELF, PETSC_ERR_PLIB, "injected internal failure (-tsl_debug_fail_kind)");
}

PetscErrorCode TslProblemExplicitForces(TslProblem p, Vec Fi, Vec Fe, Vec Fc, Vec Qp, Vec V, const PetscReal eta[], const PetscReal eta2[], PetscReal q[],
                                        PetscReal h, TslExplicitRates *rates)
{
  Vec                xl, il, el, cl = NULL, vl = NULL, ql = NULL;
  const PetscScalar *xa;
  PetscScalar       *fc;
  AsmHeat            heat;
  ForceCtx           c = {NULL, NULL, NULL, NULL, eta, eta2, q, 0, 0, PETSC_FALSE, 0, &heat, -1};
  /* with records on every element and a central-difference move since the last evaluation, the rate of the
   * bulk viscosity comes from the records' centre strains: v is neither exchanged nor gathered */
  const PetscBool    from_u = (PetscBool)(q && h > 0 && p->fast_built && p->fast_all && !p->nlgeom); /* finite strain: J'/J from v */
  PetscReal          loc[12], g[12];
  TslFailure         fail;
  PetscErrorCode     ierr;

  PetscFunctionBeginUser;
  PetscCall(PetscMemzero(&heat, sizeof(heat)));
  if (from_u) c.hinv = 1 / h;
  for (PetscInt k = 0; k < p->m->nmaterial; k++)
    if (p->m->materials[k].damp_beta > 0) c.damped = PETSC_TRUE; /* the same on every rank: the model's materials */
  if ((q && !from_u) || c.damped) {
    PetscCall(TslGhostUpdate(V, INSERT_VALUES, SCATTER_FORWARD));
    PetscCall(VecGhostGetLocalForm(V, &vl));
    PetscCall(VecGetArrayRead(vl, &c.v));
  }
  /* the state's own local form (no copy into the problem's work vector: the state is read only), its ghosts
   * current: the explicit procedure applies the prescribed values last whenever it has moved the state (at the
   * step's start and at the end of each increment), and that updates them, so no scatter here */
  PetscCall(VecGhostGetLocalForm(p->X, &xl));
  PetscCall(VecGetArrayRead(xl, &xa));
  PetscCall(BeginLocal(Fi, &il, &c.fi));
  PetscCall(BeginLocal(Fe, &el, &c.fe));
  PetscCall(BeginLocal(p->ncsurf ? Fc : NULL, &cl, &fc));
  PetscCall(BeginLocal(Qp, &ql, &c.qp));
  /* the plastic state: each evaluation returns from the committed one and commits what it reaches (an explicit
   * state is evaluated once; a second evaluation of the same state flows no further), its heat a rate over the
   * move's increment h, deposited over the next one as the friction heat is (0 for a step's first evaluation) */
  p->pstate_write   = p->pstate ? PETSC_TRUE : PETSC_FALSE;
  p->inelastic_rate = h > 0 ? 1 / h : 0;
  PetscCall(ForcePass(p, xa, &c));
  p->pstate_write = PETSC_FALSE;
  if (p->pstate) PetscCall(TslProblemCommitState(p));
  /* a contact projection that fails has no cutback to fall back on here: an error on all ranks (as is a
   * failure injected on one rank for the tests, -tsl_debug_fail_kind internal) */
  PetscCall(TslCaptureBegin());
  ierr = fc ? TslProblemContactAssemble(p, ASM_RAW, xa, fc, NULL, &heat) : PETSC_SUCCESS;
  if (!ierr && TslInjectNow(&p->inject, TSL_INJECT_INTERNAL, p->step + 1)) ierr = InjectedInternal();
  PetscCall(TslCaptureEnd());
  /* a failure here (or an inverted element above) is agreed on after the ghost sums below, by a flag in the rates'
   * reduction: the failing rank takes part in them as usual, and an increment without a failure costs no reduction of
   * its own for either (TslAgree and TslProblemCheckBadElement run when the flags say so, on every rank) */
  for (PetscInt i = 0; i < p->nnload_own; i++) { /* nodal loads, owned dofs */
    const PetscInt  dof = p->nload_own[i];
    const PetscReal v   = TslProblemEvalLoadValue(p, &p->nload[dof]);
    if (dof % p->ndof == p->ndof - 1)
      c.fi[dof] -= v, heat.flux_in += v;
    else
      c.fe[dof] += v;
  }
  PetscCall(EndLocal(Qp, &ql, &c.qp));
  PetscCall(EndLocal(p->ncsurf ? Fc : NULL, &cl, &fc));
  PetscCall(EndLocal(Fe, &el, &c.fe));
  PetscCall(EndLocal(Fi, &il, &c.fi));
  PetscCall(VecRestoreArrayRead(xl, &xa));
  PetscCall(VecGhostRestoreLocalForm(p->X, &xl));
  if ((q && !from_u) || c.damped) {
    PetscCall(VecRestoreArrayRead(vl, &c.v));
    PetscCall(VecGhostRestoreLocalForm(V, &vl));
  }
  if (Fc && !p->ncsurf) PetscCall(VecZeroEntries(Fc));
  loc[0] = heat.flux_in, loc[1] = -heat.film, loc[2] = heat.interface, loc[3] = heat.dissipation, loc[4] = heat.friction_heat, loc[5] = c.power;
  loc[6] = c.prev, loc[7] = -heat.radiation, loc[8] = heat.plastic_work, loc[9] = heat.plastic_heat;
  loc[10] = ierr ? 1 : 0, loc[11] = c.bad >= 0 ? 1 : 0;
  PetscCall(MPIU_Allreduce(loc, g, 12, MPIU_REAL, MPIU_SUM, p->comm));
  if (g[10] > 0) {
    PetscCall(TslAgree(p->comm, ierr, &fail, p->fail_msg));
    PetscCheck(!fail, p->comm, PETSC_ERR_NOT_CONVERGED, "explicit increment: %s", p->fail_msg);
  }
  if (g[11] > 0 && p->nlgeom) { /* the reference geometry was checked before the job: the deformation turned it */
    PetscInt id = c.bad >= 0 ? p->m->elem_id[c.bad] : -1, gid;
    PetscCall(MPIU_Allreduce(&id, &gid, 1, MPIU_INT, MPI_MAX, p->comm));
    SETERRQ(p->comm, PETSC_ERR_NOT_CONVERGED,
            "explicit increment: element %" PetscInt_FMT " turned inside out (det F <= 0) at step time %g: the motion has crushed it, or the solution "
            "has left the stable range (an increment above the stable one); the frames written before are kept",
            gid, (double)p->t);
  }
  if (g[11] > 0) PetscCall(TslProblemCheckBadElement(p, c.bad));
  rates->heat_in = g[0], rates->film_out = g[1], rates->interface_heat = g[2], rates->dissipation = g[3], rates->friction_heat = g[4];
  rates->viscous = g[5], rates->viscous_prev = g[6], rates->radiation_out = g[7], rates->plastic_work = g[8], rates->plastic_heat = g[9];
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TslProblemElementDamping(TslProblem p, PetscReal alpha[], PetscReal beta[])
{
  PetscFunctionBeginUser;
  for (PetscInt e = 0; e < p->m->nelem; e++) alpha[e] = p->esec[e].mat->damp_alpha, beta[e] = p->esec[e].mat->damp_beta;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TslProblemExplicitKinematicForces(TslProblem p, Vec Fk, TslExplicitRates *rates)
{
  Vec                xl, kl;
  const PetscScalar *xa;
  PetscScalar       *fk;
  AsmHeat            heat;
  PetscReal          loc[4], g[4];
  TslFailure         fail;
  PetscErrorCode     ierr;

  PetscFunctionBeginUser;
  PetscCall(PetscMemzero(&heat, sizeof(heat)));
  /* the state's own local form: its ghosts are current (the corrector applied the prescribed values, which
   * updates them, and nothing moves between its evaluations), so no copy and no scatter of its own */
  PetscCall(VecGhostGetLocalForm(p->X, &xl));
  PetscCall(VecGetArrayRead(xl, &xa));
  PetscCall(BeginLocal(Fk, &kl, &fk));
  p->select_kinematic = PETSC_TRUE;
  PetscCall(TslCaptureBegin());
  ierr = TslProblemContactAssemble(p, ASM_RAW, xa, fk, NULL, &heat);
  PetscCall(TslCaptureEnd());
  p->select_kinematic = PETSC_FALSE;
  PetscCall(EndLocal(Fk, &kl, &fk)); /* a failure is agreed on after it, by a flag in the rates' reduction (as above) */
  PetscCall(VecRestoreArrayRead(xl, &xa));
  PetscCall(VecGhostRestoreLocalForm(p->X, &xl));
  loc[0] = heat.interface, loc[1] = heat.dissipation, loc[2] = heat.friction_heat, loc[3] = ierr ? 1 : 0;
  PetscCall(MPIU_Allreduce(loc, g, 4, MPIU_REAL, MPIU_SUM, p->comm));
  if (g[3] > 0) {
    PetscCall(TslAgree(p->comm, ierr, &fail, p->fail_msg));
    PetscCheck(!fail, p->comm, PETSC_ERR_NOT_CONVERGED, "explicit kinematic contact: %s", p->fail_msg);
  }
  PetscCall(PetscMemzero(rates, sizeof(*rates)));
  rates->interface_heat = g[0], rates->dissipation = g[1], rates->friction_heat = g[2];
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Element stable increments and lumped masses, computed once per distinct element.
 *
 * The element eigenvalue problems were most of an explicit step's set-up (128 000 C3D8T: 4.9 s against 6.3 s
 * for 100 increments), and *VARIABLE MASS SCALING repeats them, and the lumped masses, every FREQUENCY
 * increments. A mesh repeats its elements (a swept or structured mesh has a handful of distinct shapes), so
 * each rank keeps the increments and masses of the distinct elements it has met (TslElemCache, for the
 * problem's life) under a key of everything they depend on:
 * the type, the section's material and dimensions, which dofs are prescribed, the shape, and the nodal
 * temperatures where a property of the material depends on temperature. Displacements do not enter the
 * kinematics (small strain), nor does the position, except in an axisymmetric model (the radius) and for a
 * type with an extra node (the generalized plane strain's reference node, kept where it is).
 *
 * The shape is the nodes' positions relative to the first node on a grid of 2^-40 of the element's size (a
 * power of two L >= the extent of its shape's nodes: x_a - x_0 = q_a L 2^-40, q_a integers), so that copies of an element whose
 * coordinates differ by rounding share a key. Every element's increment and masses, cached or not, are
 * computed on that grid, and its eigenvalue raised by 1e-8: the results depend only on the element's own key
 * (the same on any number of ranks), and the grid moves a node by at most 1e-12 of the element's extent,
 * whose effect on the eigenvalue (about twice that over the element's smallest dimension) the 1e-8 covers for
 * elements up to 5 000 times longer than thick (and on a mass, at most that 1e-12). A material tabulated in
 * temperature puts the temperatures in the key, so that its elements rarely repeat: they are computed on
 * the grid without the cache. */
#define ELEM_CACHE_MAX   4096 /* distinct elements kept per rank (at most about 6 MB) */
#define ELEM_CACHE_SLOTS 8192 /* open addressing, a power of two */
#define STABLE_KEY_MAX   (8 + 3 + TSL_MAX_ELEM_DOF / 64 + 1 + 4 * TSL_MAX_ELEM_NODES)

typedef struct {
  PetscInt64 hash, off, len; /* len 0: an empty slot */
  PetscBool  has_dt, has_mass;
  PetscReal  dt_mech, dt_heat;
  PetscReal  M[TSL_MAX_ELEM_NODES], C[TSL_MAX_ELEM_NODES]; /* lumped mass and capacity per node */
} ElemEntry;

struct TslElemCache {
  PetscInt64 *pool; /* the keys, one after the other */
  PetscInt    npool, maxpool, n;
  PetscInt    hits[2]; /* stable increments, masses: from the cache since the last report */
  ElemEntry   slot[ELEM_CACHE_SLOTS];
};

static PetscErrorCode ElemCacheDestroy(struct TslElemCache **c)
{
  PetscFunctionBeginUser;
  if (*c) PetscCall(PetscFree((*c)->pool));
  PetscCall(PetscFree(*c));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscInt64 Bits(PetscReal v)
{
  PetscInt64 b;
  memcpy(&b, &v, sizeof(b));
  return b;
}

/* A property given as a table in temperature (more than one row) that the stable increment reads. */
static PetscBool TemperatureDependent(const TslMaterial *mat)
{
  if (!mat) return PETSC_FALSE;
  return (PetscBool)(mat->prop[TSL_PROP_ELASTIC].n > 1 || mat->prop[TSL_PROP_CONDUCTIVITY].n > 1 || mat->prop[TSL_PROP_DENSITY].n > 1 ||
                     mat->prop[TSL_PROP_SPECIFIC_HEAT].n > 1);
}

/* The element's key (TslElemCache) into key[] (returns its length; 0: no grid, for an element of no extent) and
 * the input the increments are computed on: the grid's coordinates in x[], no displacement and the nodal
 * temperatures (those of a temperature-dependent material, else zero) in u[] and ti[]. */
static PetscInt StableKey(TslProblem p, PetscInt e, const TslElemData *d, PetscInt64 key[], PetscReal x[], PetscReal u[], PetscReal ti[],
                          TslElementInput *in)
{
  const TslElementSection *sec = d->in.sec;
  const PetscInt           ng  = d->in.type->geom->nnode; /* the nodes of the shape; after them a type's extra (reference) nodes */
  /* the position itself: the radius of an axisymmetric model, and the frame of an extra node (its own, exact) */
  const PetscBool absolute = (PetscBool)(TslKinematicsRevolves(d->in.type->kin) || d->n > ng), tdep = TemperatureDependent(sec->mat);
  const PetscInt  th    = p->ndof - 1;
  PetscReal       lo[3] = {PETSC_MAX_REAL, PETSC_MAX_REAL, PETSC_MAX_REAL}, hi[3] = {-PETSC_MAX_REAL, -PETSC_MAX_REAL, -PETSC_MAX_REAL}, extent = 0;
  PetscInt        n = 0, ex;
  PetscReal       up, down;

  for (PetscInt a = 0; a < ng; a++)
    for (PetscInt c = 0; c < 3; c++) lo[c] = PetscMin(lo[c], d->x[3 * a + c]), hi[c] = PetscMax(hi[c], d->x[3 * a + c]);
  for (PetscInt c = 0; c < 3; c++) extent = PetscMax(extent, hi[c] - lo[c]);
  if (!(extent > 0) || extent >= PETSC_MAX_REAL) return 0;
  (void)frexp(extent, &ex); /* extent <= L = 2^ex */
  up       = ldexp(1.0, 40 - ex);
  down     = ldexp(1.0, ex - 40);
  key[n++] = p->m->elem_type[e];
  key[n++] = (PetscInt64)(uintptr_t)sec->mat;
  key[n++] = Bits(sec->thickness);
  key[n++] = sec->shell_points;
  key[n++] = Bits(sec->thickness_modulus);
  key[n++] = sec->shell_stack;
  key[n++] = ex;
  key[n++] = d->n;
  for (PetscInt c = 0; c < 3; c++) key[n++] = absolute ? Bits(d->x[c]) : 0;
  for (PetscInt w = 0; w * 64 < d->nd; w++) { /* the prescribed dofs, a bit each */
    PetscInt64 bits = 0;
    for (PetscInt r = w * 64; r < PetscMin(d->nd, (w + 1) * 64); r++)
      if (p->pinned[d->ld[r]]) bits |= (PetscInt64)1 << (r - w * 64);
    key[n++] = bits;
  }
  for (PetscInt a = 0; a < d->n; a++)
    for (PetscInt c = 0; c < 3; c++) {
      if (a >= ng) { /* an extra node: where it is */
        key[n++]     = Bits(d->x[3 * a + c]);
        x[3 * a + c] = d->x[3 * a + c];
        continue;
      }
      const PetscReal q = nearbyint((d->x[3 * a + c] - d->x[c]) * up); /* exact: a power-of-two scale */
      key[n++]          = (PetscInt64)q;
      x[3 * a + c]      = (absolute ? d->x[c] : 0) + q * down;
    }
  for (PetscInt a = 0; a < d->n; a++) {
    for (PetscInt i = 0; i < p->ndof; i++) u[a * p->ndof + i] = 0;
    if (tdep) {
      u[a * p->ndof + th] = d->u[a * p->ndof + th];
      key[n++]            = Bits(u[a * p->ndof + th]);
    }
    ti[a] = u[a * p->ndof + th]; /* no thermal strain: the increments do not depend on it */
  }
  *in            = d->in;
  in->x          = x;
  in->u          = u;
  in->theta_init = ti;
  /* elastic: a plastic element's increments and masses are its elastic ones (unloading is elastic, the elastic wave the
   * fastest); with its committed plastic strain against u = 0 the tangent was an elastoplastic one (a reverse flow),
   * and the increments up to 10 times too long once it had yielded (a blow-up of explicit_cps4t under NLGEOM) */
  in->pstate     = NULL;
  in->pstate_new = NULL;
  return n;
}

static PetscInt64 KeyHash(PetscInt n, const PetscInt64 key[])
{
  uint64_t h = 0x9e3779b97f4a7c15ULL;
  for (PetscInt i = 0; i < n; i++) {
    h ^= (uint64_t)key[i] + 0x9e3779b97f4a7c15ULL + (h << 6) + (h >> 2);
    h *= 0xbf58476d1ce4e5b9ULL;
  }
  return (PetscInt64)(h ^ (h >> 31));
}

/* The entry of key (n words) in p's cache: its own, a new one where there is room, or NULL (a material
 * tabulated in temperature, no extent, or the cache full). */
static PetscErrorCode ElemCacheEntry(TslProblem p, PetscInt n, const PetscInt64 key[], PetscBool tdep, ElemEntry **entry)
{
  struct TslElemCache *c;
  PetscInt64           h;

  PetscFunctionBeginUser;
  *entry = NULL;
  if (!n || tdep) PetscFunctionReturn(PETSC_SUCCESS);
  if (!p->elem_cache) PetscCall(PetscCalloc1(1, &p->elem_cache));
  c = p->elem_cache;
  h = KeyHash(n, key);
  for (PetscInt k = 0; k < ELEM_CACHE_SLOTS; k++) {
    ElemEntry *s = &c->slot[((uint64_t)h + (uint64_t)k) & (ELEM_CACHE_SLOTS - 1)];
    if (s->len == n && s->hash == h && !memcmp(&c->pool[s->off], key, (size_t)n * sizeof(PetscInt64))) {
      *entry = s;
      break;
    }
    if (s->len) continue;
    if (c->n >= ELEM_CACHE_MAX) break; /* full: computed as it comes */
    if (c->npool + n > c->maxpool) {
      PetscInt64 *pool;
      c->maxpool = PetscMax(2 * c->maxpool, c->npool + n + 1024);
      PetscCall(PetscMalloc1(c->maxpool, &pool));
      if (c->npool) PetscCall(PetscArraycpy(pool, c->pool, c->npool));
      PetscCall(PetscFree(c->pool));
      c->pool = pool;
    }
    PetscCall(PetscArraycpy(&c->pool[c->npool], key, n));
    s->hash = h, s->off = c->npool, s->len = n;
    c->npool += n;
    c->n++;
    *entry = s;
    break;
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The input an element's increments and masses are computed on (StableKey's grid), its key and its entry. */
typedef struct {
  PetscReal       x[TSL_MAX_ELEM_NODES * 3], u[TSL_MAX_ELEM_DOF], ti[TSL_MAX_ELEM_NODES];
  PetscInt64      key[STABLE_KEY_MAX];
  TslElementInput in;
  ElemEntry      *entry;
} ElemOnGrid;

static PetscErrorCode ElemGrid(TslProblem p, PetscInt e, const TslElemData *d, ElemOnGrid *g)
{
  PetscInt nkey;

  PetscFunctionBeginUser;
  nkey = StableKey(p, e, d, g->key, g->x, g->u, g->ti, &g->in);
  if (!nkey) g->in = d->in; /* an element of no extent: as it stands (it has no stable increment) */
  PetscCall(ElemCacheEntry(p, nkey, g->key, TemperatureDependent(d->in.sec->mat), &g->entry));
  PetscFunctionReturn(PETSC_SUCCESS);
}

typedef struct {
  PetscScalar     *m;
  const PetscReal *scale;
  PetscInt         bad;
} MassCtx;

static PetscErrorCode MassElement(TslProblem p, PetscInt e, TslElemData *d, void *ctx, PetscBool *stop)
{
  MassCtx         *c = (MassCtx *)ctx;
  PetscReal        Mv[TSL_MAX_ELEM_NODES], Cv[TSL_MAX_ELEM_NODES], s = c->scale ? c->scale[e] : 1.0;
  const PetscReal *M = Mv, *C = Cv;
  PetscInt         th = p->ndof - 1;
  ElemOnGrid       g;

  PetscFunctionBeginUser;
  PetscCall(ElemGrid(p, e, d, &g));
  if (g.entry && g.entry->has_mass) {
    M = g.entry->M, C = g.entry->C;
    p->elem_cache->hits[1]++;
  } else {
    PetscCall(TslElementLumped(&g.in, NULL, Cv, Mv));
    if (g.entry) {
      PetscCall(PetscArraycpy(g.entry->M, Mv, d->in.type->geom->nnode));
      PetscCall(PetscArraycpy(g.entry->C, Cv, d->in.type->geom->nnode));
      g.entry->has_mass = PETSC_TRUE;
    }
  }
  for (PetscInt a = 0; a < d->in.type->geom->nnode; a++) {
    if (!(M[a] > 0)) {
      c->bad = e;
      *stop  = PETSC_TRUE;
      PetscFunctionReturn(PETSC_SUCCESS);
    }
    for (PetscInt i = 0; i < th; i++) c->m[d->ld[a * p->ndof + i]] += s * M[a];
    c->m[d->ld[a * p->ndof + th]] += C[a];
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TslProblemLumpedMass(TslProblem p, const PetscReal scale[], Vec M)
{
  Vec                xl, ml;
  const PetscScalar *xa;
  MassCtx            c      = {NULL, scale, -1};
  PetscInt           loc[3] = {-1, -1, -1}, g[3];

  PetscFunctionBeginUser;
  PetscCall(TslProblemGetLocalSolution(p, &xl, &xa));
  PetscCall(BeginLocal(M, &ml, &c.m));
  PetscCall(TslProblemElementLoop(p, xa, xa, MassElement, &c));
  PetscCall(EndLocal(M, &ml, &c.m));
  PetscCall(TslProblemRestoreLocalSolution(p, &xl, &xa));
  if (p->elem_cache) {
    PetscCall(PetscInfo(NULL, "lumped masses: %" PetscInt_FMT " of %" PetscInt_FMT " elements from the cache of %" PetscInt_FMT " distinct ones\n",
                        p->elem_cache->hits[1], p->m->nelem, p->elem_cache->n));
    p->elem_cache->hits[1] = 0;
  }
  if (c.bad >= 0) loc[0] = p->m->elem_id[c.bad], loc[1] = p->m->elem_line[2 * c.bad], loc[2] = p->m->elem_line[2 * c.bad + 1];
  PetscCall(MPIU_Allreduce(loc, g, 3, MPIU_INT, MPI_MAX, p->comm));
  if (g[0] >= 0) {
    TslLoc l = {g[1], g[2]};
    char   where[PETSC_MAX_PATH_LEN + 32];
    SETERRQ(p->comm, PETSC_ERR_USER_INPUT,
            "%s: element %" PetscInt_FMT " has a non-positive lumped mass at a node: its type is not supported in explicit steps (use a linear or a "
            "modified second-order type)",
            TslLocString(p->m, l, where, sizeof(where)), g[0]);
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Largest eigenvalue of the symmetric part of D^-1/2 A D^-1/2 (A: the n x n block of the element matrix at
 * rows/columns idx[], leading dimension lda; D: diagonal w), from above (TslLargestEigenvalue): by Irons'
 * theorem no eigenvalue of the assembled lumped-mass problem exceeds the largest element one, so the
 * increment is stable with it (an iterative estimate from below, power iteration, was not, by 10 % on a
 * bar). */
static void LargestEigenvalue(PetscInt n, const PetscInt idx[], const PetscReal A[], PetscInt lda, const PetscReal w[], PetscReal *lambda)
{
  PetscReal S[TSL_MAX_ELEM_DOF * TSL_MAX_ELEM_DOF], s[TSL_MAX_ELEM_DOF];

  for (PetscInt i = 0; i < n; i++) s[i] = 1.0 / PetscSqrtReal(w[i]);
  for (PetscInt i = 0; i < n; i++)
    for (PetscInt j = 0; j < n; j++) S[i * n + j] = 0.5 * (A[idx[i] * lda + idx[j]] + A[idx[j] * lda + idx[i]]) * s[i] * s[j];
  *lambda = n > 0 ? TslLargestEigenvalue(n, S) : 0;
}

typedef struct {
  PetscReal *R, *K, *dt_mech, *dt_heat;
  PetscInt   bad;
} StableCtx;

/* A collapsed element (a node id repeated, docs/elements.md "Collapsed elements") is, once assembled, an element on
 * its distinct nodes: the rows and columns of K and the lumped weights of the positions of one node summed into
 * its first position. Its eigenvalue bound is that element's: with the positions apart, the mode moving one
 * position of a node against another, which the assembled problem does not have, bounded the increment of a
 * collapsed CPE4T 6.4 times below the triangle's (thermal) and 2.5 times (mechanical). K is nd x nd (row-major),
 * M and C are replaced by the merged weights, first[a] is the first position of position a's node. */
static void MergeCollapsed(const TslElemData *d, PetscInt nnode, PetscInt ndof, PetscReal K[], PetscReal M[], PetscReal C[], PetscInt first[])
{
  const PetscInt nd = d->nd;

  for (PetscInt a = 0; a < nnode; a++) {
    first[a] = a;
    for (PetscInt b = 0; b < a && first[a] == a; b++)
      if (d->ld[a * ndof] == d->ld[b * ndof]) first[a] = b;
    if (first[a] == a) continue;
    M[first[a]] += M[a], C[first[a]] += C[a];
    for (PetscInt i = 0; i < ndof; i++) {
      const PetscInt ra = a * ndof + i, rb = first[a] * ndof + i;
      for (PetscInt j = 0; j < nd; j++) K[rb * nd + j] += K[ra * nd + j];
      for (PetscInt j = 0; j < nd; j++) K[j * nd + rb] += K[j * nd + ra];
    }
  }
}

/* Finite strain: an element whose centre C = F^T F is within this of its value at the element's last evaluation keeps
 * the increments found then. The element's eigenvalue follows its shape (and its stress, in the geometric stiffness):
 * a change of C by 1e-3 moves lambda by about that much, and the increment by half of it, against the 0.9 safety factor
 * on it; a rigid rotation leaves C as it was. Without it the spec's NLGEOM explicit slide spent 40 % of its time
 * evaluating every element's tangent and eigenvalue every TSL_NLGEOM_STABLE_EVERY increments. */
#define TSL_STABLE_SHAPE_TOL 1e-3

/* Finite strain: element e's increments just found, beside the shape they were found for (StableElement). */
static void KeepIncrements(TslProblem p, PetscInt e, const StableCtx *c)
{
  if (p->nlgeom) p->stable_shape[TSL_STABLE_SHAPE * e + 6] = c->dt_mech[e], p->stable_shape[TSL_STABLE_SHAPE * e + 7] = c->dt_heat[e];
}

static PetscErrorCode StableElement(TslProblem p, PetscInt e, TslElemData *d, void *ctx, PetscBool *stop)
{
  StableCtx      *c = (StableCtx *)ctx;
  PetscReal       M[TSL_MAX_ELEM_NODES], C[TSL_MAX_ELEM_NODES], Mm[TSL_MAX_ELEM_NODES], Cm[TSL_MAX_ELEM_NODES], w[TSL_MAX_ELEM_DOF] = {0}, lam;
  PetscInt        idx[TSL_MAX_ELEM_DOF] = {0}, first[TSL_MAX_ELEM_NODES], n = 0, nnode = d->in.type->geom->nnode, th = p->ndof - 1;
  PetscBool       inverted = PETSC_FALSE;
  ElemOnGrid      g;
  const PetscReal raise = 1 + 1e-8; /* above the grid's effect on the eigenvalue (StableKey) */
  TslElemData     cur;

  PetscFunctionBeginUser;
  if (p->nlgeom) { /* finite strain: the element as it stands now (the current size and shape set its increments) */
    const PetscInt dim = d->in.type->dim;
    PetscReal     *last = &p->stable_shape[TSL_STABLE_SHAPE * e], Cn[6], dC = 0;
    if (TslElementCentreStretch(&d->in, Cn)) {
      for (PetscInt r = 0; r < 6; r++) dC = PetscMax(dC, PetscAbsReal(Cn[r] - last[r]));
      if (dC <= TSL_STABLE_SHAPE_TOL) { /* its shape as at its last evaluation, turned perhaps: its increments then */
        c->dt_mech[e] = last[6], c->dt_heat[e] = last[7];
        PetscFunctionReturn(PETSC_SUCCESS);
      }
      for (PetscInt r = 0; r < 6; r++) last[r] = Cn[r];
    }
    cur = *d;
    for (PetscInt a = 0; a < d->in.type->geom->nnode; a++)
      for (PetscInt c = 0; c < dim; c++) cur.x[3 * a + c] += d->u[a * p->ndof + c];
    cur.in.x = cur.x, cur.in.u = cur.u, cur.in.theta_init = cur.ti;
    d = &cur;
  }
  PetscCall(ElemGrid(p, e, d, &g));
  if (g.entry && g.entry->has_dt) {
    c->dt_mech[e] = g.entry->dt_mech;
    c->dt_heat[e] = g.entry->dt_heat;
    p->elem_cache->hits[0]++;
    KeepIncrements(p, e, c);
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  PetscCall(TslElementInternal(&g.in, c->R, c->K, &inverted));
  if (inverted) {
    c->bad = e;
    *stop  = PETSC_TRUE;
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  PetscCall(TslElementLumped(&g.in, NULL, C, M));
  PetscCall(PetscArraycpy(Mm, M, nnode));
  PetscCall(PetscArraycpy(Cm, C, nnode));
  MergeCollapsed(d, nnode, p->ndof, c->K, Mm, Cm, first);
  for (PetscInt a = 0; a < nnode; a++)
    for (PetscInt i = 0; i < th; i++)
      if (first[a] == a && !p->pinned[d->ld[a * p->ndof + i]]) idx[n] = a * p->ndof + i, w[n++] = Mm[a];
  LargestEigenvalue(n, idx, c->K, d->nd, w, &lam);
  c->dt_mech[e] = lam > 0 ? 2.0 / PetscSqrtReal(lam * raise) : PETSC_MAX_REAL;
  n             = 0;
  for (PetscInt a = 0; a < nnode; a++)
    if (first[a] == a) idx[n] = a * p->ndof + th, w[n++] = Cm[a];
  LargestEigenvalue(n, idx, c->K, d->nd, w, &lam);
  c->dt_heat[e] = lam > 0 ? 2.0 / (lam * raise) : PETSC_MAX_REAL;
  KeepIncrements(p, e, c);
  if (g.entry) {
    g.entry->dt_mech = c->dt_mech[e], g.entry->dt_heat = c->dt_heat[e], g.entry->has_dt = PETSC_TRUE;
    if (!g.entry->has_mass) { /* the same masses as MassElement's */
      PetscCall(PetscArraycpy(g.entry->M, M, nnode));
      PetscCall(PetscArraycpy(g.entry->C, C, nnode));
      g.entry->has_mass = PETSC_TRUE;
    }
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TslProblemStableIncrements(TslProblem p, PetscReal dt_mech[], PetscReal dt_heat[])
{
  Vec                xl;
  const PetscScalar *xa;
  StableCtx          c = {NULL, NULL, dt_mech, dt_heat, -1};

  PetscFunctionBeginUser;
  PetscCall(PetscMalloc2(TSL_MAX_ELEM_DOF, &c.R, TSL_MAX_ELEM_DOF * TSL_MAX_ELEM_DOF, &c.K));
  PetscCall(StableShapesCreate(p));
  PetscCall(TslProblemGetLocalSolution(p, &xl, &xa));
  PetscCall(TslProblemElementLoop(p, xa, xa, StableElement, &c));
  PetscCall(TslProblemRestoreLocalSolution(p, &xl, &xa));
  if (p->elem_cache) {
    PetscCall(PetscInfo(NULL,
                        "stable increments: %" PetscInt_FMT " of %" PetscInt_FMT " elements from the cache of %" PetscInt_FMT " distinct ones\n",
                        p->elem_cache->hits[0], p->m->nelem, p->elem_cache->n));
    p->elem_cache->hits[0] = 0;
  }
  PetscCall(PetscFree2(c.R, c.K));
  PetscCall(TslProblemCheckBadElement(p, c.bad));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TslProblemConstrainedMask(TslProblem p, Vec mask)
{
  PetscScalar *m;

  PetscFunctionBeginUser;
  PetscCall(VecGetArray(mask, &m));
  for (PetscInt d = 0; d < p->nown * p->ndof; d++) m[d] = (p->pinned[d] || p->bc[d].active || p->dep[d] >= 0) ? 1.0 : 0.0;
  PetscCall(VecRestoreArray(mask, &m));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The lumped form of the tie u_s = sum c_sk u_k: with T the tie's map, T^T M T lumped by rows is M_k + c_sk M_s
 * (sum_k c_sk = 1), and T^T F is F_k + c_sk F_s; the secondary dof then follows its main dofs. */
PetscErrorCode TslProblemTieMove(TslProblem p, Vec V)
{
  PetscScalar *v, *moved;
  PetscInt    *from, n = 0;

  PetscFunctionBeginUser;
  if (!p->m->ntie) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(PetscMalloc2(p->nown * p->ndof, &moved, p->nown * p->ndof, &from));
  PetscCall(VecGetArray(V, &v));
  for (PetscInt d = 0; d < p->nown * p->ndof; d++) {
    if (p->dep[d] < 0 || p->bc[d].active || p->pinned[d] || v[d] == 0) continue;
    moved[n] = v[d], from[n++] = d;
    v[d] = 0;
  }
  PetscCall(VecRestoreArray(V, &v));
  for (PetscInt i = 0; i < n; i++) { /* stashed where the main dof is another rank's: applied at the assembly below */
    const TslEquation *eq = &p->m->equations[p->dep[from[i]]];
    for (PetscInt t = 1; t < eq->n; t++) {
      const PetscScalar w = -eq->coef[t] / eq->coef[0] * moved[i];
      PetscCall(VecSetValues(V, 1, &eq->gdof[t], &w, ADD_VALUES));
    }
  }
  PetscCall(PetscFree2(moved, from));
  PetscCall(VecAssemblyBegin(V));
  PetscCall(VecAssemblyEnd(V));
  PetscFunctionReturn(PETSC_SUCCESS);
}
