/* Structured meshes of one catalogue type, assembled from the element kernels and solved by LU (grid.h). */
#include "grid.h"

/* ---- quadrature ------------------------------------------------------------------------------- */

/* Legendre polynomial P_n(z) and its derivative (three-term recurrence). */
static void Legendre(PetscInt n, PetscReal z, PetscReal *p, PetscReal *dp)
{
  PetscReal p0 = 1, p1 = z;

  for (PetscInt j = 2; j <= n; j++) {
    const PetscReal p2 = ((2 * j - 1) * z * p1 - (j - 1) * p0) / j;
    p0 = p1, p1 = p2;
  }
  *p  = n == 0 ? 1 : p1;
  *dp = n * (z * p1 - p0) / (z * z - 1);
}

/* Gauss-Legendre on [-1, 1]: the roots of P_n by Newton from Chebyshev-like guesses, weights
 * 2 / ((1 - z^2) P_n'(z)^2). */
void GridGauss(PetscInt n, PetscReal x[], PetscReal w[])
{
  for (PetscInt i = 0; i < n; i++) {
    PetscReal z = PetscCosReal(PETSC_PI * (i + 0.75) / (n + 0.5)), p, dp;
    for (PetscInt it = 0; it < 100; it++) {
      PetscReal dz;
      Legendre(n, z, &p, &dp);
      dz = p / dp;
      z -= dz;
      if (PetscAbsReal(dz) < 1e-15) break;
    }
    Legendre(n, z, &p, &dp);
    x[n - 1 - i] = z;
    w[n - 1 - i] = 2 / ((1 - z * z) * dp * dp);
  }
}

PetscInt GridSimplexDims(const TslGeometry *g)
{
  PetscInt ns = 0;

  for (PetscInt d = 0; d < g->dim; d++) {
    PetscReal lo = 0;
    for (PetscInt a = 0; a < g->nnode; a++) lo = PetscMin(lo, g->node_xi[a][d]);
    if (lo >= 0) ns++;
  }
  return ns;
}

/* Tensor Gauss rule on [-1, 1]^dim; on the first ns directions (the unit simplex) the Duffy map
 *   xi_0 = u_0, xi_1 = u_1 (1 - u_0), xi_2 = u_2 (1 - u_0)(1 - u_1),  u = (1 + s)/2,
 * with its Jacobian (1 - u_0)^(ns-1) (1 - u_1)^(ns-2) / 2^ns in the weight. */
void GridRuleCreate(const TslGeometry *g, PetscInt npd, GridRule *rule)
{
  const PetscInt dim = g->dim, ns = GridSimplexDims(g);
  PetscReal      s[8], ws[8];
  PetscInt       total = 1;

  npd = PetscMin(npd, 8);
  GridGauss(npd, s, ws);
  for (PetscInt d = 0; d < dim; d++) total *= npd;
  rule->n = total;
  for (PetscInt q = 0; q < total; q++) {
    PetscReal t[3] = {0, 0, 0}, w = 1, u[3];
    PetscInt  c = q;
    for (PetscInt d = 0; d < dim; d++) {
      t[d] = s[c % npd];
      w *= ws[c % npd];
      c /= npd;
    }
    for (PetscInt d = 0; d < 3; d++) rule->xi[q][d] = d < dim ? t[d] : 0;
    for (PetscInt d = 0; d < ns; d++) u[d] = 0.5 * (1 + t[d]), w *= 0.5;
    if (ns == 2) {
      rule->xi[q][0] = u[0];
      rule->xi[q][1] = u[1] * (1 - u[0]);
      w *= 1 - u[0];
    } else if (ns == 3) {
      rule->xi[q][0] = u[0];
      rule->xi[q][1] = u[1] * (1 - u[0]);
      rule->xi[q][2] = u[2] * (1 - u[0]) * (1 - u[1]);
      w *= (1 - u[0]) * (1 - u[0]) * (1 - u[1]);
    }
    rule->w[q] = w;
  }
}

/* ---- mesh ------------------------------------------------------------------------------------- */

/* Kuhn (Freudenthal) split of the unit ns-cube into ns! simplices: the paths 0 -> e_p0 -> e_p0 + e_p1
 * -> ... -> (1, ..., 1) over the permutations p. Vertex lists are reordered (1 <-> 2) where needed so
 * that every simplex is positively oriented like the reference one. ns = 0: one empty "simplex". */
