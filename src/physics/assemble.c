/* Assembly of the coupled residual and Jacobian, with constraints applied by row operations.
 *
 * One element loop serves four purposes (AsmMode): the constrained residual, the constrained
 * Jacobian, the nonzero pattern of that Jacobian (exact preallocation through MATPREALLOCATOR), and
 * the unconstrained residual whose values at prescribed dofs are the reactions RF / RFL. Because the
 * pattern is produced by the very code that inserts values, preallocation is exact by construction.
 */
#include "problem_impl.h"

static PetscErrorCode DiagonalBlock(Mat J, Mat *Ad);

void TslProblemGather(TslProblem p, PetscInt e, const PetscScalar *xa, const PetscScalar *xoa, TslElemData *d)
{
  const TslModel *m  = p->m;
  PetscInt        k0 = m->elem_ptr[e];

  d->n  = m->elem_ptr[e + 1] - k0;
  d->nd = d->n * p->ndof;
  for (PetscInt a = 0; a < d->n; a++) {
    PetscInt l = p->elem_lnode[k0 + a];
    for (PetscInt c = 0; c < 3; c++) d->x[3 * a + c] = m->node_xyz[3 * l + c];
    for (PetscInt i = 0; i < p->ndof; i++) {
      d->ld[a * p->ndof + i] = l * p->ndof + i;
      d->u[a * p->ndof + i]  = xa ? PetscRealPart(xa[l * p->ndof + i]) : 0;
      d->uo[a * p->ndof + i] = xoa ? PetscRealPart(xoa[l * p->ndof + i]) : 0;
    }
    d->ti[a] = p->theta_init[l];
    if (!xa) d->u[a * p->ndof + p->ndof - 1] = d->ti[a];
    if (!xoa) d->uo[a * p->ndof + p->ndof - 1] = d->ti[a];
  }
  d->in.type       = TslElementTypeGet(m->elem_type[e]);
  d->in.sec        = &p->esec[e];
  d->in.x          = d->x;
  d->in.u          = d->u;
  d->in.theta_init = d->ti;
  d->in.pstate         = p->pstate_off && p->pstate_off[e] >= 0 ? p->pstate + p->pstate_off[e] : NULL;
  d->in.pstate_new     = d->in.pstate && p->pstate_write ? p->pstate_new + p->pstate_off[e] : NULL;
  d->in.inelastic_rate = p->inelastic_rate;
  d->in.dt             = p->dt;
  d->in.nlgeom         = p->nlgeom;
  d->in_old            = d->in;
  d->in_old.u          = d->uo;
  /* the old state is the committed one: no further flow, no heat, nothing written */
  d->in_old.pstate_new     = NULL;
  d->in_old.inelastic_rate = 0;
}

/* The one element loop: gathers each local element's data (current and old state; NULL arrays read as
 * the initial state) and hands it to the visitor. Every per-element computation (assembly, checks,
 * heat balance, output fields) goes through here. */
