/* The default preconditioner of the implicit steps: the temperature-displacement block Gauss-Seidel of
 * PETSc's multiplicative field split (temperature first, then the displacement with the coupling block's
 * update), built so that the displacement block is held once.
 *
 * PCFIELDSPLIT extracts the displacement block as an AIJ matrix and keeps it for the next set-up, and
 * BoomerAMG (PCHYPRE) copies it again into hypre's format: with the Jacobian, the block's values were
 * held three times. Here, when the displacement solver is hypre, the block is written straight into hypre's
 * ParCSR arrays and handed to PCHYPRE as a MATHYPRE matrix, which it takes without a copy (HypreBlock), and
 * later set-ups on the same pattern refresh its values in place (HypreValues): the 3D contact benchmark's
 * peak memory at N = 128 fell from 1 205 to 1 046 MB when the AIJ copy went (docs/running.md "Contact at
 * scale"), and at N = 64 from 320 to 296 MB when the extract did. The temperature block (a sixteenth of the
 * Jacobian in 3D) and the coupling block (displacement rows, temperature columns) stay AIJ extracts,
 * reused while the pattern is unchanged. The arithmetic is the field split's: y_T = B_T^-1 b_T,
 * y_u = B_u^-1 (b_u - A_uT y_T).
 *
 * The blocks are cut straight from the Jacobian's CSR arrays (CheckDirect, Extract): in thermoslide's
 * node-interleaved layout a column's field and its index in the field are arithmetic, so the extraction is
 * one streaming pass per block with no communication and no index set gathered; PETSc's MatCreateSubMatrix
 * (the fallback for any other layout or matrix type) had taken 7.0 of the 15.7 s of the preconditioner's
 * set-up at 1 M unknowns on one rank, 4.4 of 10.9 s on two.
 *
 * The sub-solvers keep the field split's options prefixes (-fieldsplit_T_..., -fieldsplit_u_...), so the
 * defaults and a user's sub-solver options apply unchanged; -pc_fieldsplit_type additive drops the coupling
 * update; anything else of PETSc's field split (Schur, more splits) is `-pc_type fieldsplit`. */
#include "solve_impl.h"
#include <string.h>
#include <petscmathypre.h>
#include <_hypre_parcsr_mv.h>
#include <_hypre_parcsr_ls.h>
#include <petsc/private/pcimpl.h>

/* A block's CSR arrays, owned here: the AIJ matrix made on them does not copy them. Diagonal part with
 * local columns; off-diagonal part (several ranks) with global columns, which PETSc compacts in place to
 * local ones when the matrix is assembled (values keep their order). */
typedef struct {
  PetscInt     m, *i, *j, *oi, *oj;
  PetscScalar *a, *oa;
} Arrays;

typedef struct {
  IS               is[2];  /* temperature, displacement */
  KSP              ksp[2]; /* sub-solvers */
  Mat              A[2];   /* the blocks as the sub-solvers hold them (AIJ extract, or hypre's ParCSR) */
  Mat              Aut;    /* displacement rows, temperature columns */
  PetscBool        aut_stale; /* Aut's values are not this operator's (block solves: the coupling goes through the operator) */
  Vec              zf, wf;    /* whole-operator work vectors for that product */
  VecScatter       sc[2];  /* global vector -> block vectors */
  Vec              x[2], y[2], w;
  PetscBool        additive; /* -pc_fieldsplit_type additive */
  PetscObjectState state;    /* nonzero state of the operator the blocks were extracted from */
  Mat              from;     /* ... and the operator itself (not referenced) */
  /* direct extraction (Extract): the dof slots of each field within a node, the position of each slot in
   * its field (-1: another field's), and the CSR arrays under the persistent AIJ blocks */
  PetscBool        direct;
  PetscInt         ndof, nslot[2], slot[2][8], pos[2][8];
  Arrays           arr[3]; /* temperature block, coupling block, displacement block (when not hypre's) */
  /* block solves (Triangular): an operator whose temperature rows have no displacement entries is block
   * triangular, and the split then solves each block by CG to the outer solve's tolerance, so the outer
   * Krylov method converges in one iteration */
  KSP       outer;       /* the Krylov method this split preconditions (not referenced): its tolerance */
  PetscBool tri_allowed; /* the sub-solvers' Krylov types are thermoslide's defaults (preonly) */
  PetscBool tri;         /* this operator is block triangular: the blocks are solved by CG */
  PetscBool tri_failed;  /* a CG block solve failed on this pattern: one cycle per block until it changes */
  PetscBool coupled;     /* a displacement entry in a temperature row here (the temperature block's extraction) */
  PetscInt  extra;       /* displacement cycles beyond one per application, since TslSplitTakeExtraCycles */
  /* weighted-Jacobi smoothing on a BoomerAMG hierarchy (JacobiWeights): omega_l = jacobi_scale / lambda_l */
  PetscReal jacobi_scale;                 /* 0: hypre's weights */
  PetscInt  nweight[2];                   /* levels weighted, per block (0: none) */
  PetscReal weight[2][32], lambda[2][32]; /* per level: the weight and the estimate it came from */
  PetscBool amg_cycle;                    /* -tsl_amg_cycle: BoomerAMG's V-cycle applied by amg.c where it can */
  PetscBool cycled[2];                    /* ... and applied so, per block */
} Split;

static const char *const prefix[2] = {"fieldsplit_T_", "fieldsplit_u_"};