static PetscInt KuhnSplit(PetscInt ns, PetscInt vert[6][4][3])
{
  PetscInt n = 0, ncode = 1;

  if (ns == 0) return 1;
  for (PetscInt k = 0; k < ns; k++) ncode *= ns;
  for (PetscInt code = 0; code < ncode; code++) {
    PetscInt  perm[3], c = code, e[3][3];
    PetscBool distinct = PETSC_TRUE;
    PetscReal det;

    for (PetscInt k = 0; k < ns; k++) perm[k] = c % ns, c /= ns;
    for (PetscInt k = 0; k < ns; k++)
      for (PetscInt l = 0; l < k; l++)
        if (perm[k] == perm[l]) distinct = PETSC_FALSE;
    if (!distinct) continue;
    for (PetscInt d = 0; d < 3; d++) vert[n][0][d] = 0;
    for (PetscInt k = 1; k <= ns; k++) {
      for (PetscInt d = 0; d < 3; d++) vert[n][k][d] = vert[n][k - 1][d];
      vert[n][k][perm[k - 1]] += 1;
    }
    for (PetscInt k = 0; k < ns; k++)
      for (PetscInt d = 0; d < ns; d++) e[k][d] = vert[n][k + 1][d] - vert[n][0][d];
    det = ns == 2 ? e[0][0] * e[1][1] - e[0][1] * e[1][0]
                  : e[0][0] * (e[1][1] * e[2][2] - e[1][2] * e[2][1]) - e[0][1] * (e[1][0] * e[2][2] - e[1][2] * e[2][0]) +
                        e[0][2] * (e[1][0] * e[2][1] - e[1][1] * e[2][0]);
    if (det < 0)
      for (PetscInt d = 0; d < 3; d++) {
        const PetscInt tmp = vert[n][1][d];
        vert[n][1][d]      = vert[n][2][d];
        vert[n][2][d]      = tmp;
      }
    n++;
  }
  return n;
}

PetscBool GridConvergenceRow(const TslElementType *t, PetscInt *n0, PetscReal min[2])
{
  const PetscBool quadratic = (PetscBool)(t->geom->order > 1);

  /* the DC rows: their kernels are the coupled rows' temperature part (element_coupled_kernels compares them) */
  if (t->kin == TSL_KIN_AXISYMMETRIC_TWIST || t->nextra || TslElementTypeHeatOnly(t)) return PETSC_FALSE;
  *n0    = t->dim == 3 && quadratic ? 1 : 2;
  min[0] = quadratic ? 2.7 : 1.8;
  min[1] = quadratic ? 1.8 : 0.85;
  return PETSC_TRUE;
}