PetscErrorCode TslProblemElementLoop(TslProblem p, const PetscScalar *xa, const PetscScalar *xoa, TslElementVisitor visit, void *ctx)
{
  TslElemData d;

  PetscFunctionBeginUser;
  for (PetscInt e = 0; e < p->m->nelem; e++) {
    PetscBool stop = PETSC_FALSE;
    TslProblemGather(p, e, xa, xoa, &d);
    PetscCall(visit(p, e, &d, ctx, &stop));
    if (stop) break;
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Matrix entries go through here. In the pattern pass the dofs become their nodes, so a node pair is
 * recorded once rather than ndof^2 times (the matrix gets whole node blocks): rows of owned nodes are
 * appended to p->pattern_pairs as one record per call, without any search (PatternRows sorts them out once
 * at the end); rows of ghost nodes go to A, the node-level MATPREALLOCATOR, which sends them to their
 * owners. Negative indices are ignored, as MatSetValues does. */
static PetscErrorCode MatAdd(TslProblem p, AsmMode mode, Mat A, PetscInt nrow, const PetscInt rows[], PetscInt ncol, const PetscInt cols[],
                             const PetscScalar v[])
{
  PetscFunctionBeginUser;
  if (mode == ASM_PATTERN) {
    PetscInt    nr = 0, ng = 0, nc = 0, r[TSL_MAX_ELEM_DOF], g[TSL_MAX_ELEM_DOF], c[TSL_MAX_ELEM_DOF], *rec;
    PetscScalar zero[TSL_MAX_ELEM_DOF] = {0};
    PetscCheck(nrow <= TSL_MAX_ELEM_DOF && ncol <= TSL_MAX_ELEM_DOF, PETSC_COMM_SELF, PETSC_ERR_PLIB, "pattern block too large");
    for (PetscInt i = 0; i < nrow; i++) {
      const PetscInt n = rows[i] / p->ndof;
      if (rows[i] < 0) continue;
      if (n < p->nown) {
        if (!nr || r[nr - 1] != n) r[nr++] = n;
      } else if (!ng || g[ng - 1] != n) g[ng++] = n;
    }
    for (PetscInt j = 0; j < ncol; j++)
      if (cols[j] >= 0 && (!nc || c[nc - 1] != cols[j] / p->ndof)) c[nc++] = cols[j] / p->ndof;
    for (PetscInt i = 0; i < ng; i++) PetscCall(MatSetValuesLocal(A, 1, &g[i], nc, c, zero, ADD_VALUES));
    if (!nr || !nc) PetscFunctionReturn(PETSC_SUCCESS);
    if (p->pattern_pairs.n + 2 + nr + nc > p->pattern_pairs.cap) {
      p->pattern_pairs.cap = 2 * p->pattern_pairs.cap + 2 + nr + nc;
      PetscCall(PetscRealloc(sizeof(PetscInt) * (size_t)p->pattern_pairs.cap, &p->pattern_pairs.rec));
    }
    rec    = p->pattern_pairs.rec + p->pattern_pairs.n;
    rec[0] = nr, rec[1] = nc;
    PetscCall(PetscArraycpy(rec + 2, r, nr));
    PetscCall(PetscArraycpy(rec + 2 + nr, c, nc));
    p->pattern_pairs.n += 2 + nr + nc;
  } else PetscCall(MatSetValuesLocal(A, nrow, rows, ncol, cols, v, ADD_VALUES));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Adds weight * (row r of R, K) to local row `row`. */
static PetscErrorCode AddRow(TslProblem p, AsmMode mode, Mat A, PetscScalar *f, PetscInt row, PetscReal w, PetscInt r, PetscInt n, const PetscInt ld[],
                             const PetscReal R[], const PetscReal K[])
{
  PetscScalar v[TSL_MAX_ELEM_DOF];

  PetscFunctionBeginUser;
  if (mode == ASM_RESIDUAL || mode == ASM_RAW) {
    f[row] += w * R[r];
  } else {
    for (PetscInt j = 0; j < n; j++) v[j] = K ? w * K[r * n + j] : 0;
    PetscCall(MatAdd(p, mode, A, 1, &row, n, ld, v));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* A row's kind for the matrix pattern: 'f' free, 'p' pinned (a slot the kinematics does not use), 'b'
 * prescribed by a boundary condition, 'e' eliminated by an equation. */
static char RowKind(TslProblem p, PetscInt r)
{
  return p->pinned[r] ? 'p' : p->bc[r].active ? 'b' : p->dep[r] >= 0 ? 'e' : 'f';
}

/* Whole node blocks (ld = node-major dofs of n / ndof nodes) none of whose rows is constrained: the
 * block can go in with one MatSetValuesBlockedLocal. */
static PetscBool FreeNodeBlocks(TslProblem p, PetscInt n, const PetscInt ld[], PetscInt nb, PetscInt bidx[])
{
  if (n % p->ndof || n / p->ndof > nb) return PETSC_FALSE;
  for (PetscInt a = 0; a < n / p->ndof; a++) {
    if (ld[a * p->ndof] % p->ndof) return PETSC_FALSE;
    bidx[a] = ld[a * p->ndof] / p->ndof;
    for (PetscInt i = 0; i < p->ndof; i++) {
      PetscInt row = ld[a * p->ndof + i];
      if (row != ld[a * p->ndof] + i || RowKind(p, row) != 'f') return PETSC_FALSE;
    }
  }
  return PETSC_TRUE;
}

/* The place of node column block `col` (its first column) among the blocks of the CSR row ja[lo0..hi0) (whole
 * node blocks, sorted), or -1 when the row does not hold it. */
static PetscInt BlockPlace(const PetscInt ja[], PetscInt lo0, PetscInt hi0, PetscInt bs, PetscInt col)
{
  PetscInt lo = lo0, hi = hi0;

  while (lo < hi) { /* first entry >= col */
    PetscInt mid = (lo + hi) / 2;
    if (ja[mid] < col)
      lo = mid + 1;
    else
      hi = mid;
  }
  return lo < hi0 && ja[lo] == col && (lo - lo0) % bs == 0 ? (lo - lo0) / bs : -1;
}

/* Adds the block K (nb node blocks, node-major, ld = ln[a]*bs + i) to the Jacobian's CSR values (p->jac_val):
 * node b's block of node a's rows at block place pos[a*nb + b]. Rows of prescribed or pinned dofs are dropped,
 * as TslProblemInsert drops them (a node without a free row has no places: all its rows are dropped). */
static void AddNodeBlocks(TslProblem p, PetscInt nb, const PetscInt ln[], const unsigned short pos[], const PetscReal K[])
{
  const PetscInt bs = p->ndof, nd = nb * bs;

  for (PetscInt a = 0; a < nb; a++)
    for (PetscInt i = 0; i < bs; i++) {
      const PetscInt   lr  = ln[a] * bs + i;
      const PetscReal *src = &K[(a * bs + i) * nd];
      PetscScalar     *row;
      if (p->pinned[lr] || p->bc[lr].active) continue;
      row = p->jac_val + p->jac_row[lr];
      for (PetscInt b = 0; b < nb; b++) {
        PetscScalar *dst = row + bs * pos[a * nb + b];
        for (PetscInt j = 0; j < bs; j++) dst[j] += src[b * bs + j];
      }
    }
}

/* A block of whole node blocks (ld = node-major dofs) straight into the CSR values of the Jacobian being
 * assembled (p->jac_val): every node owned here and no row eliminated by an equation, else false and nothing
 * added. The places are found by binary search in the rows (the elements' map, BuildDirectMap, keeps them; a
 * contact block's nodes change with the pairing): a search per node pair instead of MatSetValues's per entry. */
static PetscBool InsertDirect(TslProblem p, PetscInt n, const PetscInt ld[], const PetscReal K[])
{
  const PetscInt bs = p->ndof, nb = n / bs;
  PetscInt       ln[TSL_MAX_ELEM_NODES + 1];
  PetscBool      free[TSL_MAX_ELEM_NODES + 1];
  unsigned short pos[(TSL_MAX_ELEM_NODES + 1) * (TSL_MAX_ELEM_NODES + 1)];

  if (!p->jac_val || n % bs || nb > TSL_MAX_ELEM_NODES + 1) return PETSC_FALSE;
  for (PetscInt a = 0; a < nb; a++) {
    const PetscInt r0 = ld[a * bs];
    if (r0 < 0 || r0 % bs || r0 / bs >= p->nown) return PETSC_FALSE;
    free[a] = PETSC_FALSE;
    for (PetscInt i = 0; i < bs; i++) {
      const char kind = ld[a * bs + i] == r0 + i ? RowKind(p, r0 + i) : 0;
      if (!kind || kind == 'e') return PETSC_FALSE;
      if (kind == 'f') free[a] = PETSC_TRUE;
    }
    ln[a] = r0 / bs;
  }
  for (PetscInt a = 0; a < nb; a++) { /* every place first: nothing is added unless all are found */
    if (!free[a]) continue;           /* only its diagonal is in the pattern, and all its rows are dropped */
    for (PetscInt b = 0; b < nb; b++) {
      const PetscInt k = BlockPlace(p->jac_col, p->jac_row[ln[a] * bs], p->jac_row[ln[a] * bs + 1], bs, ln[b] * bs);
      if (k < 0 || k >= 65536) return PETSC_FALSE; /* not in the pattern (TslProblemInsert then reports it) */
      pos[a * nb + b] = (unsigned short)k;
    }
  }
  AddNodeBlocks(p, nb, ln, pos, K);
  return PETSC_TRUE;
}

/* Inserts an element block, applying the constraints: rows of prescribed dofs are dropped, rows of
 * dofs eliminated by an equation go to the other terms' rows with weight -c_k/c_0 (T^T R, T^T K). */
PetscErrorCode TslProblemInsert(TslProblem p, AsmMode mode, Mat A, PetscScalar *f, PetscInt n, const PetscInt ld[], const PetscReal R[],
                                const PetscReal K[])
{
  PetscInt bidx[TSL_MAX_ELEM_NODES + 1], m = 0;

  PetscFunctionBeginUser;
  for (PetscInt r = 0; r < n; r++) m += ld[r] >= 0;
  if (m < n) { /* leave out the slots the model does not have (TslProblemSlotDof) */
    PetscInt  keep[TSL_MAX_ELEM_DOF], ld2[TSL_MAX_ELEM_DOF];
    PetscReal R2[TSL_MAX_ELEM_DOF], K2[TSL_MAX_ELEM_DOF * TSL_MAX_ELEM_DOF];
    PetscCheck(n <= TSL_MAX_ELEM_DOF, PETSC_COMM_SELF, PETSC_ERR_PLIB, "too many element rows");
    for (PetscInt r = 0, k = 0; r < n; r++)
      if (ld[r] >= 0) keep[k] = r, ld2[k++] = ld[r];
    for (PetscInt i = 0; i < m; i++) {
      if (R) R2[i] = R[keep[i]];
      for (PetscInt j = 0; K && j < m; j++) K2[i * m + j] = K[keep[i] * n + keep[j]];
    }
    PetscCall(TslProblemInsert(p, mode, A, f, m, ld2, R ? R2 : NULL, K ? K2 : NULL));
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  if (mode == ASM_JACOBIAN && K && InsertDirect(p, n, ld, K)) PetscFunctionReturn(PETSC_SUCCESS);
  if (((mode == ASM_JACOBIAN && K) || mode == ASM_PATTERN) && FreeNodeBlocks(p, n, ld, TSL_MAX_ELEM_NODES + 1, bidx)) {
    if (mode == ASM_PATTERN) PetscCall(MatAdd(p, mode, A, n, ld, n, ld, NULL)); /* every node pair once */
    else PetscCall(MatSetValuesBlockedLocal(A, n / p->ndof, bidx, n / p->ndof, bidx, K, ADD_VALUES));
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  for (PetscInt r = 0; r < n; r++) {
    PetscInt row = ld[r], q = p->dep[row];
    if (mode == ASM_RAW) { /* reactions: the equations' T^T still applies (a main node's support carries what its
                              secondary nodes pass on), a prescribed dof keeps its own row */
      if (q < 0 || p->bc[row].active) f[row] += R[r];
      else
        for (PetscInt t = 1; t < p->m->equations[q].n; t++) f[p->eq_ldof[q][t]] -= p->m->equations[q].coef[t] / p->m->equations[q].coef[0] * R[r];
      continue;
    }
    if (p->bc[row].active || p->pinned[row]) continue;
    if (q < 0) {
      PetscCall(AddRow(p, mode, A, f, row, 1.0, r, n, ld, R, K));
      continue;
    }
    for (PetscInt t = 1; t < p->m->equations[q].n; t++) {
      PetscInt tr = p->eq_ldof[q][t];
      if (p->bc[tr].active) continue;
      PetscCall(AddRow(p, mode, A, f, tr, -p->m->equations[q].coef[t] / p->m->equations[q].coef[0], r, n, ld, R, K));
    }
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TslProblemFaceLoadValue(TslProblem p, const TslFaceRecord *r, TslFaceLoadValue *v)
{
  PetscFunctionBeginUser;
  v->value = TslProblemEvalLoadValue(p, &r->value);
  v->sink  = TslProblemEvalLoadValue(p, &r->sink);
  v->zero  = p->m->absolute_zero;
  if (r->film_amp >= 0) {
    const TslAmplitude *a = &p->m->amplitudes[r->film_amp];
    v->value *= TslAmplitudeEval(a, a->total_time ? p->ttot : p->t);
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TslProblemRecordLoad(TslProblem p, const TslFaceRecord *r, const TslElementInput *in, PetscReal R[], PetscReal K[], PetscReal *heat)
{
  TslFaceLoadValue v;

  PetscFunctionBeginUser;
  PetscCall(TslProblemFaceLoadValue(p, r, &v));
  *heat = 0;
  if (TslFaceLoadKindIsBodyForce(r->kind))
    PetscCall(TslElementBodyForce(in, r->kind, v.value, r->axis, R, NULL)); /* no tangent: the load depends on no unknown */
  else
    PetscCall(TslElementFaceLoad(in, r->kind, r->face, &v, R, K, heat));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Capacity term of the time discretisation chosen by the solver: R_theta(a) += shift (Q_a - Q_old_a),
 * K += shift C (backward Euler: shift = 1/dt; steady state: 0, skipped). C is diagonal for the linear
 * families and the consistent matrix for the second-order ones (TslElementHeatContent). */
static PetscErrorCode AddCapacity(TslProblem p, const TslElemData *d, PetscReal R[], PetscReal K[], AsmHeat *heat)
{
  PetscReal      Q[TSL_MAX_ELEM_NODES], Qo[TSL_MAX_ELEM_NODES], C[TSL_MAX_ELEM_NODES * TSL_MAX_ELEM_NODES];
  const PetscInt th = p->ndof - 1, n = d->in.type->geom->nnode;

  PetscFunctionBeginUser;
  if (p->shift == 0) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(TslElementHeatContent(&d->in, Q, K ? C : NULL));
  PetscCall(TslElementHeatContent(&d->in_old, Qo, NULL));
  /* the element's own nodes: d->n also counts a generalized plane strain element's reference node, which
   * has no capacity */
  for (PetscInt a = 0; a < n; a++) {
    const PetscInt row = p->ndof * a + th;
    R[row] += p->shift * (Q[a] - Qo[a]);
    if (K)
      for (PetscInt b = 0; b < n; b++) K[row * d->nd + p->ndof * b + th] += p->shift * C[a * n + b];
    if (heat) heat->stored += Q[a] - Qo[a];
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* An element's block: straight into the CSR values when the element has a direct-insertion map and a
 * Jacobian is being assembled, else through TslProblemInsert. */
static PetscErrorCode InsertElement(TslProblem p, AsmMode mode, Mat A, PetscScalar *f, PetscInt e, const TslElemData *d, const PetscReal R[],
                                    const PetscReal K[])
{
  PetscFunctionBeginUser;
  if (mode == ASM_JACOBIAN && K && p->jac_val && p->blk_ptr[e + 1] > p->blk_ptr[e]) {
    PetscInt ln[TSL_MAX_ELEM_NODES + 1];
    for (PetscInt a = 0; a < d->n; a++) ln[a] = d->ld[a * p->ndof] / p->ndof;
    AddNodeBlocks(p, d->n, ln, &p->blk[p->blk_ptr[e]], K);
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  PetscCall(TslProblemInsert(p, mode, A, f, d->nd, d->ld, R, K));
  PetscFunctionReturn(PETSC_SUCCESS);
}

typedef struct {
  AsmMode      mode;
  Mat          A;
  PetscScalar *f;
  AsmHeat     *heat;
  PetscReal   *R, *K;
  PetscInt    *bad_elem;
} AsmCtx;

/* An element's work after its internal force (and tangent) are in c->R (c->K): the capacity term, the
 * insertion, its face loads. */
static PetscErrorCode ElementRest(TslProblem p, PetscInt e, const TslElemData *d, AsmCtx *c)
{
  PetscReal *R = c->R, *K = c->mode == ASM_JACOBIAN ? c->K : NULL;

  PetscFunctionBeginUser;
  PetscCall(AddCapacity(p, d, R, K, c->heat));
  if (c->mode == ASM_RESIDUAL && p->flux_on) /* the dialect's instantaneous flux: |R_i| over the element's components, per field */
    for (PetscInt i = 0; i < d->nd; i++) {
      const PetscInt f = d->ld[i] % p->ndof == p->ndof - 1;
      p->flux_abs[f] += PetscAbsReal(R[i]), p->flux_n[f] += 1;
    }
  PetscCall(InsertElement(p, c->mode, c->A, c->f, e, d, R, K));
  for (PetscInt i = p->face_start[e]; i < p->face_start[e + 1]; i++) {
    const TslFaceRecord *r = &p->face[i];
    PetscReal            h = 0;
    PetscCall(PetscArrayzero(R, d->nd));
    if (K) PetscCall(PetscArrayzero(K, d->nd * d->nd));
    PetscCall(TslProblemRecordLoad(p, r, &d->in, R, K, &h));
    PetscCall(InsertElement(p, c->mode, c->A, c->f, e, d, R, K));
    if (c->heat) TslAsmHeatAdd(c->heat, r->kind, h);
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode AssembleElement(TslProblem p, PetscInt e, TslElemData *d, void *ctx, PetscBool *stop)
{
  AsmCtx   *c        = (AsmCtx *)ctx;
  PetscBool inverted = PETSC_FALSE;
  PetscReal energy[4];

  PetscFunctionBeginUser;
  (void)stop;
  if (c->mode == ASM_PATTERN) {
    PetscCall(TslProblemInsert(p, c->mode, c->A, c->f, d->nd, d->ld, NULL, NULL));
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  /* the heat balance's pass: with the energies */
  PetscCall(TslElementInternalEnergy(&d->in, c->R, c->mode == ASM_JACOBIAN ? c->K : NULL, &inverted, c->heat ? energy : NULL));
  if (inverted) {
    if (*c->bad_elem < 0) *c->bad_elem = e;
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  if (c->heat) {
    c->heat->energy[0] += energy[0], c->heat->energy[1] += energy[1];
    c->heat->plastic_work += energy[2], c->heat->plastic_heat += energy[3];
  }
  PetscCall(ElementRest(p, e, d, c));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The residual of the elements with a force record (TslProblemRecords: small strain, temperature-independent
 * properties, so an element's geometry and conduction never change): internal force, heat flow and, in the
 * heat balance's pass, the energies from the record, a batch of TSL_FAST_LANES elements of one type per
 * kernel call (docs/explicit.md "Element force records"; the same formulas as TslElementInternal to
 * rounding), the rest of each element's work as for the others. An inverted element has no record. */
static PetscErrorCode AssembleRecords(TslProblem p, const PetscScalar *xa, const PetscScalar *xoa, AsmCtx *c)
{
  enum { W = TSL_FAST_LANES };
  TslElemData d[W];
  PetscReal   u[TSL_MAX_ELEM_DOF * W], ti[TSL_MAX_ELEM_NODES * W], R[TSL_MAX_ELEM_DOF * W], energy[2 * W];

  PetscFunctionBeginUser;
  for (PetscInt b = 0; b < p->fast_nbatch; b++) {
    const PetscInt            *lane  = &p->fast_batch[W * b];
    const TslElementFastShape *shape = &p->fast_shape[p->m->elem_type[lane[0]]];
    for (PetscInt j = 0; j < W; j++) { /* an empty lane repeats lane 0 (computed, never inserted) */
      TslProblemGather(p, lane[j] >= 0 ? lane[j] : lane[0], xa, xoa, &d[j]);
      TslElementFastInterleave(d[j].nd, j, d[j].u, u);
      TslElementFastInterleave(d[j].n, j, d[j].ti, ti);
    }
    const int inv = TslElementFastResidualBatch(shape, p->nlgeom, &p->fast_rec[p->fast_boff[b]], u, ti, R, c->heat ? energy : NULL);
    for (PetscInt j = 0; j < W; j++) {
      if (lane[j] < 0) continue;
      if (inv & (1 << j)) { /* finite strain: turned inside out by this iterate, as the generic kernel's `inverted` */
        if (*c->bad_elem < 0) *c->bad_elem = lane[j];
        continue;
      }
      for (PetscInt i = 0; i < d[j].nd; i++) c->R[i] = R[i * W + j];
      if (c->heat) c->heat->energy[0] += energy[j], c->heat->energy[1] += energy[W + j];
      PetscCall(ElementRest(p, lane[j], &d[j], c));
    }
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The element, contact and nodal-load contributions. xa, xoa: local forms of the current and old
 * solution; f: local form of the residual; R, K: work arrays of TSL_MAX_ELEM_DOF and its square. */
static PetscErrorCode AssembleLoop(TslProblem p, AsmMode mode, const PetscScalar *xa, const PetscScalar *xoa, PetscScalar *f, Mat A, AsmHeat *heat,
                                   PetscReal *R, PetscReal *K, PetscInt *bad_elem)
{
  AsmCtx          ctx     = {mode, A, f, heat, R, K, bad_elem};
  const PetscBool records = (mode == ASM_RESIDUAL || mode == ASM_RAW) && p->fast_implicit && p->fast_built; /* small or finite strain */

  PetscFunctionBeginUser;
  if (mode == ASM_RESIDUAL) p->flux_abs[0] = p->flux_abs[1] = p->flux_n[0] = p->flux_n[1] = 0;
  if (records) {
    PetscCall(AssembleRecords(p, xa, xoa, &ctx));
    for (PetscInt e = 0; e < p->m->nelem; e++) {
      TslElemData d;
      PetscBool   stop = PETSC_FALSE;
      if (p->fast_off[e] >= 0) continue;
      TslProblemGather(p, e, xa, xoa, &d);
      PetscCall(AssembleElement(p, e, &d, &ctx, &stop));
    }
  } else
    PetscCall(TslProblemElementLoop(p, xa, xoa, AssembleElement, &ctx));
  PetscCall(TslProblemContactAssemble(p, mode, xa, f, A, heat));
  /* nodal loads (owned dofs only): residual = internal - external */
  if (mode == ASM_RESIDUAL || mode == ASM_RAW) {
    for (PetscInt i = 0; i < p->nnload_own; i++) {
      PetscInt  dof = p->nload_own[i];
      PetscReal v   = -TslProblemEvalLoadValue(p, &p->nload[dof]);
      PetscCall(TslProblemInsert(p, mode, A, f, 1, &dof, &v, NULL));
      if (heat && dof % p->ndof == p->ndof - 1) heat->flux_in -= v;
    }
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode Injected(TslInjectKind kind)
{
  PetscFunctionBeginUser;
  SETERRQ(PETSC_COMM_SELF, kind == TSL_INJECT_CONVERGE ? PETSC_ERR_CONV_FAILED : PETSC_ERR_PLIB, "injected %s failure (-tsl_debug_fail_kind)",
          kind == TSL_INJECT_CONVERGE ? "convergence" : "internal");
}

/* The element and contact loop, run rank by rank, with its outcome decided on all ranks (sys.h): a fatal
 * failure on any rank is raised on all; a convergence-type one (e.g. a contact projection that does not
 * converge at a wild Newton iterate) comes back as *fail on all ranks, with its message in p->fail_msg. */
static PetscErrorCode AssembleLocal(TslProblem p, AsmMode mode, const PetscScalar *xa, const PetscScalar *xoa, PetscScalar *f, Mat A, AsmHeat *heat,
                                    PetscInt *bad_elem, TslFailure *fail)
{
  PetscReal     *R, *K;
  PetscErrorCode e;

  PetscFunctionBeginUser;
  *bad_elem = -1;
  if (heat) PetscCall(PetscMemzero(heat, sizeof(*heat)));
  PetscCall(PetscMalloc2(TSL_MAX_ELEM_DOF, &R, TSL_MAX_ELEM_DOF * TSL_MAX_ELEM_DOF, &K));
  PetscCall(TslCaptureBegin());
  e = AssembleLoop(p, mode, xa, xoa, f, A, heat, R, K, bad_elem);
  if (!e && mode == ASM_RESIDUAL && TslInjectNow(&p->inject, TSL_INJECT_CONVERGE, p->step + 1)) e = Injected(TSL_INJECT_CONVERGE);
  if (!e && mode == ASM_RESIDUAL && TslInjectNow(&p->inject, TSL_INJECT_INTERNAL, p->step + 1)) e = Injected(TSL_INJECT_INTERNAL);
  PetscCall(TslCaptureEnd());
  PetscCall(PetscFree2(R, K));
  PetscCall(TslAgree(p->comm, e, fail, p->fail_msg));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* An inverted element after an assembly (collective): at small strain a user error (TslProblemCheckBadElement); in a
 * finite-strain step one turned inside out by a Newton iterate (det F <= 0; the reference geometry was checked before
 * the job), a convergence-type failure on all ranks, so the increment is cut back. */
static PetscErrorCode AssembledBadElement(TslProblem p, PetscInt bad, TslFailure *fail)
{
  PetscInt id = bad >= 0 ? p->m->elem_id[bad] : -1, g;

  PetscFunctionBeginUser;
  if (!p->nlgeom) PetscFunctionReturn(TslProblemCheckBadElement(p, bad));
  PetscCall(MPIU_Allreduce(&id, &g, 1, MPIU_INT, MPI_MAX, p->comm));
  if (g < 0 || *fail) PetscFunctionReturn(PETSC_SUCCESS);
  *fail = TSL_FAIL_CONVERGENCE;
  PetscCall(PetscSNPrintf(p->fail_msg, sizeof(p->fail_msg), "element %" PetscInt_FMT " turned inside out (det F <= 0) at a Newton iterate", g));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* An inverted element on any rank is a user error on all ranks (collective). */
PetscErrorCode TslProblemCheckBadElement(TslProblem p, PetscInt bad)
{
  PetscInt loc[3] = {-1, -1, -1}, g[3];
  char     where[PETSC_MAX_PATH_LEN + 32];

  PetscFunctionBeginUser;
  if (bad >= 0) loc[0] = p->m->elem_id[bad], loc[1] = p->m->elem_line[2 * bad], loc[2] = p->m->elem_line[2 * bad + 1];
  PetscCall(MPIU_Allreduce(loc, g, 3, MPIU_INT, MPI_MAX, p->comm));
  if (g[0] >= 0) {
    TslLoc l = {g[1], g[2]};
    SETERRQ(p->comm, PETSC_ERR_USER_INPUT, "%s: element %" PetscInt_FMT " is inverted or degenerate (non-positive Jacobian determinant)",
            TslLocString(p->m, l, where, sizeof(where)), g[0]);
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

typedef struct {
  PetscReal *R, *K, sum[6]; /* per row group (RowGroup): the sum of |K_ii|, then the count */
  PetscInt   bad, stride;
} CheckCtx;

/* The constraint rows' scale group of a slot: 0 the translations (and the unused slots), 1 the temperature,
 * 2 the twist phi of the axisymmetric types with twist. phi's rows are moments per radian, r^2 times a
 * translation's at the same node: in one mean with the translations they set the scale of every displacement
 * constraint row, 3e5 times the rows around it on rings at r = 1000, and the first residual of an increment
 * with a prescribed displacement (the constraint rows' s (u - g)) rose with it, to 1e15, so that the
 * displacement tolerance (1e-8 of that residual) exceeded the applied load (issue 44, item 7). Dof 5 is a
 * regular node's unknown on the twist types only (the generalized plane strain types carry theirs on the
 * reference node, an extra node whose rows keep group 0). */
static PetscInt RowGroup(TslProblem p, PetscInt slot)
{
  return slot == p->ndof - 1 ? 1 : p->node_dof[slot] == 5 ? 2 : 0;
}

static PetscErrorCode CheckElement(TslProblem p, PetscInt e, TslElemData *d, void *ctx, PetscBool *stop)
{
  CheckCtx *c        = (CheckCtx *)ctx;
  PetscBool inverted = PETSC_FALSE;

  PetscFunctionBeginUser;
  if (p->m->elem_nat[e] % c->stride) { /* geometry only */
    if (!TslElementValid(&d->in)) c->bad = e, *stop = PETSC_TRUE;
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  PetscCall(TslElementInternal(&d->in, c->R, c->K, &inverted));
  if (inverted) {
    c->bad = e;
    *stop  = PETSC_TRUE;
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  for (PetscInt r = 0; r < d->nd; r++) {
    PetscInt f = RowGroup(p, r % p->ndof);
    c->sum[f] += PetscAbsReal(c->K[r * d->nd + r]);
    c->sum[3 + f] += 1;
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Checks every element's geometry, and measures the mean diagonal of the element matrices per field:
 * constraint rows are scaled by it, so that they look like the rows around them to the AMG smoothers
 * (rows of 1 next to rows of E*thickness slow BoomerAMG down badly in parallel). The mean comes from
 * every stride-th element in the deck's order (about 4096 in all, the same on any number of ranks):
 * a scale, not an exact figure, and a full tangent of every element would cost as much as a Jacobian. */
PetscErrorCode TslProblemCheckElements(TslProblem p)
{
  CheckCtx  c = {NULL, NULL, {0, 0, 0, 0, 0, 0}, -1, PetscMax(1, p->m->nelem_global / 4096)};
  PetscReal g[6];

  PetscFunctionBeginUser;
  PetscCall(PetscMalloc2(TSL_MAX_ELEM_DOF, &c.R, TSL_MAX_ELEM_DOF * TSL_MAX_ELEM_DOF, &c.K));
  PetscCall(TslProblemElementLoop(p, NULL, NULL, CheckElement, &c));
  PetscCall(PetscFree2(c.R, c.K));
  PetscCall(TslProblemCheckBadElement(p, c.bad));
  PetscCall(MPIU_Allreduce(c.sum, g, 6, MPIU_REAL, MPIU_SUM, p->comm));
  for (PetscInt f = 0; f < 3; f++) p->row_scale[f] = (g[3 + f] > 0 && g[f] > 0) ? g[f] / g[3 + f] : 1.0;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Rows of the constraints themselves, scaled by the field's row scale (owned rows only):
 *   s (u_d - g) = 0    and    s (u_a + sum_k (c_k/c_0) u_k) = 0 */
static PetscErrorCode ConstraintRows(TslProblem p, AsmMode mode, const PetscScalar *xa, PetscScalar *F, Mat A)
{
  PetscFunctionBeginUser;
  for (PetscInt d = 0; d < p->nown * p->ndof; d++) {
    PetscInt  q = p->dep[d];
    PetscReal s = p->row_scale[RowGroup(p, d % p->ndof)];
    if (p->pinned[d]) { /* a slot the kinematics does not use: s u = 0 */
      if (mode == ASM_RESIDUAL)
        F[d] = s * xa[d];
      else
        PetscCall(MatAdd(p, mode, A, 1, &d, 1, &d, &s));
    } else if (p->bc[d].active) {
      if (mode == ASM_RESIDUAL)
        F[d] = s * (xa[d] - TslProblemEvalLoadValue(p, &p->bc[d]));
      else
        PetscCall(MatAdd(p, mode, A, 1, &d, 1, &d, &s));
    } else if (q >= 0) {
      const TslEquation *eq = &p->m->equations[q];
      PetscScalar        v[64];
      PetscCheck(eq->n <= 64, PETSC_COMM_SELF, PETSC_ERR_SUP, "equations with more than 64 terms");
      for (PetscInt t = 0; t < eq->n; t++) v[t] = s * eq->coef[t] / eq->coef[0];
      if (mode == ASM_RESIDUAL) {
        F[d] = 0;
        for (PetscInt t = 0; t < eq->n; t++) F[d] += v[t] * xa[p->eq_ldof[q][t]];
      } else
        PetscCall(MatAdd(p, mode, A, 1, &d, eq->n, p->eq_ldof[q], v));
    }
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TslProblemGetLocalSolution(TslProblem p, Vec *xl, const PetscScalar **xa)
{
  PetscFunctionBeginUser;
  PetscCall(VecCopy(p->X, p->Xl));
  PetscCall(TslGhostUpdate(p->Xl, INSERT_VALUES, SCATTER_FORWARD));
  PetscCall(VecGhostGetLocalForm(p->Xl, xl));
  PetscCall(VecGetArrayRead(*xl, xa));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TslProblemRestoreLocalSolution(TslProblem p, Vec *xl, const PetscScalar **xa)
{
  PetscFunctionBeginUser;
  PetscCall(VecRestoreArrayRead(*xl, xa));
  PetscCall(VecGhostRestoreLocalForm(p->Xl, xl));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Local forms of X (ghosts updated) and Xold. */
static PetscErrorCode GetStates(TslProblem p, Vec X, Vec *xl, Vec *xol, const PetscScalar **xa, const PetscScalar **xoa)
{
  PetscFunctionBeginUser;
  if (X != p->Xl) PetscCall(VecCopy(X, p->Xl));
  /* one at a time: duplicated ghosted vectors share their scatter */
  PetscCall(TslGhostUpdate(p->Xl, INSERT_VALUES, SCATTER_FORWARD));
  PetscCall(TslGhostUpdate(p->Xold, INSERT_VALUES, SCATTER_FORWARD));
  PetscCall(VecGhostGetLocalForm(p->Xl, xl));
  PetscCall(VecGhostGetLocalForm(p->Xold, xol));
  PetscCall(VecGetArrayRead(*xl, xa));
  PetscCall(VecGetArrayRead(*xol, xoa));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode RestoreStates(TslProblem p, Vec *xl, Vec *xol, const PetscScalar **xa, const PetscScalar **xoa)
{
  PetscFunctionBeginUser;
  PetscCall(VecRestoreArrayRead(*xl, xa));
  PetscCall(VecRestoreArrayRead(*xol, xoa));
  PetscCall(VecGhostRestoreLocalForm(p->Xl, xl));
  PetscCall(VecGhostRestoreLocalForm(p->Xold, xol));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Residual (constrained or raw) into F; *fail: a convergence-type failure agreed by all ranks. */
static PetscErrorCode Residual(TslProblem p, AsmMode mode, Vec X, Vec F, AsmHeat *heat, TslFailure *fail)
{
  Vec                xl, xol, fl;
  const PetscScalar *xa, *xoa;
  PetscScalar       *fa, *Fa;
  PetscInt           bad;

  PetscFunctionBeginUser;
  PetscCall(GetStates(p, X, &xl, &xol, &xa, &xoa));
  PetscCall(VecGhostGetLocalForm(p->Fl, &fl));
  PetscCall(VecZeroEntries(fl));
  PetscCall(VecGetArray(fl, &fa));
  PetscCall(AssembleLocal(p, mode, xa, xoa, fa, NULL, heat, &bad, fail));
  PetscCall(VecRestoreArray(fl, &fa));
  PetscCall(VecGhostRestoreLocalForm(p->Fl, &fl));
  PetscCall(AssembledBadElement(p, bad, fail));
  PetscCall(TslGhostUpdate(p->Fl, ADD_VALUES, SCATTER_REVERSE));
  PetscCall(VecCopy(p->Fl, F));
  if (mode == ASM_RESIDUAL) {
    PetscCall(VecGetArray(F, &Fa));
    PetscCall(ConstraintRows(p, mode, xa, Fa, NULL));
    PetscCall(VecRestoreArray(F, &Fa));
  }
  PetscCall(RestoreStates(p, &xl, &xol, &xa, &xoa));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TslProblemFormFunction(SNES snes, Vec X, Vec F, void *ctx)
{
  TslFailure fail;

  PetscFunctionBeginUser;
  PetscCall(TslPhaseBegin(TSL_PHASE_ASSEMBLY));
  PetscCall(Residual((TslProblem)ctx, ASM_RESIDUAL, X, F, NULL, &fail));
  PetscCall(TslPhaseEnd(TSL_PHASE_ASSEMBLY));
  if (fail) PetscCall(SNESSetFunctionDomainError(snes));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TslProblemFormJacobian(SNES snes, Vec X, Mat J, Mat P, void *ctx)
{
  TslProblem         p = (TslProblem)ctx;
  Vec                xl, xol;
  const PetscScalar *xa, *xoa;
  PetscInt           bad;
  TslFailure         fail;
  Mat                Ad = NULL;
  const PetscInt    *ja;

  PetscFunctionBeginUser;
  PetscCall(TslPhaseBegin(TSL_PHASE_ASSEMBLY));
  PetscCall(MatZeroEntries(P));
  PetscCall(GetStates(p, X, &xl, &xol, &xa, &xoa));
  if (P == p->J && p->blk) { /* direct insertion (BuildDirectMap) */
    PetscInt  nrow;
    PetscBool done;
    PetscCall(DiagonalBlock(P, &Ad));
    PetscCall(MatSeqAIJGetArray(Ad, &p->jac_val));
    PetscCall(MatGetRowIJ(Ad, 0, PETSC_FALSE, PETSC_FALSE, &nrow, &p->jac_row, &ja, &done));
    p->jac_col = ja;
  }
  PetscCall(AssembleLocal(p, ASM_JACOBIAN, xa, xoa, NULL, P, NULL, &bad, &fail));
  if (p->jac_val) {
    PetscInt  nrow;
    PetscBool done;
    PetscCall(MatSeqAIJRestoreArray(Ad, &p->jac_val));
    PetscCall(MatRestoreRowIJ(Ad, 0, PETSC_FALSE, PETSC_FALSE, &nrow, &p->jac_row, &ja, &done));
    p->jac_val = NULL, p->jac_row = NULL, p->jac_col = NULL;
  }
  PetscCall(ConstraintRows(p, ASM_JACOBIAN, xa, NULL, P));
  PetscCall(RestoreStates(p, &xl, &xol, &xa, &xoa));
  PetscCall(MatAssemblyBegin(P, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(P, MAT_FINAL_ASSEMBLY));
  PetscCall(TslPhaseEnd(TSL_PHASE_ASSEMBLY));
  PetscCall(AssembledBadElement(p, bad, &fail));
  if (fail) PetscCall(SNESSetJacobianDomainError(snes));
  if (J != P) {
    PetscCall(MatAssemblyBegin(J, MAT_FINAL_ASSEMBLY));
    PetscCall(MatAssemblyEnd(J, MAT_FINAL_ASSEMBLY));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The local diagonal block of the Jacobian (the matrix itself on one rank). */
static PetscErrorCode DiagonalBlock(Mat J, Mat *Ad)
{
  PetscBool mpi;

  PetscFunctionBeginUser;
  PetscCall(PetscObjectTypeCompare((PetscObject)J, MATMPIAIJ, &mpi));
  if (mpi) PetscCall(MatMPIAIJGetSeqAIJ(J, Ad, NULL, NULL));
  else *Ad = J;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The direct-insertion map (problem_impl.h) of the assembled pattern: for each element with owned nodes and
 * no row eliminated by an equation, the place of every node block in the CSR rows, found once by binary
 * search, so that a Jacobian assembly adds the element block without any search (MatSetValues looked up
 * every entry). Rows of prescribed or pinned dofs are skipped at insertion (InsertElement), so elements on
 * a boundary take this path too (two thirds of the 3D contact benchmark's elements: the base on its
 * supports, the thin block under its prescribed temperature). Every point row of a node with a free row
 * carries the node's whole column blocks (TslProblemPreallocate), so its first row's structure serves all;
 * a node without a free row has only its diagonal and no place (never read). */
static PetscErrorCode BuildDirectMap(TslProblem p, Mat J)
{
  const TslModel *m  = p->m;
  const PetscInt  bs = p->ndof;
  Mat             Ad;
  const PetscInt *ia, *ja;
  PetscInt        nrow;
  PetscBool       done;

  PetscFunctionBeginUser;
  PetscCall(PetscFree(p->blk_ptr));
  PetscCall(PetscFree(p->blk));
  PetscCall(PetscMalloc1(m->nelem + 1, &p->blk_ptr));
  p->blk_ptr[0] = 0;
  for (PetscInt e = 0; e < m->nelem; e++) {
    const PetscInt *ln = &p->elem_lnode[m->elem_ptr[e]], nb = m->elem_ptr[e + 1] - m->elem_ptr[e];
    PetscBool       ok = PETSC_TRUE;
    for (PetscInt a = 0; a < nb && ok; a++) {
      if (ln[a] >= p->nown) ok = PETSC_FALSE;
      for (PetscInt i = 0; i < bs && ok; i++)
        if (RowKind(p, ln[a] * bs + i) == 'e') ok = PETSC_FALSE;
    }
    p->blk_ptr[e + 1] = p->blk_ptr[e] + (ok ? nb * nb : 0);
  }
  PetscCall(PetscMalloc1(p->blk_ptr[m->nelem], &p->blk));
  PetscCall(DiagonalBlock(J, &Ad));
  PetscCall(MatGetRowIJ(Ad, 0, PETSC_FALSE, PETSC_FALSE, &nrow, &ia, &ja, &done));
  PetscCheck(done, PETSC_COMM_SELF, PETSC_ERR_PLIB, "no row structure of the Jacobian");
  for (PetscInt e = 0; e < m->nelem; e++) {
    const PetscInt *ln = &p->elem_lnode[m->elem_ptr[e]], nb = m->elem_ptr[e + 1] - m->elem_ptr[e];
    if (p->blk_ptr[e + 1] == p->blk_ptr[e]) continue;
    for (PetscInt a = 0; a < nb; a++) {
      const PetscInt r = ln[a] * bs, lo0 = ia[r], hi0 = ia[r + 1];
      PetscBool      free = PETSC_FALSE;
      for (PetscInt i = 0; i < bs; i++)
        if (RowKind(p, r + i) == 'f') free = PETSC_TRUE;
      if (!free) continue; /* all rows skipped at insertion */
      for (PetscInt b = 0; b < nb; b++) {
        const PetscInt place = BlockPlace(ja, lo0, hi0, bs, ln[b] * bs);
        PetscCheck(place >= 0 && place < 65536, PETSC_COMM_SELF, PETSC_ERR_PLIB, "Jacobian pattern without the element's node block");
        p->blk[p->blk_ptr[e] + a * nb + b] = (unsigned short)place;
      }
    }
  }
  PetscCall(MatRestoreRowIJ(Ad, 0, PETSC_FALSE, PETSC_FALSE, &nrow, &ia, &ja, &done));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The node graph of the owned rows from the pattern pass: the records of p->pattern_pairs (freed here)
 * counted and copied into rows (a counting sort: two sweeps, no search), each row's duplicates dropped with
 * a marker over the local nodes, its columns turned into global node numbers and sorted, and the rows that
 * other ranks sent through the preallocator (G, global rows rs.. of this rank's nodes) merged in. Linear in
 * the number of pairs; the hash of the MATPREALLOCATOR it replaces for the owned rows cost a cache miss per
 * pair and grew faster than the mesh. ia[nown + 1], ja: CSR to free. */
static PetscErrorCode PatternRows(TslProblem p, Mat G, PetscInt rs, PetscInt **ia, PetscInt **ja)
{
  const PetscInt  nown = p->nown, *gnum = p->m->node_gnum, *rec = p->pattern_pairs.rec, nrec = p->pattern_pairs.n;
  PetscInt       *start, *pos, *col, *mark, w = 0, lo = 0, gz;
  MatInfo         info;

  PetscFunctionBeginUser;
  PetscCall(PetscCalloc1(nown + 1, &start));
  for (PetscInt k = 0; k < nrec; k += 2 + rec[k] + rec[k + 1])
    for (PetscInt i = 0; i < rec[k]; i++) start[rec[k + 2 + i] + 1] += rec[k + 1];
  for (PetscInt r = 0; r < nown; r++) start[r + 1] += start[r];
  PetscCall(PetscMalloc1(start[nown], &col));
  PetscCall(PetscMalloc1(nown, &pos));
  PetscCall(PetscArraycpy(pos, start, nown));
  for (PetscInt k = 0; k < nrec; k += 2 + rec[k] + rec[k + 1])
    for (PetscInt i = 0; i < rec[k]; i++) {
      const PetscInt r = rec[k + 2 + i];
      PetscCall(PetscArraycpy(&col[pos[r]], &rec[k + 2 + rec[k]], rec[k + 1]));
      pos[r] += rec[k + 1];
    }
  PetscCall(PetscFree(pos));
  PetscCall(PetscFree(p->pattern_pairs.rec));
  p->pattern_pairs.n = p->pattern_pairs.cap = 0;
  /* in place: the unique columns of row r end before its first duplicate is read */
  PetscCall(PetscMalloc1(p->nn, &mark));
  for (PetscInt l = 0; l < p->nn; l++) mark[l] = -1;
  for (PetscInt r = 0; r < nown; r++) {
    const PetscInt hi = start[r + 1], first = w;
    for (PetscInt k = lo; k < hi; k++) {
      const PetscInt l = col[k];
      if (mark[l] != r) mark[l] = r, col[w++] = gnum[l];
    }
    PetscCall(PetscSortInt(w - first, &col[first]));
    start[r] = first, lo = hi;
  }
  start[nown] = w;
  PetscCall(PetscFree(mark));
  PetscCall(MatGetInfo(G, MAT_LOCAL, &info)); /* G holds only the rows other ranks sent (zeros where set) */
  gz = (PetscInt)info.nz_used;
  if (gz) { /* rows with contributions from other ranks: merged into a fresh array */
    PetscInt *merged, *mstart;
    PetscCall(PetscMalloc1(w + gz, &merged));
    PetscCall(PetscMalloc1(nown + 1, &mstart));
    mstart[0] = 0;
    for (PetscInt r = 0; r < nown; r++) {
      PetscInt        nc, n = start[r + 1] - start[r];
      const PetscInt *gc;
      PetscCall(PetscArraycpy(&merged[mstart[r]], &col[start[r]], n));
      PetscCall(MatGetRow(G, rs + r, &nc, &gc, NULL));
      PetscCall(PetscArraycpy(&merged[mstart[r] + n], gc, nc));
      n += nc; /* before MatRestoreRow, which zeroes nc */
      PetscCall(MatRestoreRow(G, rs + r, &nc, &gc, NULL));
      PetscCall(PetscSortRemoveDupsInt(&n, &merged[mstart[r]]));
      mstart[r + 1] = mstart[r] + n;
    }
    PetscCall(PetscFree(col));
    PetscCall(PetscFree(start));
    *ia = mstart, *ja = merged;
  } else *ia = start, *ja = col;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The pattern's zeros written into the preallocated J, each point row whole with its columns sorted
 * (MAT_SORTED_FULL: a copy per row instead of a search per entry). A parallel AIJ matrix takes them straight
 * into its two local blocks, the diagonal one (local rows and columns) and the off-diagonal one (global columns
 * until the assembly compacts them), as MatSetValues would put them entry by entry after a range test and a
 * search each (a third of the set-up phase of the 283 k peer block on 2 ranks); any other matrix (one rank)
 * takes global rows and columns. ja: sorted global nodes. */
static PetscErrorCode FillPattern(TslProblem p, Mat J, PetscInt rs, const PetscInt ia[], const PetscInt ja[], const PetscScalar zero[],
                                  PetscInt pcols[])
{
  const PetscInt bs = p->ndof;
  PetscBool      mpi;
  Mat            B[2] = {J, NULL}; /* where the diagonal and the off-diagonal columns go */
  PetscInt       ro = rs, co = 0;  /* row and diagonal column offsets (global node numbers to B's) */

  PetscFunctionBeginUser;
  PetscCall(PetscObjectTypeCompare((PetscObject)J, MATMPIAIJ, &mpi));
  if (mpi) {
    PetscCall(MatMPIAIJGetSeqAIJ(J, &B[0], &B[1], NULL));
    ro = 0, co = rs;
  }
  for (PetscInt b = 0; b < 2; b++)
    if (B[b]) {
      PetscBool    seq;
      PetscScalar *v;
      MatInfo      info;
      PetscCall(MatSetOption(B[b], MAT_SORTED_FULL, PETSC_TRUE));
      PetscCall(PetscObjectTypeCompare((PetscObject)B[b], MATSEQAIJ, &seq));
      if (!seq) continue;
      /* the new values array faulted in at once (TslPrefault): 1.1 GB at 1 M unknowns */
      PetscCall(MatGetInfo(B[b], MAT_LOCAL, &info));
      PetscCall(MatSeqAIJGetArray(B[b], &v));
      TslPrefault(v, sizeof(*v) * (size_t)info.nz_allocated);
      PetscCall(MatSeqAIJRestoreArray(B[b], &v));
      { /* and its column indices (the preallocated rows' starts and room) */
        const PetscInt *bi, *bj;
        PetscInt        n;
        PetscBool       done;
        PetscCall(MatGetRowIJ(B[b], 0, PETSC_FALSE, PETSC_FALSE, &n, &bi, &bj, &done));
        if (done) TslPrefault((void *)bj, sizeof(*bj) * (size_t)bi[n]);
        PetscCall(MatRestoreRowIJ(B[b], 0, PETSC_FALSE, PETSC_FALSE, &n, &bi, &bj, &done));
      }
    }
  for (PetscInt r = 0; r < p->nown; r++) {
    const PetscInt *cols = &ja[ia[r]], nc = ia[r + 1] - ia[r];
    PetscInt        d0 = 0, d1 = nc; /* cols[d0..d1) are the diagonal block's */
    if (mpi) {
      while (d0 < nc && cols[d0] < rs) d0++;
      d1 = d0;
      while (d1 < nc && cols[d1] < rs + p->nown) d1++;
    }
    for (PetscInt b = 0; b < 2; b++) {
      PetscInt n = 0;
      for (PetscInt k = 0; k < nc; k++) {
        const PetscBool diag = k >= d0 && k < d1 ? PETSC_TRUE : PETSC_FALSE;
        if (diag != (b == 0)) continue;
        for (PetscInt j = 0; j < bs; j++) pcols[n++] = (diag ? cols[k] - co : cols[k]) * bs + j;
      }
      for (PetscInt i = 0; i < bs && n; i++) {
        PetscInt row = (ro + r) * bs + i;
        PetscCall(MatSetValues(B[b], 1, &row, n, pcols, zero, INSERT_VALUES));
      }
    }
  }
  for (PetscInt b = 0; b < 2; b++)
    if (B[b]) PetscCall(MatSetOption(B[b], MAT_SORTED_FULL, PETSC_FALSE));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The Jacobian's pattern, exact by construction: the pattern pass runs the very insertion code of the
 * assembly (TslProblemInsert, ConstraintRows, contact), whose node pairs give the node blocks of each row
 * (PatternRows: the owned rows recorded locally, ghost rows through a node-level MATPREALLOCATOR to their
 * owners); the matrix is preallocated with whole ndof x ndof blocks and every block filled with zeros once,
 * so its structure never changes afterwards (MatZeroEntries keeps it) and elements without constrained
 * rows go in with one blocked call. Rows of prescribed dofs carry the explicit zeros of their node's blocks. */
PetscErrorCode TslProblemPreallocate(TslProblem p)
{
  Mat          pre, G, J;
  PetscInt     bad, rs, *dnz, *onz, maxc = 0, *pcols, *ia = NULL, *ja = NULL;
  PetscScalar *zero;
  TslFailure   fail;

  PetscFunctionBeginUser;
  /* the solver's preconditioner of the old pattern goes first (TslProblemSetRepatternCallback): the pattern
   * pass and the new matrix then come in its place, not on top of it */
  if (p->J && p->repattern) PetscCall(p->repattern(p->repattern_ctx));
  PetscCall(MatCreate(p->comm, &pre));
  PetscCall(MatSetSizes(pre, p->nown, p->nown, PETSC_DETERMINE, PETSC_DETERMINE));
  PetscCall(MatSetType(pre, MATPREALLOCATOR));
  PetscCall(MatSetLocalToGlobalMapping(pre, p->l2g_node, p->l2g_node));
  PetscCall(MatSetUp(pre));
  /* room for one record per element node row block; contact and constraints grow it */
  p->pattern_pairs.n   = 0;
  p->pattern_pairs.cap = 2 * p->m->nelem + 2 * p->m->elem_ptr[p->m->nelem] + 64;
  PetscCall(PetscMalloc1(p->pattern_pairs.cap, &p->pattern_pairs.rec));
  PetscCall(AssembleLocal(p, ASM_PATTERN, NULL, NULL, NULL, pre, NULL, &bad, &fail));
  PetscCall(ConstraintRows(p, ASM_PATTERN, NULL, NULL, pre));
  PetscCall(MatAssemblyBegin(pre, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(pre, MAT_FINAL_ASSEMBLY));
  PetscCall(MatCreate(p->comm, &G));
  PetscCall(MatSetSizes(G, p->nown, p->nown, PETSC_DETERMINE, PETSC_DETERMINE));
  PetscCall(MatSetType(G, MATAIJ));
  PetscCall(MatPreallocatorPreallocate(pre, PETSC_TRUE, G));
  PetscCall(MatDestroy(&pre));
  PetscCall(MatGetOwnershipRange(G, &rs, NULL));
  PetscCall(PatternRows(p, G, rs, &ia, &ja));
  PetscCall(MatDestroy(&G));

  PetscCall(PetscMalloc2(p->nown, &dnz, p->nown, &onz));
  for (PetscInt r = 0; r < p->nown; r++) {
    dnz[r] = onz[r] = 0;
    for (PetscInt k = ia[r]; k < ia[r + 1]; k++) {
      if (ja[k] >= rs && ja[k] < rs + p->nown) dnz[r]++;
      else onz[r]++;
    }
    maxc = PetscMax(maxc, ia[r + 1] - ia[r]);
  }
  if (p->J) {
    /* a new pattern (contact pairing or constraints changed): the same matrix object preallocated again,
     * which frees its old arrays before allocating the new ones. A second matrix beside the old one,
     * which the solver still references until it is handed the new one, raised the peak memory of the
     * 3D contact benchmark by the whole Jacobian (see docs/running.md "Contact at scale"). */
    J = p->J;
    p->J = NULL;
  } else {
    PetscCall(MatCreate(p->comm, &J));
    PetscCall(MatSetSizes(J, p->nown * p->ndof, p->nown * p->ndof, PETSC_DETERMINE, PETSC_DETERMINE));
    PetscCall(MatSetType(J, MATAIJ));
    PetscCall(MatSetBlockSize(J, p->ndof));
    PetscCall(MatSetFromOptions(J));
    PetscCall(MatSetLocalToGlobalMapping(J, p->l2g, p->l2g));
  }
  PetscCall(MatXAIJSetPreallocation(J, p->ndof, dnz, onz, NULL, NULL));
  PetscCall(PetscFree2(dnz, onz));
  PetscCall(PetscCalloc2(maxc * p->ndof, &zero, maxc * p->ndof, &pcols));
  PetscCall(FillPattern(p, J, rs, ia, ja, zero, pcols));
  PetscCall(PetscFree2(zero, pcols));
  PetscCall(PetscFree(ia));
  PetscCall(PetscFree(ja));
  PetscCall(MatAssemblyBegin(J, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(J, MAT_FINAL_ASSEMBLY));
  PetscCall(MatSetOption(J, MAT_NEW_NONZERO_ALLOCATION_ERR, PETSC_TRUE));
  PetscCall(BuildDirectMap(p, J));
  PetscCall(MatDestroy(&p->J));
  p->J = J;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* A step whose constraints leave every row as it was keeps the matrix (its pattern depends on the rows'
 * kinds and the contact pairing only; the contact search rebuilds it itself when the pairing changes).
 * Collective: rebuilt when any rank's rows changed. */
PetscErrorCode TslProblemPreallocateIfChanged(TslProblem p)
{
  const PetscInt n = p->nn * p->ndof;
  PetscInt       changed = 0, any;

  PetscFunctionBeginUser;
  if (!p->pattern_rows) {
    PetscCall(PetscCalloc1(n, &p->pattern_rows));
    changed = 1;
  }
  for (PetscInt d = 0; d < n; d++) {
    char kind = RowKind(p, d);
    if (p->pattern_rows[d] != kind) changed = 1, p->pattern_rows[d] = kind;
  }
  PetscCall(MPIU_Allreduce(&changed, &any, 1, MPIU_INT, MPI_MAX, p->comm));
  if (any || !p->J) PetscCall(TslProblemPreallocate(p));
  else PetscCall(PetscInfo(NULL, "constraints unchanged: the Jacobian's pattern is kept\n"));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The totals of the solved state from one raw residual pass (every element row, prescribed ones too): the
 * reactions at prescribed temperatures, the face, nodal and contact heat, the heat stored over the increment,
 * sum_a Q(theta_a) - Q(theta_old_a) (the residual's own heat content, lumped or consistent, so that heat in - heat out - stored
 * closes to solver tolerance), and the elements' strain and hourglass energies (TslElementInternalEnergy:
 * an implicit increment's history row costs one element pass, not three). */
PetscErrorCode TslProblemHeatBalance(TslProblem p, TslHeatBalance *hb)
{
  AsmHeat            heat;
  const PetscScalar *r;
  PetscReal          loc[12] = {0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0}, g[12];
  TslFailure         fail;

  PetscFunctionBeginUser;
  p->pstate_write = p->pstate ? PETSC_TRUE : PETSC_FALSE; /* the plastic state at this solution, for TslProblemCommitState */
  PetscCall(Residual(p, ASM_RAW, p->X, p->Rraw, &heat, &fail));
  p->pstate_write = PETSC_FALSE;
  /* the state was solved, so its contact projections exist: a failure here is not a cutback matter */
  PetscCheck(!fail, p->comm, PETSC_ERR_PLIB, "%s", p->fail_msg);
  PetscCall(VecGetArrayRead(p->Rraw, &r));
  for (PetscInt n = 0; n < p->nown; n++) {
    PetscInt d = n * p->ndof + p->ndof - 1;
    if (p->bc[d].active) loc[2] += PetscRealPart(r[d]);
  }
  PetscCall(VecRestoreArrayRead(p->Rraw, &r));
  loc[0] = heat.flux_in;
  loc[1] = -heat.film;
  loc[4] = heat.interface;
  loc[5] = heat.dissipation;
  loc[6] = heat.friction_heat;
  loc[3] = heat.stored * p->shift;
  loc[7] = heat.energy[0];
  loc[8] = heat.energy[1];
  loc[9]  = -heat.radiation;
  loc[10] = heat.plastic_work;
  loc[11] = heat.plastic_heat;
  PetscCall(MPIU_Allreduce(loc, g, 12, MPIU_REAL, MPIU_SUM, p->comm));
  hb->heat_in          = g[0];
  hb->film_out         = g[1];
  hb->radiation_out    = g[9];
  hb->reaction_heat    = g[2];
  hb->stored_rate      = g[3];
  hb->interface_heat   = g[4];
  hb->dissipation      = g[5];
  hb->friction_heat    = g[6];
  hb->plastic_work     = g[10];
  hb->plastic_heat     = g[11];
  hb->balance          = g[0] + g[2] + g[6] + g[11] - g[1] - g[9] - g[3];
  hb->strain_energy    = g[7];
  hb->hourglass_energy = g[8];
  PetscFunctionReturn(PETSC_SUCCESS);
}