static PetscErrorCode CreateSubSolver(PC pc, Split *s, PetscInt i)
{
  const char *pre;

  PetscFunctionBeginUser;
  PetscCall(KSPCreate(PetscObjectComm((PetscObject)pc), &s->ksp[i]));
  PetscCall(PetscObjectIncrementTabLevel((PetscObject)s->ksp[i], (PetscObject)pc, 1));
  PetscCall(PCGetOptionsPrefix(pc, &pre));
  PetscCall(KSPSetOptionsPrefix(s->ksp[i], pre));
  PetscCall(KSPAppendOptionsPrefix(s->ksp[i], prefix[i]));
  PetscCall(KSPSetFromOptions(s->ksp[i]));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode FreeArrays(Arrays *b)
{
  PetscFunctionBeginUser;
  PetscCall(PetscFree(b->i));
  PetscCall(PetscFree(b->j));
  PetscCall(PetscFree(b->a));
  PetscCall(PetscFree(b->oi));
  PetscCall(PetscFree(b->oj));
  PetscCall(PetscFree(b->oa));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Whether the blocks can be cut straight from the operator's CSR arrays: an AIJ matrix in thermoslide's
 * node-interleaved layout (block size ndof, every rank owning whole nodes), each field a fixed set of dof
 * slots of every node (read off the index sets). Then a column's field and its index in the field's
 * numbering are arithmetic, (c / ndof) nC + pos[c % ndof], for local and global columns alike: no
 * communication, no index set gathered. PETSc's MatCreateSubMatrix and the AIJ-to-hypre conversion had
 * been most of the preconditioner's set-up (1 M unknowns: 7.0 s + 3.9 s of 15.7 s on one rank). */
static PetscErrorCode CheckDirect(Split *s, Mat P)
{
  PetscBool seq, mpi;
  PetscInt  bs, rs, re;

  PetscFunctionBeginUser;
  s->direct = PETSC_FALSE;
  PetscCall(PetscObjectBaseTypeCompare((PetscObject)P, MATSEQAIJ, &seq));
  PetscCall(PetscObjectBaseTypeCompare((PetscObject)P, MATMPIAIJ, &mpi));
  PetscCall(MatGetBlockSize(P, &bs));
  PetscCall(MatGetOwnershipRange(P, &rs, &re));
  if (!(seq || mpi) || bs < 1 || bs > 8 || rs % bs || re % bs) PetscFunctionReturn(PETSC_SUCCESS);
  s->ndof = bs;
  for (PetscInt f = 0; f < 2; f++) {
    const PetscInt *idx;
    PetscInt        n, nn = (re - rs) / bs, ns;
    PetscBool       ok;
    PetscCall(ISGetLocalSize(s->is[f], &n));
    if (nn == 0 || n % nn) PetscFunctionReturn(PETSC_SUCCESS);
    ns = n / nn;
    if (ns < 1 || ns > bs) PetscFunctionReturn(PETSC_SUCCESS);
    PetscCall(ISGetIndices(s->is[f], &idx));
    for (PetscInt k = 0; k < bs; k++) s->pos[f][k] = -1;
    for (PetscInt k = 0; k < ns; k++) s->slot[f][k] = (idx[k] - rs) % bs, s->pos[f][s->slot[f][k]] = k;
    ok = PETSC_TRUE;
    for (PetscInt q = 0; q < nn && ok; q++)
      for (PetscInt k = 0; k < ns && ok; k++) ok = (PetscBool)(idx[q * ns + k] == rs + q * bs + s->slot[f][k]);
    PetscCall(ISRestoreIndices(s->is[f], &idx));
    if (!ok) PetscFunctionReturn(PETSC_SUCCESS);
    s->nslot[f] = ns;
  }
  s->direct = PETSC_TRUE;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The operator's local CSR arrays, read-only: the diagonal part (local columns) and, on several ranks, the
 * off-diagonal part (columns through garray, increasing in global order); nn owned nodes. The extraction
 * (the AIJ blocks, hypre's displacement block and its refresh) reads them, nothing writes them. */
typedef struct {
  Mat                Ad, Ao;
  const PetscInt    *garray, *ia, *ja, *oia, *oja;
  const PetscScalar *aa, *oaa;
  PetscInt           rs, re, nn;
  PetscBool          mpi;
} Csr;

static PetscLogEvent ExtractEvent;

/* Opens P's arrays and starts the extraction's log event (CsrRestore ends both). */
static PetscErrorCode CsrGet(const Split *s, Mat P, Csr *c)
{
  PetscInt  n;
  PetscBool done;

  PetscFunctionBeginUser;
  if (!ExtractEvent) PetscCall(PetscLogEventRegister("TslSplitExtract", MAT_CLASSID, &ExtractEvent));
  PetscCall(PetscLogEventBegin(ExtractEvent, P, 0, 0, 0));
  PetscCall(PetscMemzero(c, sizeof(*c)));
  PetscCall(MatGetOwnershipRange(P, &c->rs, &c->re));
  c->nn = (c->re - c->rs) / s->ndof;
  PetscCall(PetscObjectBaseTypeCompare((PetscObject)P, MATMPIAIJ, &c->mpi));
  if (c->mpi) PetscCall(MatMPIAIJGetSeqAIJ(P, &c->Ad, &c->Ao, &c->garray));
  else c->Ad = P;
  PetscCall(MatGetRowIJ(c->Ad, 0, PETSC_FALSE, PETSC_FALSE, &n, &c->ia, &c->ja, &done));
  PetscCheck(done, PETSC_COMM_SELF, PETSC_ERR_PLIB, "no row structure of the operator");
  PetscCall(MatSeqAIJGetArrayRead(c->Ad, &c->aa));
  if (c->Ao) {
    PetscCall(MatGetRowIJ(c->Ao, 0, PETSC_FALSE, PETSC_FALSE, &n, &c->oia, &c->oja, &done));
    PetscCheck(done, PETSC_COMM_SELF, PETSC_ERR_PLIB, "no row structure of the operator");
    PetscCall(MatSeqAIJGetArrayRead(c->Ao, &c->oaa));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode CsrRestore(Mat P, Csr *c)
{
  PetscInt  n;
  PetscBool done;

  PetscFunctionBeginUser;
  PetscCall(MatSeqAIJRestoreArrayRead(c->Ad, &c->aa));
  PetscCall(MatRestoreRowIJ(c->Ad, 0, PETSC_FALSE, PETSC_FALSE, &n, &c->ia, &c->ja, &done));
  if (c->Ao) {
    PetscCall(MatSeqAIJRestoreArrayRead(c->Ao, &c->oaa));
    PetscCall(MatRestoreRowIJ(c->Ao, 0, PETSC_FALSE, PETSC_FALSE, &n, &c->oia, &c->oja, &done));
  }
  PetscCall(PetscLogEventEnd(ExtractEvent, P, 0, 0, 0));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Rows of field rf and columns of field cf of P into b. fill: 0 counts the rows (b->i, b->oi), 1 fills the
 * columns and values, 2 the values alone (the pattern of an earlier fill). */
static PetscErrorCode Extract(Split *s, Mat P, PetscInt rf, PetscInt cf, PetscInt fill, Arrays *b)
{
  const PetscInt  bs = s->ndof, nr = s->nslot[rf], nc = s->nslot[cf], *pc = s->pos[cf];
  const PetscBool tcoupling = rf == 0 && cf == 0 && fill > 0; /* the temperature block's values: also watch its rows' other entries */
  Csr             c;

  PetscFunctionBeginUser;
  if (tcoupling) s->coupled = PETSC_FALSE;
  PetscCall(CsrGet(s, P, &c));
  if (fill == 0) {
    b->m = c.nn * nr;
    PetscCall(PetscMalloc1(b->m + 1, &b->i));
    if (c.mpi) PetscCall(PetscMalloc1(b->m + 1, &b->oi));
    b->i[0] = 0;
    if (c.mpi) b->oi[0] = 0;
  } else if (fill == 1) {
    PetscCall(PetscMalloc1(b->i[b->m], &b->j));
    PetscCall(PetscMalloc1(b->i[b->m], &b->a));
    if (c.mpi) PetscCall(PetscMalloc1(b->oi[b->m], &b->oj));
    if (c.mpi) PetscCall(PetscMalloc1(b->oi[b->m], &b->oa));
    TslPrefault(b->j, sizeof(*b->j) * (size_t)b->i[b->m]), TslPrefault(b->a, sizeof(*b->a) * (size_t)b->i[b->m]);
    if (c.mpi) TslPrefault(b->oj, sizeof(*b->oj) * (size_t)b->oi[b->m]), TslPrefault(b->oa, sizeof(*b->oa) * (size_t)b->oi[b->m]);
  }
  for (PetscInt q = 0, row = 0; q < c.nn; q++)
    for (PetscInt k = 0; k < nr; k++, row++) {
      const PetscInt r = q * bs + s->slot[rf][k];
      PetscInt       d = fill ? b->i[row] : 0, o = fill && c.mpi ? b->oi[row] : 0;
      for (PetscInt e = c.ia[r]; e < c.ia[r + 1]; e++) {
        const PetscInt col = c.ja[e], p = pc[col % bs];
        if (p < 0) {
          if (tcoupling && c.aa[e] != 0 && s->pos[1][col % bs] >= 0) s->coupled = PETSC_TRUE;
          continue;
        }
        if (fill == 1) b->j[d] = (col / bs) * nc + p;
        if (fill) b->a[d] = c.aa[e];
        d++;
      }
      for (PetscInt e = c.Ao ? c.oia[r] : 0; c.Ao && e < c.oia[r + 1]; e++) {
        const PetscInt g = c.garray[c.oja[e]], p = pc[g % bs];
        if (p < 0) {
          if (tcoupling && c.oaa[e] != 0 && s->pos[1][g % bs] >= 0) s->coupled = PETSC_TRUE;
          continue;
        }
        if (fill == 1) b->oj[o] = (g / bs) * nc + p;
        if (fill) b->oa[o] = c.oaa[e];
        o++;
      }
      if (fill == 0) {
        b->i[row + 1] = b->i[row] + d;
        if (c.mpi) b->oi[row + 1] = b->oi[row] + o;
      } else PetscCheck(d == b->i[row + 1] && (!c.mpi || o == b->oi[row + 1]), PETSC_COMM_SELF, PETSC_ERR_PLIB, "operator pattern changed under its block");
    }
  PetscCall(CsrRestore(P, &c));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Whether every temperature row of the operator has only zeros in displacement columns (on every rank), as the
 * temperature block's extraction of this set-up found (Extract): then the operator is block triangular
 * (temperature first) and the multiplicative split with exact block solves is its inverse. That holds for any
 * model without contact (the heat equation does not depend on the displacements in small strain); a contact
 * pair's conductance or frictional heat puts displacement entries in the temperature rows. Collective. */
static PetscErrorCode Triangular(Split *s, MPI_Comm comm, PetscBool *tri)
{
  PetscBool coupled = s->coupled;

  PetscFunctionBeginUser;
  PetscCall(MPIU_Allreduce(MPI_IN_PLACE, &coupled, 1, MPIU_BOOL, MPI_LOR, comm));
  *tri = (PetscBool)!coupled;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The sub-solvers' Krylov method: CG with the true residual norm for block solves, else one preconditioner
 * application (the default preonly). Changing it keeps the sub-solver's preconditioner and hierarchy. */
static PetscErrorCode SubSolverMode(Split *s, PetscBool tri)
{
  PetscFunctionBeginUser;
  s->tri = tri;
  for (PetscInt i = 0; i < 2; i++) {
    PetscInt    maxit = 500;
    const char *pre;
    PetscCall(KSPSetType(s->ksp[i], tri ? KSPCG : KSPPREONLY));
    PetscCall(KSPSetNormType(s->ksp[i], tri ? KSP_NORM_UNPRECONDITIONED : KSP_NORM_NONE));
    /* at most 500 CG iterations before the fallback to one cycle, or the user's -fieldsplit_{T,u}_ksp_max_it
     * (which PETSc does not read for a preonly solver) */
    PetscCall(KSPGetOptionsPrefix(s->ksp[i], &pre));
    PetscCall(PetscOptionsGetInt(NULL, pre, "-ksp_max_it", &maxit, NULL));
    if (tri) PetscCall(KSPSetTolerances(s->ksp[i], PETSC_DEFAULT, PETSC_DEFAULT, PETSC_DEFAULT, maxit));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The displacement block (rows and columns of field 1) built straight into hypre's ParCSR format and
 * wrapped as a MATHYPRE matrix, which PCHYPRE takes without a copy: one counting pass and one filling pass
 * over the Jacobian's CSR arrays, no intermediate AIJ extract and no conversion (MatConvert had cost 1.0 s
 * of the 3.3 s preconditioner set-up of the 283 k-unknown block, and the extract coexisted with hypre's copy
 * at the set-up's memory peak). The layout is the one hypre's own assembly of the converted extract makes,
 * so the arithmetic is unchanged: each row's columns in the Jacobian's order with the diagonal swapped into
 * the first place, the off-rank columns numbered in increasing global order (col_map_offd). */
static PetscErrorCode HypreBlock(PC pc, Split *s, Mat P, Mat *H)
{
  const PetscInt      bs = s->ndof, nr = s->nslot[1], *pos = s->pos[1];
  PetscInt            N, nB = 0, nd = 0, no = 0, ncol = 0, *lk = NULL;
  HYPRE_BigInt        range[2];
  hypre_ParCSRMatrix *A;
  hypre_CSRMatrix    *D, *O;
  HYPRE_Int          *di, *dj, *oi, *oj;
  HYPRE_Complex      *da, *oa;
  HYPRE_BigInt       *cmap;
  Csr                 c;

  PetscFunctionBeginUser;
  PetscCall(MatGetSize(P, &N, NULL));
  PetscCall(CsrGet(s, P, &c));
  if (c.Ao) {
    PetscCall(MatGetSize(c.Ao, NULL, &nB));
    PetscCall(PetscCalloc1(nB, &lk));
  }
  /* counts, and the off-rank columns the block uses (numbered in garray's, i.e. increasing global, order) */
  for (PetscInt q = 0; q < c.nn; q++)
    for (PetscInt k = 0; k < nr; k++) {
      const PetscInt r = q * bs + s->slot[1][k];
      for (PetscInt e = c.ia[r]; e < c.ia[r + 1]; e++) nd += pos[c.ja[e] % bs] >= 0;
      for (PetscInt e = c.Ao ? c.oia[r] : 0; c.Ao && e < c.oia[r + 1]; e++)
        if (pos[c.garray[c.oja[e]] % bs] >= 0) no++, lk[c.oja[e]] = 1;
    }
  for (PetscInt k = 0; k < nB; k++) lk[k] = lk[k] ? ncol++ : -1;
  range[0] = c.rs / bs * nr, range[1] = c.re / bs * nr;
  A = hypre_ParCSRMatrixCreate(PetscObjectComm((PetscObject)pc), N / bs * nr, N / bs * nr, range, range, (HYPRE_Int)ncol, (HYPRE_Int)nd,
                               (HYPRE_Int)no);
  PetscCheck(A, PETSC_COMM_SELF, PETSC_ERR_LIB, "hypre could not create the displacement block");
  PetscCallExternal(hypre_ParCSRMatrixInitialize_v2, A, HYPRE_MEMORY_HOST);
  D = hypre_ParCSRMatrixDiag(A), O = hypre_ParCSRMatrixOffd(A);
  di = hypre_CSRMatrixI(D), dj = hypre_CSRMatrixJ(D), da = hypre_CSRMatrixData(D);
  oi = hypre_CSRMatrixI(O), oj = hypre_CSRMatrixJ(O), oa = hypre_CSRMatrixData(O);
  cmap = hypre_ParCSRMatrixColMapOffd(A);
  TslPrefault(dj, sizeof(*dj) * (size_t)nd), TslPrefault(da, sizeof(*da) * (size_t)nd);
  TslPrefault(oj, sizeof(*oj) * (size_t)no), TslPrefault(oa, sizeof(*oa) * (size_t)no);
  for (PetscInt k = 0; k < nB; k++)
    if (lk[k] >= 0) cmap[lk[k]] = (HYPRE_BigInt)((c.garray[k] / bs) * nr + pos[c.garray[k] % bs]);
  di[0] = oi[0] = 0;
  for (PetscInt q = 0, row = 0, d = 0, o = 0; q < c.nn; q++)
    for (PetscInt k = 0; k < nr; k++, row++) {
      const PetscInt r = q * bs + s->slot[1][k], d0 = d;
      for (PetscInt e = c.ia[r]; e < c.ia[r + 1]; e++) {
        const PetscInt col = c.ja[e], p = pos[col % bs];
        if (p < 0) continue;
        dj[d] = (HYPRE_Int)((col / bs) * nr + p), da[d] = c.aa[e];
        d++;
      }
      for (PetscInt e = d0; e < d; e++) /* hypre's convention: the diagonal first, swapped with the first entry */
        if (dj[e] == row) {
          const HYPRE_Complex t = da[e];
          da[e] = da[d0], da[d0] = t, dj[e] = dj[d0], dj[d0] = (HYPRE_Int)row;
          break;
        }
      di[row + 1] = (HYPRE_Int)d;
      for (PetscInt e = c.Ao ? c.oia[r] : 0; c.Ao && e < c.oia[r + 1]; e++) {
        if (pos[c.garray[c.oja[e]] % bs] < 0) continue;
        oj[o] = (HYPRE_Int)lk[c.oja[e]], oa[o] = c.oaa[e];
        o++;
      }
      oi[row + 1] = (HYPRE_Int)o;
    }
  PetscCallExternal(hypre_CSRMatrixSetRownnz, D);
  PetscCallExternal(hypre_CSRMatrixSetRownnz, O);
  PetscCall(PetscFree(lk));
  PetscCall(CsrRestore(P, &c));
  PetscCall(MatCreateFromParCSR(A, MATHYPRE, PETSC_OWN_POINTER, H));
  PetscCall(MatSetBlockSizes(*H, nr, nr));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* New values of the Jacobian into the displacement block H that HypreBlock made on the same pattern: each row's
 * values in the Jacobian's order, then the diagonal swapped first as HypreBlock placed it. H's state is raised,
 * so that BoomerAMG builds its next hierarchy on it (freeing the previous one as it starts). Set-ups after the
 * first of a pattern (the Newton iterations of an increment, the increments of a step) so skip the block's
 * allocation, whose pages the kernel clears on first touch, and the column pass. */
static PetscErrorCode HypreValues(Split *s, Mat P, Mat H)
{
  const PetscInt      bs = s->ndof, nr = s->nslot[1], *pos = s->pos[1];
  hypre_ParCSRMatrix *A;
  HYPRE_Complex      *da, *oa;
  const HYPRE_Int    *di, *oi;
  Csr                 c;

  PetscFunctionBeginUser;
  PetscCall(MatHYPREGetParCSR(H, &A));
  di = hypre_CSRMatrixI(hypre_ParCSRMatrixDiag(A)), da = hypre_CSRMatrixData(hypre_ParCSRMatrixDiag(A));
  oi = hypre_CSRMatrixI(hypre_ParCSRMatrixOffd(A)), oa = hypre_CSRMatrixData(hypre_ParCSRMatrixOffd(A));
  PetscCall(CsrGet(s, P, &c));
  for (PetscInt q = 0, row = 0; q < c.nn; q++)
    for (PetscInt k = 0; k < nr; k++, row++) {
      const PetscInt r = q * bs + s->slot[1][k], d0 = di[row];
      PetscInt       d = d0, o = oi[row], dg = -1;
      for (PetscInt e = c.ia[r]; e < c.ia[r + 1]; e++) {
        const PetscInt col = c.ja[e], p = pos[col % bs];
        if (p < 0) continue;
        if (dg < 0 && (col / bs) * nr + p == row) dg = d;
        da[d++] = c.aa[e];
      }
      PetscCheck(d == di[row + 1], PETSC_COMM_SELF, PETSC_ERR_PLIB, "operator pattern changed under its block");
      if (dg > d0) {
        const HYPRE_Complex t = da[dg];
        da[dg] = da[d0], da[d0] = t;
      }
      for (PetscInt e = c.Ao ? c.oia[r] : 0; c.Ao && e < c.oia[r + 1]; e++)
        if (pos[c.garray[c.oja[e]] % bs] >= 0) oa[o++] = c.oaa[e];
      PetscCheck(o == oi[row + 1], PETSC_COMM_SELF, PETSC_ERR_PLIB, "operator pattern changed under its block");
    }
  PetscCall(CsrRestore(P, &c));
  /* raises H's state (hypre's assembly of an assembled matrix changes nothing) */
  PetscCall(MatAssemblyBegin(H, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(H, MAT_FINAL_ASSEMBLY));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The block (rows rf, columns cf) as an AIJ matrix on arrays b: made at the first call, its values
 * refreshed in place afterwards. */
static PetscErrorCode Block(PC pc, Split *s, Mat P, PetscInt rf, PetscInt cf, Arrays *b, Mat *B)
{
  PetscFunctionBeginUser;
  if (*B) {
    PetscCall(Extract(s, P, rf, cf, 2, b));
    /* the values changed under the matrix: assembling again drops its value caches and raises its state,
     * so that its solver sets up again */
    PetscCall(MatAssemblyBegin(*B, MAT_FINAL_ASSEMBLY));
    PetscCall(MatAssemblyEnd(*B, MAT_FINAL_ASSEMBLY));
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  PetscCall(Extract(s, P, rf, cf, 0, b));
  PetscCall(Extract(s, P, rf, cf, 1, b));
  {
    PetscMPIInt size;
    PetscInt    nrow, ncol, N, nn;
    MPI_Comm    comm = PetscObjectComm((PetscObject)pc);
    PetscCallMPI(MPI_Comm_size(comm, &size));
    nn   = b->m / s->nslot[rf];
    nrow = b->m, ncol = nn * s->nslot[cf];
    PetscCall(MatGetSize(P, &N, NULL));
    if (size == 1) PetscCall(MatCreateSeqAIJWithArrays(comm, nrow, ncol, b->i, b->j, b->a, B));
    else
      PetscCall(MatCreateMPIAIJWithSplitArrays(comm, nrow, ncol, N / s->ndof * s->nslot[rf], N / s->ndof * s->nslot[cf], b->i, b->j, b->a, b->oi, b->oj,
                                               b->oa, B));
    PetscCall(MatSetBlockSizes(*B, s->nslot[rf], s->nslot[cf]));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Frees the blocks and sub-solvers (a new pattern, or the end). */
PetscErrorCode TslSplitReset(PC pc)
{
  Split *s;

  PetscFunctionBeginUser;
  s = (Split *)pc->data;
  if (!s) PetscFunctionReturn(PETSC_SUCCESS);
  for (PetscInt i = 0; i < 2; i++) {
    PetscCall(KSPDestroy(&s->ksp[i]));
    PetscCall(MatDestroy(&s->A[i]));
    PetscCall(VecScatterDestroy(&s->sc[i]));
    PetscCall(VecDestroy(&s->x[i]));
    PetscCall(VecDestroy(&s->y[i]));
  }
  PetscCall(MatDestroy(&s->Aut));
  PetscCall(VecDestroy(&s->zf));
  PetscCall(VecDestroy(&s->wf));
  for (PetscInt i = 0; i < 3; i++) PetscCall(FreeArrays(&s->arr[i]));
  PetscCall(VecDestroy(&s->w));
  s->from       = NULL;
  s->tri        = PETSC_FALSE;
  s->tri_failed = PETSC_FALSE;
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode Destroy(PC pc)
{
  Split *s;

  PetscFunctionBeginUser;
  PetscCall(TslSplitReset(pc));
  s = (Split *)pc->data;
  PetscCall(ISDestroy(&s->is[0]));
  PetscCall(ISDestroy(&s->is[1]));
  PetscCall(PetscFree(pc->data));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Weighted-Jacobi smoothing with a weight per level from that level's spectrum. BoomerAMG's Jacobi sweep
 * x += omega D^-1 (b - A x) reads the level's matrix once, a third of a Chebyshev sweep of order 2 (a residual
 * and two products), but hypre gives every level one fixed weight or a conservative estimate of its own. Here
 * each level but the coarsest (solved directly) gets omega_l = jacobi_scale / (1.1 lambda_l), lambda_l the
 * largest eigenvalue of D^-1 A_l estimated by ten Lanczos (CG) steps, hypre's own estimator for its Chebyshev
 * smoother, which converges to the top of the spectrum from below (the steady block's finest level: 2.99
 * after ten steps against 3.086 from 1 000 power iterations; C3D10MT 3.18 against 3.20); the factor 1.1
 * covers the rest, and a sweep is a convergent smoother while omega_l lambda_l < 2 (jacobi_scale 1.6 gives
 * 1.45-1.5). Gershgorin's bound (max over rows of sum |a_ij| / a_ii, one pass) caps the estimate: on the
 * unsymmetric displacement block of a contact model Lanczos returned 7.4 against a bound of 5.5 (and 3.2
 * by power iteration). Measured on the peer benchmark's block (docs/running.md): 38-40 CG iterations for
 * 32 with Chebyshev, the linear solve 22 % faster; the estimates cost what Chebyshev's own set-up spends
 * on the same estimates. Applied when both sweeps of the block's BoomerAMG are Jacobi and the user gave no
 * -..._pc_hypre_boomeramg_relax_weight_all of their own; computed at every set-up of the split, which
 * follows a new operator and so a new hierarchy (hypre keeps a level's weight until it is set again: a
 * weight cached across set-ups could belong to an older hierarchy). The hypre solver is the first member of PETSc's PCHYPRE context (3.18 and since);
 * its finest level is checked against the block before anything is written. */
/* Gershgorin's bound on the spectrum of D^-1 A: the largest row sum of |a_ij| / a_ii over all ranks, one
 * streaming pass over the level's local rows (hypre's hypre_ParCSRMaxEigEstimate computes the same bound in
 * about five times the time). A row without a positive diagonal gives no bound (0). */
static PetscErrorCode Gershgorin(hypre_ParCSRMatrix *A, PetscReal *bound)
{
  hypre_CSRMatrix  *D = hypre_ParCSRMatrixDiag(A), *O = hypre_ParCSRMatrixOffd(A);
  const HYPRE_Int  *di = hypre_CSRMatrixI(D), *dj = hypre_CSRMatrixJ(D), *oi = hypre_CSRMatrixI(O);
  const HYPRE_Real *da = hypre_CSRMatrixData(D), *oa = hypre_CSRMatrixData(O);
  const HYPRE_Int   n = hypre_CSRMatrixNumRows(D), no = oi ? hypre_CSRMatrixNumRows(O) : 0;
  PetscReal         mx = 0, bad = 0;

  PetscFunctionBeginUser;
  for (HYPRE_Int r = 0; r < n; r++) {
    PetscReal diag = 0, sum = 0;
    for (HYPRE_Int e = di[r]; e < di[r + 1]; e++) {
      if (dj[e] == r) diag = da[e];
      sum += PetscAbsReal(da[e]);
    }
    if (r < no)
      for (HYPRE_Int e = oi[r]; e < oi[r + 1]; e++) sum += PetscAbsReal(oa[e]);
    if (diag > 0)
      mx = PetscMax(mx, sum / diag);
    else
      bad = 1;
  }
  {
    PetscReal in[2] = {mx, bad}, out[2];
    PetscCallMPI(MPIU_Allreduce(in, out, 2, MPIU_REAL, MPIU_MAX, hypre_ParCSRMatrixComm(A)));
    *bound = out[1] > 0 ? 0 : out[0];
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode JacobiWeights(Split *s, PetscInt i)
{
  PC                subpc;
  PetscBool         hypre, user;
  const char       *type, *pre;
  hypre_ParAMGData *amg;
  PetscInt          N, nl;

  PetscFunctionBeginUser;
  s->nweight[i] = 0;
  PetscCall(KSPGetPC(s->ksp[i], &subpc));
  PetscCall(PetscObjectTypeCompare((PetscObject)subpc, PCHYPRE, &hypre));
  if (!hypre || s->jacobi_scale <= 0 || !subpc->data) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(PCHYPREGetType(subpc, &type));
  PetscCall(KSPGetOptionsPrefix(s->ksp[i], &pre));
  PetscCall(PetscOptionsHasName(NULL, pre, "-pc_hypre_boomeramg_relax_weight_all", &user));
  if (!type || strcmp(type, "boomeramg") || user) PetscFunctionReturn(PETSC_SUCCESS);
  amg = *(hypre_ParAMGData **)subpc->data;
  PetscCall(MatGetSize(s->A[i], &N, NULL));
  if (!amg || !hypre_ParAMGDataAArray(amg) || !hypre_ParAMGDataGridRelaxType(amg)) PetscFunctionReturn(PETSC_SUCCESS);
  nl = hypre_ParAMGDataNumLevels(amg);
  if (nl < 2 || !hypre_ParAMGDataAArray(amg)[0] || hypre_ParCSRMatrixGlobalNumRows(hypre_ParAMGDataAArray(amg)[0]) != N)
    PetscFunctionReturn(PETSC_SUCCESS);
  if (hypre_ParAMGDataGridRelaxType(amg)[1] != 0 || hypre_ParAMGDataGridRelaxType(amg)[2] != 0) PetscFunctionReturn(PETSC_SUCCESS); /* not Jacobi */
  for (PetscInt l = 0; l < nl - 1; l++) {
    HYPRE_Real mx = 0, mn = 0;
    PetscReal  gx = 0;
    PetscCallExternal(hypre_ParCSRMaxEigEstimateCG, hypre_ParAMGDataAArray(amg)[l], 1, 10, &mx, &mn);
    PetscCall(Gershgorin(hypre_ParAMGDataAArray(amg)[l], &gx));
    if (!(mx > 0) || PetscIsInfOrNanReal(mx)) mx = gx / 1.1; /* no Lanczos estimate: the bound */
    if (gx > 0 && 1.1 * mx > gx) mx = gx / 1.1;              /* an unsymmetric block (contact) can mislead Lanczos above the bound */
    if (mx > 0) hypre_ParAMGDataRelaxWeight(amg)[l] = s->jacobi_scale / (1.1 * mx); /* else hypre's weight stays */
    if (l < 32) s->lambda[i][l] = mx, s->weight[i][l] = hypre_ParAMGDataRelaxWeight(amg)[l];
  }
  s->nweight[i] = PetscMin(nl - 1, 32); /* the levels listed by -ksp_view */
  PetscCall(PetscInfo(subpc, "%s BoomerAMG Jacobi weights on %" PetscInt_FMT " levels, finest %g (lambda %g)\n", prefix[i], nl - 1,
                      (double)s->weight[i][0], (double)s->lambda[i][0]));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode SetUp(PC pc)
{
  Split           *s;
  Mat              P;
  PetscObjectState state;
  MatReuse         reuse;
  PC               sub;
  PetscBool        hypre, tri = PETSC_FALSE;

  PetscFunctionBeginUser;
  s = (Split *)pc->data;
  PetscCall(PCGetOperators(pc, NULL, &P));
  PetscCall(MatGetNonzeroState(P, &state));
  if (s->from != P || s->state != state) PetscCall(TslSplitReset(pc));
  reuse    = s->from ? MAT_REUSE_MATRIX : MAT_INITIAL_MATRIX;
  s->from  = P;
  s->state = state;
  if (!s->ksp[0]) {
    Vec X;
    PetscCall(MatCreateVecs(P, &X, NULL));
    for (PetscInt i = 0; i < 2; i++) {
      PetscCall(CreateSubSolver(pc, s, i));
      {
        PetscInt n;
        PetscCall(ISGetLocalSize(s->is[i], &n));
        PetscCall(VecCreateMPI(PetscObjectComm((PetscObject)pc), n, PETSC_DETERMINE, &s->x[i]));
        PetscCall(VecDuplicate(s->x[i], &s->y[i]));
        PetscCall(VecScatterCreate(X, s->is[i], s->x[i], NULL, &s->sc[i]));
      }
    }
    PetscCall(VecDuplicate(s->x[1], &s->w));
    PetscCall(VecDestroy(&X));
  }
  if (reuse == MAT_INITIAL_MATRIX) PetscCall(CheckDirect(s, P));
  /* temperature block: an AIJ extract, reused while the pattern holds */
  if (s->direct) PetscCall(Block(pc, s, P, 0, 0, &s->arr[0], &s->A[0]));
  else PetscCall(MatCreateSubMatrix(P, s->is[0], s->is[0], reuse, &s->A[0]));
  PetscCall(KSPSetOperators(s->ksp[0], s->A[0], s->A[0]));
  /* block solves when the operator is block triangular (the temperature block's extraction found no displacement
   * entry in its rows); the sub-solvers take the mode below, once the displacement solver exists */
  if (s->tri_allowed && s->direct && !s->additive && !s->tri_failed) PetscCall(Triangular(s, PetscObjectComm((PetscObject)P), &tri));
  /* coupling block: with block solves the outer method takes one iteration and so the split one coupling product,
   * which goes through the operator itself (Coupling) instead of an extract made for it */
  s->aut_stale = PETSC_TRUE;
  if (!s->additive && !tri) {
    if (s->direct) PetscCall(Block(pc, s, P, 1, 0, &s->arr[1], &s->Aut));
    else PetscCall(MatCreateSubMatrix(P, s->is[1], s->is[0], s->Aut ? MAT_REUSE_MATRIX : MAT_INITIAL_MATRIX, &s->Aut));
    s->aut_stale = PETSC_FALSE;
  }
  /* displacement block */
  PetscCall(KSPGetPC(s->ksp[1], &sub));
  PetscCall(PetscObjectTypeCompare((PetscObject)sub, PCHYPRE, &hypre));
  {
    MatNullSpace sp = NULL;
    PetscCall(PetscObjectQuery((PetscObject)s->is[1], "nearnullspace", (PetscObject *)&sp));
    if (hypre && s->direct && s->A[1]) PetscCall(HypreValues(s, P, s->A[1])); /* the same pattern: new values in place */
    else if (hypre) {
      /* the previous hierarchy and hypre copy go first (a new solver object: PCHYPRE frees its hierarchy
       * only when it builds the next one), then the extract lives only until it is converted */
      PetscCall(KSPDestroy(&s->ksp[1]));
      PetscCall(MatDestroy(&s->A[1]));
      PetscCall(CreateSubSolver(pc, s, 1));
      if (s->direct) PetscCall(HypreBlock(pc, s, P, &s->A[1]));
      else {
        Mat Au = NULL;
        PetscCall(MatCreateSubMatrix(P, s->is[1], s->is[1], MAT_INITIAL_MATRIX, &Au));
        PetscCall(MatConvert(Au, MATHYPRE, MAT_INITIAL_MATRIX, &s->A[1]));
        /* the node block size (BoomerAMG's number of functions), which the conversion drops */
        PetscCall(MatSetBlockSizesFromMats(s->A[1], Au, Au));
        PetscCall(MatDestroy(&Au));
      }
    } else if (s->direct) PetscCall(Block(pc, s, P, 1, 1, &s->arr[2], &s->A[1]));
    else PetscCall(MatCreateSubMatrix(P, s->is[1], s->is[1], s->A[1] ? MAT_REUSE_MATRIX : MAT_INITIAL_MATRIX, &s->A[1]));
    if (sp) PetscCall(MatSetNearNullSpace(s->A[1], sp));
  }
  PetscCall(KSPSetOperators(s->ksp[1], s->A[1], s->A[1]));
  if (tri != s->tri) PetscCall(SubSolverMode(s, tri));
  for (PetscInt i = 0; i < 2; i++) {
    PC             subpc;
    PCFailedReason why;
    PetscCall(KSPSetUp(s->ksp[i]));
    PetscCall(JacobiWeights(s, i));
    PetscCall(KSPGetPC(s->ksp[i], &subpc));
    PetscCall(TslAmgCycleSet(subpc, s->amg_cycle, &s->cycled[i]));
    PetscCall(PCGetFailedReason(subpc, &why));
    if (why != PC_NOERROR) PetscCall(PCSetFailedReason(pc, PC_SUBPC_ERROR));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Solves one block; a failed sub-solve poisons the result, so the outer Krylov method stops on it. A block
 * solve by CG that fails (an indefinite or unsymmetric block, too many iterations) is repeated as one cycle,
 * and the split keeps to one cycle per block until the pattern changes; the outer method (flexible) goes on. */
static PetscErrorCode SubSolve(PC pc, Split *s, PetscInt i)
{
  KSPConvergedReason r;
  PetscInt           its;

  PetscFunctionBeginUser;
  PetscCall(KSPSolve(s->ksp[i], s->x[i], s->y[i]));
  PetscCall(KSPGetConvergedReason(s->ksp[i], &r));
  if (r < 0 && s->tri) {
    PetscCall(PetscInfo(pc, "%s block solve by CG failed (%s): one cycle per block until the pattern changes\n", i ? "displacement" : "temperature",
                        KSPConvergedReasons[r]));
    PetscCall(SubSolverMode(s, PETSC_FALSE));
    s->tri_failed = PETSC_TRUE;
    PetscCall(KSPSolve(s->ksp[i], s->x[i], s->y[i]));
    PetscCall(KSPGetConvergedReason(s->ksp[i], &r));
  }
  if (i == 1 && s->tri) {
    PetscCall(KSPGetIterationNumber(s->ksp[1], &its));
    s->extra += PetscMax(its, 1) - 1;
  }
  if (r < 0) {
    PetscCall(PCSetFailedReason(pc, PC_SUBPC_ERROR));
    PetscCall(VecSetInf(s->y[i]));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* w = A_uT y_T, the coupling block's product: through the whole operator with y_T in the temperature slots and
 * zeros elsewhere while block solves hold (one product per operator: a pass over the operator instead of an
 * extract of the block, its allocation and a pass over it), else the block, extracted now if this set-up had
 * not (a block solve failed and the split went over to one cycle per outer iteration). */
static PetscErrorCode Coupling(PC pc, Split *s, Vec yT, Vec w)
{
  PetscFunctionBeginUser;
  if (s->tri) { /* block solves: the block was not extracted at this set-up */
    if (!s->zf) PetscCall(MatCreateVecs(s->from, &s->zf, &s->wf));
    PetscCall(VecZeroEntries(s->zf));
    PetscCall(VecScatterBegin(s->sc[0], yT, s->zf, INSERT_VALUES, SCATTER_REVERSE));
    PetscCall(VecScatterEnd(s->sc[0], yT, s->zf, INSERT_VALUES, SCATTER_REVERSE));
    PetscCall(MatMult(s->from, s->zf, s->wf));
    PetscCall(VecScatterBegin(s->sc[1], s->wf, w, INSERT_VALUES, SCATTER_FORWARD));
    PetscCall(VecScatterEnd(s->sc[1], s->wf, w, INSERT_VALUES, SCATTER_FORWARD));
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  if (s->aut_stale) {
    PetscCall(Block(pc, s, s->from, 1, 0, &s->arr[1], &s->Aut)); /* direct: block solves need it */
    s->aut_stale = PETSC_FALSE;
  }
  PetscCall(MatMult(s->Aut, yT, w));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode Apply(PC pc, Vec b, Vec y)
{
  Split *s;

  PetscFunctionBeginUser;
  s = (Split *)pc->data;
  if (s->tri) {
    /* each block's residual below a part of the outer tolerance (relative to this application's input, the
     * outer method's normalised Krylov vector), so that the outer residual is below it after one iteration:
     * half for the displacement block, a tenth for the temperature block, whose cycles are cheap and whose
     * residual is the heat balance the job reports (7e-8 of 455 on the peer block with the outer iterations,
     * 1.5e-6 with half, 9e-8 with a tenth) */
    PetscReal rtol = 1e-10, bnorm;
    if (s->outer) PetscCall(KSPGetTolerances(s->outer, &rtol, NULL, NULL, NULL));
    PetscCall(VecNorm(b, NORM_2, &bnorm));
    PetscCall(KSPSetTolerances(s->ksp[0], 0.0, 0.1 * rtol * bnorm, PETSC_DEFAULT, PETSC_DEFAULT));
    PetscCall(KSPSetTolerances(s->ksp[1], 0.0, 0.5 * rtol * bnorm, PETSC_DEFAULT, PETSC_DEFAULT));
  }
  PetscCall(VecScatterBegin(s->sc[0], b, s->x[0], INSERT_VALUES, SCATTER_FORWARD));
  PetscCall(VecScatterEnd(s->sc[0], b, s->x[0], INSERT_VALUES, SCATTER_FORWARD));
  PetscCall(VecScatterBegin(s->sc[1], b, s->x[1], INSERT_VALUES, SCATTER_FORWARD));
  PetscCall(VecScatterEnd(s->sc[1], b, s->x[1], INSERT_VALUES, SCATTER_FORWARD));
  PetscCall(SubSolve(pc, s, 0));
  if (!s->additive) {
    PetscCall(Coupling(pc, s, s->y[0], s->w));
    PetscCall(VecAXPY(s->x[1], -1.0, s->w));
  }
  PetscCall(SubSolve(pc, s, 1));
  for (PetscInt i = 0; i < 2; i++) {
    PetscCall(VecScatterBegin(s->sc[i], s->y[i], y, INSERT_VALUES, SCATTER_REVERSE));
    PetscCall(VecScatterEnd(s->sc[i], s->y[i], y, INSERT_VALUES, SCATTER_REVERSE));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode View(PC pc, PetscViewer v)
{
  Split    *s;
  PetscBool ascii;

  PetscFunctionBeginUser;
  s = (Split *)pc->data;
  PetscCall(PetscObjectTypeCompare((PetscObject)v, PETSCVIEWERASCII, &ascii));
  if (!ascii) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(PetscViewerASCIIPrintf(v, "thermoslide field split (%s): temperature block, then displacement block%s\n",
                                   s->additive ? "additive" : "multiplicative", s->additive ? "" : " with the coupling block's update"));
  if (s->tri)
    PetscCall(PetscViewerASCIIPrintf(v, "block-triangular operator: each block solved by CG (temperature to a tenth, displacement to half the outer "
                                        "tolerance)\n"));
  for (PetscInt i = 0; i < 2; i++) {
    PetscCall(PetscViewerASCIIPrintf(v, "%s block solver (options prefix %s):\n", i ? "displacement" : "temperature", prefix[i]));
    PetscCall(PetscViewerASCIIPushTab(v));
    if (s->nweight[i] > 0) {
      PetscCall(
          PetscViewerASCIIPrintf(v, "BoomerAMG Jacobi weights per level (-tsl_amg_jacobi_scale %g / (1.1 x estimated largest eigenvalue of D^-1 A)):",
                                 (double)s->jacobi_scale));
      PetscCall(PetscViewerASCIIUseTabs(v, PETSC_FALSE));
      for (PetscInt l = 0; l < s->nweight[i]; l++) PetscCall(PetscViewerASCIIPrintf(v, " %.3g", (double)s->weight[i][l]));
      PetscCall(PetscViewerASCIIPrintf(v, "\n"));
      PetscCall(PetscViewerASCIIUseTabs(v, PETSC_TRUE));
    }
    if (s->cycled[i]) PetscCall(PetscViewerASCIIPrintf(v, "BoomerAMG V-cycle applied by thermoslide (first sweep from zero; -tsl_amg_cycle)\n"));
    if (s->ksp[i]) PetscCall(KSPView(s->ksp[i], v));
    else PetscCall(PetscViewerASCIIPrintf(v, "not set up\n"));
    PetscCall(PetscViewerASCIIPopTab(v));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* -pc_fieldsplit_type under options prefix pre: multiplicative (the default) or additive; any other type is
 * a user error that names the option. */
PetscErrorCode TslSplitOptionType(const char *pre, PetscBool *additive)
{
  char type[64] = "multiplicative";

  PetscFunctionBeginUser;
  PetscCall(PetscOptionsGetString(NULL, pre, "-pc_fieldsplit_type", type, sizeof(type), NULL));
  PetscCheck(!strcmp(type, "multiplicative") || !strcmp(type, "additive"), PETSC_COMM_WORLD, PETSC_ERR_USER_INPUT,
             "option -pc_fieldsplit_type %s: thermoslide's field split is multiplicative or additive; add -pc_type fieldsplit for PETSc's "
             "field split of that type",
             type);
  *additive = (PetscBool)!strcmp(type, "additive");
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The type's options (PCSetFromOptions): -pc_fieldsplit_type under the PC's prefix (TslSplitOptionType). */
static PetscErrorCode SetFromOptions(PC pc, PetscOptionItems *items)
{
  Split      *s = (Split *)pc->data;
  const char *pre;

  PetscFunctionBeginUser;
  (void)items;
  PetscCall(PCGetOptionsPrefix(pc, &pre));
  PetscCall(TslSplitOptionType(pre, &s->additive));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The type's constructor (PCSetType): an empty split, its fields given by TslSplitSetUp. */
static PetscErrorCode PCCreate_TslSplit(PC pc)
{
  Split *s;

  PetscFunctionBeginUser;
  PetscCall(PetscNew(&s));
  s->amg_cycle            = PETSC_TRUE;
  pc->data                = s;
  pc->ops->setup          = SetUp;
  pc->ops->apply          = Apply;
  pc->ops->view           = View;
  pc->ops->destroy        = Destroy;
  pc->ops->reset          = TslSplitReset;
  pc->ops->setfromoptions = SetFromOptions;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TslSplitRegister(void)
{
  static PetscBool done = PETSC_FALSE;

  PetscFunctionBeginUser;
  if (done) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(PCRegister(PCTSLSPLIT, PCCreate_TslSplit));
  done = PETSC_TRUE;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Makes pc thermoslide's split over the temperature and displacement index sets (referenced). */
PetscErrorCode TslSplitSetUp(PC pc, IS is_theta, IS is_u)
{
  Split *s;

  PetscFunctionBeginUser;
  PetscCall(TslSplitRegister());
  PetscCall(PCSetType(pc, PCTSLSPLIT));
  s = (Split *)pc->data;
  PetscCall(PetscObjectReference((PetscObject)is_theta));
  PetscCall(PetscObjectReference((PetscObject)is_u));
  PetscCall(ISDestroy(&s->is[0]));
  PetscCall(ISDestroy(&s->is[1]));
  s->is[0] = is_theta;
  s->is[1] = is_u;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Block solves when the operator is block triangular (allowed: the sub-solvers' Krylov types are the defaults),
 * to the tolerance of outer, the Krylov method pc belongs to (not referenced). */
PetscErrorCode TslSplitSetTriangular(PC pc, KSP outer, PetscBool allowed)
{
  Split *s;

  PetscFunctionBeginUser;
  s = (Split *)pc->data;
  s->outer       = outer;
  s->tri_allowed = allowed;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The displacement-block cycles beyond one per application of the split since the last call (block solves
 * take several), so that a caller can count cycles, which the outer iterations alone no longer measure. */
PetscErrorCode TslSplitTakeExtraCycles(PC pc, PetscInt *extra)
{
  Split *s;

  PetscFunctionBeginUser;
  s = (Split *)pc->data;
  *extra   = s->extra;
  s->extra = 0;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The blocks' BoomerAMG: weighted-Jacobi smoothing with per-level weights (JacobiWeights), omega_l = scale /
 * (1.1 lambda_l), 0 leaving hypre's weights; and whether its V-cycles are applied by thermoslide (amg.c) where
 * they are hypre's plain cycle with Jacobi smoothing (the same arithmetic, one product with the zero iterate
 * fewer per level). */
PetscErrorCode TslSplitSetAmg(PC pc, PetscReal scale, PetscBool cycle)
{
  Split *s;

  PetscFunctionBeginUser;
  s = (Split *)pc->data;
  s->jacobi_scale = scale;
  s->amg_cycle    = cycle;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Whether pc is thermoslide's split. */
PetscErrorCode TslSplitIs(PC pc, PetscBool *is)
{
  PetscFunctionBeginUser;
  PetscCall(PetscObjectTypeCompare((PetscObject)pc, PCTSLSPLIT, is));
  PetscFunctionReturn(PETSC_SUCCESS);
}