PetscErrorCode GridCreate(const TslElementType *type, const PetscInt ncell[], const PetscReal lo[], const PetscReal hi[], Grid *grid)
{
  const TslGeometry *g   = type->geom;
  const PetscInt     dim = type->dim, P = g->order, ns = GridSimplexDims(g), nen = g->nnode;
  PetscInt           np[3] = {1, 1, 1}, nc[3] = {1, 1, 1}, nlat = 1, ncells = 1, vert[6][4][3], nsplit, off[6][TSL_MAX_ELEM_NODES][3];
  PetscInt          *lat2node;

  PetscFunctionBeginUser;
  PetscCall(PetscMemzero(grid, sizeof(*grid)));
  PetscCheck(g->dim == dim, PETSC_COMM_SELF, PETSC_ERR_SUP, "%s: grids of a %" PetscInt_FMT "D family in %" PetscInt_FMT "D", type->name, g->dim,
             dim);
  grid->type = type;
  grid->nen  = nen;
  grid->ndof = type->ndof;
  for (PetscInt d = 0; d < 3; d++) {
    grid->ncell[d] = d < dim ? ncell[d] : 1;
    grid->lo[d]    = d < dim ? lo[d] : 0;
    grid->hi[d]    = d < dim ? hi[d] : 0;
  }
  for (PetscInt d = 0; d < dim; d++) {
    nc[d] = ncell[d];
    np[d] = P * ncell[d] + 1;
    nlat *= np[d];
    ncells *= ncell[d];
  }
  /* every node's position in the cell, in units of the fine lattice (1/P cell): the affine image of its
   * reference coordinates on the split simplex (first ns directions) and on [0, 1] (the others) */
  nsplit = KuhnSplit(ns, vert);
  for (PetscInt s = 0; s < nsplit; s++)
    for (PetscInt a = 0; a < nen; a++)
      for (PetscInt d = 0; d < 3; d++) {
        PetscReal o = 0;
        if (d < ns) {
          o = vert[s][0][d];
          for (PetscInt k = 0; k < ns; k++) o += g->node_xi[a][k] * (vert[s][k + 1][d] - vert[s][0][d]);
        } else if (d < dim)
          o = 0.5 * (g->node_xi[a][d] + 1);
        off[s][a][d] = (PetscInt)PetscFloorReal(P * o + 0.5);
        PetscCheck(PetscAbsReal(P * o - off[s][a][d]) < 1e-12, PETSC_COMM_SELF, PETSC_ERR_SUP, "%s node %" PetscInt_FMT " is not on the lattice",
                   type->name, a + 1);
      }
  grid->nelem = ncells * nsplit;
  PetscCall(PetscMalloc1(grid->nelem * nen, &grid->conn));
  PetscCall(PetscMalloc1(nlat, &lat2node));
  for (PetscInt l = 0; l < nlat; l++) lat2node[l] = -1;
  for (PetscInt k = 0, e = 0; k < nc[2]; k++)
    for (PetscInt j = 0; j < nc[1]; j++)
      for (PetscInt i = 0; i < nc[0]; i++)
        for (PetscInt s = 0; s < nsplit; s++, e++)
          for (PetscInt a = 0; a < nen; a++) {
            const PetscInt p0 = P * i + off[s][a][0], p1 = P * j + off[s][a][1], p2 = P * k + off[s][a][2];
            const PetscInt l        = p0 + np[0] * (p1 + np[1] * p2);
            grid->conn[e * nen + a] = l;
            lat2node[l]             = 0;
          }
  /* number the lattice points in use in lattice order (a banded matrix), and place them */
  for (PetscInt l = 0; l < nlat; l++)
    if (!lat2node[l])
      lat2node[l] = grid->nnode++;
    else
      lat2node[l] = -1;
  PetscCall(PetscMalloc2(3 * grid->nnode, &grid->x, grid->nnode, &grid->theta_init));
  for (PetscInt l = 0; l < nlat; l++) {
    const PetscInt a = lat2node[l], p[3] = {l % np[0], (l / np[0]) % np[1], l / (np[0] * np[1])};
    if (a < 0) continue;
    for (PetscInt d = 0; d < 3; d++) grid->x[3 * a + d] = d < dim ? lo[d] + (hi[d] - lo[d]) * p[d] / (PetscReal)(np[d] - 1) : 0;
    grid->theta_init[a] = 0;
  }
  for (PetscInt i = 0; i < grid->nelem * nen; i++) grid->conn[i] = lat2node[grid->conn[i]];
  PetscCall(PetscFree(lat2node));
  GridSetMaterial(grid, 1, 0.3, 1, 0, 0, 1);
  PetscFunctionReturn(PETSC_SUCCESS);
}

static void Constant(TslPropertyTable *t, PetscReal v0, PetscReal v1)
{
  t->n           = 1;
  t->value[0][0] = v0, t->value[0][1] = v1;
}

void GridSetMaterial(Grid *grid, PetscReal E, PetscReal nu, PetscReal k, PetscReal alpha, PetscReal theta_init, PetscReal thickness)
{
  PetscCallAbort(PETSC_COMM_SELF, PetscMemzero(&grid->mat, sizeof(grid->mat)));
  Constant(&grid->mat.prop[TSL_PROP_ELASTIC], E, nu);
  Constant(&grid->mat.prop[TSL_PROP_CONDUCTIVITY], k, 0);
  Constant(&grid->mat.prop[TSL_PROP_DENSITY], 1, 0);
  Constant(&grid->mat.prop[TSL_PROP_SPECIFIC_HEAT], 1, 0);
  Constant(&grid->mat.prop[TSL_PROP_EXPANSION], alpha, 0);
  grid->sec = (TslElementSection){&grid->mat, thickness, 0, 0, 0};
  for (PetscInt a = 0; a < grid->nnode; a++) grid->theta_init[a] = theta_init;
}

PetscErrorCode GridDestroy(Grid *grid)
{
  PetscFunctionBeginUser;
  PetscCall(PetscFree(grid->conn));
  PetscCall(PetscFree2(grid->x, grid->theta_init));
  PetscFunctionReturn(PETSC_SUCCESS);
}

void GridElementInput(const Grid *grid, PetscInt e, const PetscReal u[], PetscReal xe[], PetscReal ue[], PetscReal th0[], TslElementInput *in)
{
  const PetscInt ndof = grid->ndof;

  for (PetscInt a = 0; a < grid->nen; a++) {
    const PetscInt n = grid->conn[e * grid->nen + a];
    for (PetscInt d = 0; d < 3; d++) xe[3 * a + d] = grid->x[3 * n + d];
    for (PetscInt i = 0; i < ndof; i++) ue[ndof * a + i] = u ? u[ndof * n + i] : 0;
    th0[a] = grid->theta_init[n];
  }
  *in = (TslElementInput){.type = grid->type, .sec = &grid->sec, .x = xe, .u = ue, .theta_init = th0};
}

PetscErrorCode GridMinJacobian(const Grid *grid, PetscReal *min_detJ, PetscInt *invalid)
{
  const TslGeometry *g = grid->type->geom;
  PetscReal          xe[TSL_MAX_ELEM_NODES * 3], ue[TSL_MAX_ELEM_DOF], th0[TSL_MAX_ELEM_NODES];
  TslElementInput    in;
  TslElementPoint    p;

  PetscFunctionBeginUser;
  *min_detJ = PETSC_MAX_REAL;
  *invalid  = 0;
  for (PetscInt e = 0; e < grid->nelem; e++) {
    GridElementInput(grid, e, NULL, xe, ue, th0, &in);
    for (PetscInt q = 0; q < g->nnode + g->full.n; q++) {
      const PetscReal *xi = q < g->nnode ? g->node_xi[q] : g->full.xi[q - g->nnode];
      if (!TslElementPointEvaluate(grid->type, &grid->sec, xe, xi, 1, &p)) (*invalid)++;
      *min_detJ = PetscMin(*min_detJ, p.detJ);
    }
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscBool GridOnPlane(const Grid *grid, PetscInt a, PetscInt d, PetscReal value)
{
  const PetscReal tol = 1e-10 * (PetscAbsReal(grid->hi[d] - grid->lo[d]) + PetscAbsReal(value) + 1);
  return PetscAbsReal(grid->x[3 * a + d] - value) < tol ? PETSC_TRUE : PETSC_FALSE;
}

PetscBool GridFaceOnPlane(const Grid *grid, PetscInt e, PetscInt f, PetscInt d, PetscReal value)
{
  const TslGeometry *g    = grid->type->geom;
  const PetscInt    *node = &grid->conn[e * grid->nen];

  for (PetscInt k = 0; k < g->face_nnode[f]; k++)
    if (!GridOnPlane(grid, node[g->face_node[f][k]], d, value)) return PETSC_FALSE;
  return PETSC_TRUE;
}

PetscErrorCode GridFaceWeights(const Grid *grid, PetscInt d, PetscReal value, PetscReal w[])
{
  const TslGeometry             *g     = grid->type->geom;
  const struct TslKinematicsRow *kin   = TslKinematicsRowGet(grid->type->kin);
  const PetscReal                thick = grid->sec.thickness > 0 ? grid->sec.thickness : 1;

  PetscFunctionBeginUser;
  for (PetscInt e = 0; e < grid->nelem; e++)
    for (PetscInt f = 0; f < g->nface; f++) {
      const TslGeometry *fg   = g->face_geom[f];
      const PetscInt     fn   = g->face_nnode[f];
      const PetscInt    *node = &grid->conn[e * grid->nen];
      GridRule           rule;

      if (!GridFaceOnPlane(grid, e, f, d, value)) continue;
      GridRuleCreate(fg, 6, &rule);
      for (PetscInt q = 0; q < rule.n; q++) {
        PetscReal N[TSL_MAX_FACE_NODES], dN[TSL_MAX_FACE_NODES * 3], T[2][3] = {{0}}, xq[3] = {0, 0, 0}, dA;
        fg->shape(rule.xi[q], N, dN);
        for (PetscInt k = 0; k < fn; k++) {
          const PetscReal *xa = &grid->x[3 * node[g->face_node[f][k]]];
          for (PetscInt c = 0; c < 3; c++) {
            xq[c] += N[k] * xa[c];
            for (PetscInt j = 0; j < fg->dim; j++) T[j][c] += dN[fg->dim * k + j] * xa[c];
          }
        }
        if (fg->dim == 1)
          dA = PetscSqrtReal(T[0][0] * T[0][0] + T[0][1] * T[0][1] + T[0][2] * T[0][2]);
        else {
          const PetscReal n0 = T[0][1] * T[1][2] - T[0][2] * T[1][1], n1 = T[0][2] * T[1][0] - T[0][0] * T[1][2];
          const PetscReal n2 = T[0][0] * T[1][1] - T[0][1] * T[1][0];
          dA                 = PetscSqrtReal(n0 * n0 + n1 * n1 + n2 * n2);
        }
        dA *= rule.w[q];
        if (kin->thickness) dA *= thick;
        if (kin->revolve) dA *= 2 * PETSC_PI * xq[0];
        for (PetscInt k = 0; k < fn; k++) w[node[g->face_node[f][k]]] += N[k] * dA;
      }
    }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* ---- face loads -------------------------------------------------------------------------------- */

PetscErrorCode GridAddFaceLoad(Grid *grid, PetscInt d, PetscReal plane, TslFaceLoadKind kind, PetscReal value, PetscReal value2)
{
  PetscFunctionBeginUser;
  PetscCheck(grid->nload < GRID_MAX_FACE_LOADS, PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE, "at most %d face loads", GRID_MAX_FACE_LOADS);
  grid->load[grid->nload++] = (GridFaceLoad){d, plane, kind, value, value2};
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode GridAddBodyFlux(Grid *grid, PetscReal q)
{
  PetscFunctionBeginUser;
  PetscCall(GridAddFaceLoad(grid, -1, 0, TSL_BODY_FLUX, q, 0));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Adds the grid's face and body loads on element e (kernel input in) to Re and Ke (may be NULL); *heat (may be
 * NULL) += their heat. */
static PetscErrorCode ElementFaceLoads(const Grid *grid, PetscInt e, const TslElementInput *in, PetscReal Re[], PetscReal Ke[], PetscReal *heat)
{
  PetscFunctionBeginUser;
  for (PetscInt l = 0; l < grid->nload; l++) {
    const GridFaceLoad *ld = &grid->load[l];
    if (ld->kind == TSL_BODY_FLUX) {
      PetscReal h;
      PetscCall(TslElementFaceLoad(in, ld->kind, 0, &(TslFaceLoadValue){ld->value, ld->value2, 0}, Re, Ke, &h));
      if (heat) *heat += h;
      continue;
    }
    for (PetscInt f = 0; f < grid->type->geom->nface; f++) {
      PetscReal h;
      if (!GridFaceOnPlane(grid, e, f, ld->d, ld->plane)) continue;
      PetscCall(TslElementFaceLoad(in, ld->kind, f + 1, &(TslFaceLoadValue){ld->value, ld->value2, 0}, Re, Ke, &h));
      if (heat) *heat += h;
    }
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode GridFaceHeat(const Grid *grid, const PetscReal u[], PetscReal *heat)
{
  PetscReal       xe[TSL_MAX_ELEM_NODES * 3], ue[TSL_MAX_ELEM_DOF], th0[TSL_MAX_ELEM_NODES], Re[TSL_MAX_ELEM_DOF];
  TslElementInput in;

  PetscFunctionBeginUser;
  *heat = 0;
  for (PetscInt e = 0; e < grid->nelem; e++) {
    GridElementInput(grid, e, u, xe, ue, th0, &in);
    for (PetscInt i = 0; i < grid->nen * grid->ndof; i++) Re[i] = 0;
    PetscCall(ElementFaceLoads(grid, e, &in, Re, NULL, heat));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* ---- manufactured problems --------------------------------------------------------------------- */

PetscErrorCode GridLoadVector(const Grid *grid, const GridRule *rule, GridSourceFn source, void *ctx, PetscReal F[])
{
  const TslElementType *t    = grid->type;
  const PetscInt        ndof = grid->ndof, nen = grid->nen;
  PetscReal             xe[TSL_MAX_ELEM_NODES * 3], ue[TSL_MAX_ELEM_DOF], th0[TSL_MAX_ELEM_NODES];
  TslElementInput       in;
  TslElementPoint       p;

  PetscFunctionBeginUser;
  for (PetscInt i = 0; i < grid->nnode * ndof; i++) F[i] = 0;
  for (PetscInt e = 0; e < grid->nelem; e++) {
    GridElementInput(grid, e, NULL, xe, ue, th0, &in);
    for (PetscInt q = 0; q < rule->n; q++) {
      PetscReal s[TSL_MAX_NODE_DOF];
      PetscCheck(TslElementPointEvaluate(t, &grid->sec, xe, rule->xi[q], rule->w[q], &p), PETSC_COMM_SELF, PETSC_ERR_PLIB, "invalid map");
      source(ctx, p.x, s);
      for (PetscInt a = 0; a < nen; a++)
        for (PetscInt i = 0; i < ndof; i++) F[ndof * grid->conn[e * nen + a] + i] += p.N[a] * s[i] * p.dV;
    }
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode GridErrors(const Grid *grid, const PetscReal u[], const GridRule *rule, GridFieldFn field, void *ctx, PetscReal l2[], PetscReal h1[])
{
  const TslElementType *t    = grid->type;
  const PetscInt        ndof = grid->ndof, dim = t->dim, nen = grid->nen;
  PetscReal             xe[TSL_MAX_ELEM_NODES * 3], ue[TSL_MAX_ELEM_DOF], th0[TSL_MAX_ELEM_NODES];
  TslElementInput       in;
  TslElementPoint       p;

  PetscFunctionBeginUser;
  for (PetscInt i = 0; i < ndof; i++) l2[i] = h1[i] = 0;
  for (PetscInt e = 0; e < grid->nelem; e++) {
    GridElementInput(grid, e, u, xe, ue, th0, &in);
    for (PetscInt q = 0; q < rule->n; q++) {
      PetscCheck(TslElementPointEvaluate(t, &grid->sec, xe, rule->xi[q], rule->w[q], &p), PETSC_COMM_SELF, PETSC_ERR_PLIB, "invalid map");
      for (PetscInt i = 0; i < ndof; i++) {
        PetscReal f, g[3], fh = 0, gh[3] = {0, 0, 0}, e1 = 0;
        field(ctx, i, p.x, &f, g);
        for (PetscInt a = 0; a < nen; a++) {
          fh += p.N[a] * ue[ndof * a + i];
          for (PetscInt d = 0; d < dim; d++) gh[d] += p.dNdx[a][d] * ue[ndof * a + i];
        }
        for (PetscInt d = 0; d < dim; d++) e1 += (gh[d] - g[d]) * (gh[d] - g[d]);
        l2[i] += (fh - f) * (fh - f) * p.dV;
        h1[i] += e1 * p.dV;
      }
    }
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* ---- assembly and solve ----------------------------------------------------------------------- */

/* Exact preallocation: a node row couples to every node of its elements. */
PetscErrorCode GridCreateMatrix(const Grid *grid, Mat *K)
{
  const PetscInt nnode = grid->nnode, nen = grid->nen, ndof = grid->ndof;
  PetscInt      *start, *list, *mark, *nnz;

  PetscFunctionBeginUser;
  PetscCall(PetscCalloc1(nnode + 1, &start));
  PetscCall(PetscMalloc3(grid->nelem * nen, &list, nnode, &mark, nnode * ndof, &nnz));
  for (PetscInt i = 0; i < grid->nelem * nen; i++) start[grid->conn[i] + 1]++;
  for (PetscInt a = 0; a < nnode; a++) start[a + 1] += start[a];
  for (PetscInt a = 0; a < nnode; a++) mark[a] = 0;
  for (PetscInt i = 0; i < grid->nelem * nen; i++) list[start[grid->conn[i]] + mark[grid->conn[i]]++] = i / nen;
  for (PetscInt a = 0; a < nnode; a++) mark[a] = -1;
  for (PetscInt a = 0; a < nnode; a++) {
    PetscInt count = 0;
    for (PetscInt k = start[a]; k < start[a + 1]; k++)
      for (PetscInt b = 0; b < nen; b++) {
        const PetscInt n = grid->conn[list[k] * nen + b];
        if (mark[n] != a) mark[n] = a, count++;
      }
    for (PetscInt i = 0; i < ndof; i++) nnz[ndof * a + i] = count * ndof;
  }
  PetscCall(MatCreateSeqAIJ(PETSC_COMM_SELF, nnode * ndof, nnode * ndof, 0, nnz, K));
  PetscCall(PetscFree3(list, mark, nnz));
  PetscCall(PetscFree(start));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode GridAssemble(const Grid *grid, const PetscReal u[], PetscReal R[], Mat K)
{
  const PetscInt  nen = grid->nen, ndof = grid->ndof, nd = nen * ndof;
  PetscReal       xe[TSL_MAX_ELEM_NODES * 3], ue[TSL_MAX_ELEM_DOF], th0[TSL_MAX_ELEM_NODES], Re[TSL_MAX_ELEM_DOF], *Ke = NULL;
  PetscInt        idx[TSL_MAX_ELEM_DOF];
  TslElementInput in;

  PetscFunctionBeginUser;
  if (K) {
    PetscCall(PetscMalloc1(nd * nd, &Ke));
    PetscCall(MatZeroEntries(K));
  }
  for (PetscInt i = 0; i < grid->nnode * ndof; i++) R[i] = 0;
  for (PetscInt e = 0; e < grid->nelem; e++) {
    PetscBool inverted;
    GridElementInput(grid, e, u, xe, ue, th0, &in);
    PetscCall(TslElementInternal(&in, Re, Ke, &inverted));
    PetscCheck(!inverted, PETSC_COMM_SELF, PETSC_ERR_PLIB, "%s element %" PetscInt_FMT " inverted", grid->type->name, e);
    PetscCall(ElementFaceLoads(grid, e, &in, Re, Ke, NULL));
    for (PetscInt a = 0; a < nen; a++)
      for (PetscInt i = 0; i < ndof; i++) idx[ndof * a + i] = ndof * grid->conn[e * nen + a] + i;
    for (PetscInt i = 0; i < nd; i++) R[idx[i]] += Re[i];
    if (K) PetscCall(MatSetValues(K, nd, idx, nd, idx, Ke, ADD_VALUES));
  }
  if (K) {
    PetscCall(MatAssemblyBegin(K, MAT_FINAL_ASSEMBLY));
    PetscCall(MatAssemblyEnd(K, MAT_FINAL_ASSEMBLY));
    PetscCall(PetscFree(Ke));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscReal MaxFree(PetscInt n, const PetscReal F[], const PetscReal R[], const PetscBool fixed[])
{
  PetscReal m = 0;
  for (PetscInt i = 0; i < n; i++)
    if (!fixed[i]) m = PetscMax(m, PetscAbsReal(F[i] - R[i]));
  return m;
}

PetscErrorCode GridSolve(const Grid *grid, const PetscReal F[], PetscInt nfix, const PetscInt fix[], PetscReal u[], GridSolveInfo *info)
{
  const PetscInt     N = grid->nnode * grid->ndof;
  PetscReal         *R, *b, r0;
  const PetscScalar *du;
  PetscBool         *fixed;
  Mat                K;
  Vec                rhs, x;
  KSP                ksp;
  PC                 pc;
  KSPConvergedReason reason;
  PCFailedReason     pcreason;

  PetscFunctionBeginUser;
  PetscCall(PetscMalloc2(N, &R, N, &fixed));
  for (PetscInt i = 0; i < N; i++) fixed[i] = PETSC_FALSE;
  for (PetscInt i = 0; i < nfix; i++) fixed[fix[i]] = PETSC_TRUE;
  PetscCall(GridCreateMatrix(grid, &K));
  PetscCall(GridAssemble(grid, u, R, K));
  r0 = MaxFree(N, F, R, fixed);
  PetscCall(MatZeroRows(K, nfix, fix, 1.0, NULL, NULL));
  PetscCall(VecCreateSeq(PETSC_COMM_SELF, N, &rhs));
  PetscCall(VecDuplicate(rhs, &x));
  PetscCall(VecGetArray(rhs, &b));
  for (PetscInt i = 0; i < N; i++) b[i] = fixed[i] ? 0 : F[i] - R[i];
  PetscCall(VecRestoreArray(rhs, &b));
  PetscCall(KSPCreate(PETSC_COMM_SELF, &ksp));
  PetscCall(KSPSetType(ksp, KSPPREONLY));
  PetscCall(KSPGetPC(ksp, &pc));
  PetscCall(PCSetType(pc, PCLU));
  PetscCall(KSPSetOperators(ksp, K, K));
  PetscCall(KSPSolve(ksp, rhs, x));
  PetscCall(KSPGetConvergedReason(ksp, &reason));
  PetscCall(PCGetFailedReason(pc, &pcreason));
  info->factored = (PetscBool)(reason > 0 && pcreason == PC_NOERROR);
  info->failure  = info->factored ? "none" : (pcreason != PC_NOERROR ? PCFailedReasons[pcreason] : KSPConvergedReasons[reason]);
  info->residual = PETSC_MAX_REAL;
  if (info->factored) {
    PetscCall(VecGetArrayRead(x, &du));
    for (PetscInt i = 0; i < N; i++) u[i] += PetscRealPart(du[i]);
    PetscCall(VecRestoreArrayRead(x, &du));
    PetscCall(GridAssemble(grid, u, R, NULL));
    info->residual = MaxFree(N, F, R, fixed) / (r0 > 0 ? r0 : 1);
  }
  PetscCall(KSPDestroy(&ksp));
  PetscCall(VecDestroy(&rhs));
  PetscCall(VecDestroy(&x));
  PetscCall(MatDestroy(&K));
  PetscCall(PetscFree2(R, fixed));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode GridEnergies(const Grid *grid, const PetscReal u[], PetscReal *strain, PetscReal *hourglass)
{
  PetscReal        xe[TSL_MAX_ELEM_NODES * 3], ue[TSL_MAX_ELEM_DOF], th0[TSL_MAX_ELEM_NODES];
  TslElementInput  in;
  TslElementResult res;

  PetscFunctionBeginUser;
  *strain = *hourglass = 0;
  for (PetscInt e = 0; e < grid->nelem; e++) {
    GridElementInput(grid, e, u, xe, ue, th0, &in);
    PetscCall(TslElementOutput(&in, &res));
    *strain += res.strain_energy;
    *hourglass += res.hourglass_energy;
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode GridSolveConduction(const Grid *grid, const GridRule *rule, const PetscReal F[], PetscInt nplane, const PetscInt dir[],
                                   const PetscReal value[], GridFieldFn exact, void *ctx, PetscReal u[], GridSolveInfo *info, PetscReal err[2])
{
  const TslElementType *t    = grid->type;
  const PetscInt        ndof = t->ndof, th = TslElementTypeThetaSlot(t);
  PetscReal             l2[TSL_MAX_NODE_DOF], h1[TSL_MAX_NODE_DOF];
  PetscInt             *fix, nfix = 0;

  PetscFunctionBeginUser;
  PetscCall(PetscMalloc1(grid->nnode * ndof, &fix));
  for (PetscInt a = 0; a < grid->nnode; a++) {
    PetscBool held = PETSC_FALSE;
    for (PetscInt k = 0; k < nplane; k++) held = (PetscBool)(held || GridOnPlane(grid, a, dir[k], value[k]));
    for (PetscInt i = 0; i < ndof; i++) {
      PetscReal g[3];
      exact(ctx, i, &grid->x[3 * a], &u[ndof * a + i], g);
      if (i < th || held)
        fix[nfix++] = ndof * a + i;
      else
        u[ndof * a + i] = 0;
    }
  }
  PetscCall(GridSolve(grid, F, nfix, fix, u, info));
  err[0] = err[1] = PETSC_MAX_REAL;
  if (info->factored) {
    PetscCall(GridErrors(grid, u, rule, exact, ctx, l2, h1));
    err[0] = PetscSqrtReal(l2[th]);
    err[1] = PetscSqrtReal(h1[th]);
  }
  PetscCall(PetscFree(fix));
  PetscFunctionReturn(PETSC_SUCCESS);
}
