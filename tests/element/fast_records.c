/* The explicit force records (src/element/fast.c) against the generic kernels they replace: for every
 * catalogue type with a fast row, on a distorted element (shifted far from the origin too, where the
 * geometry's rounding is largest) with arbitrary displacements, temperatures and velocities, the internal
 * force and heat flow equal TslElementInternal's, the bulk viscosity forces and power
 * TslElementBulkViscosity's, to 1e-12 of the largest entry, the strain and hourglass energies TslElementOutput's. The types without a row
 * (generalized plane strain, twist, hybrid) and a temperature-dependent material get no record (size 0); nor does a continuum shell
 * section with other than the 5 Simpson points of the row. The same again at finite strain (nl: TslElementInput.nlgeom), each element
 * turned by 40 degrees about its first node on top of strains of 5 %, and a record's lane turned inside out flagged as inverted. */
#include "check.h"

static void Constant(TslPropertyTable *t, PetscReal v0, PetscReal v1)
{
  t->n           = 1;
  t->value[0][0] = v0, t->value[0][1] = v1;
}

/* Largest |a - b| over n entries, relative to the largest |b| (floor 1e-300). */
static PetscReal RelDiff(PetscInt n, const PetscReal a[], const PetscReal b[])
{
  PetscReal d = 0, m = 1e-300;
  for (PetscInt i = 0; i < n; i++) d = PetscMax(d, PetscAbsReal(a[i] - b[i])), m = PetscMax(m, PetscAbsReal(b[i]));
  return d / m;
}

/* A batch of TSL_FAST_LANES different elements of the type (geometry, unknowns, velocities and viscosity
 * differing by lane, one lane without viscosity) gives in each lane exactly what that element's own
 * evaluation gives: the lanes do not mix. */
static PetscErrorCode CheckBatch(TestLog *log, const TslElementInput *in0, const TslElementFastShape *shape, const PetscReal x0[], const PetscReal u0[],
                                 const PetscReal v0[], const PetscReal ti0[], PetscReal offset, PetscBool nl)
{
  enum { W = TSL_FAST_LANES };
  const TslElementType *t = in0->type;
  const PetscInt        n = t->geom->nnode, nd = n * t->ndof, size = shape->size;
  PetscReal             x[TSL_MAX_ELEM_NODES * 3], u[TSL_MAX_ELEM_DOF], v[TSL_MAX_ELEM_DOF], rec[TSL_FAST_MAX_SIZE], R[W][TSL_MAX_ELEM_DOF],
      Rv[W][TSL_MAX_ELEM_DOF], w[W], se[W], hg[W], eta[W], eta2[W], batch[TSL_FAST_MAX_SIZE * W], ub[TSL_MAX_ELEM_DOF * W], vb[TSL_MAX_ELEM_DOF * W],
      tib[TSL_MAX_ELEM_NODES * W], Rb[TSL_MAX_ELEM_DOF * W], Rvb[TSL_MAX_ELEM_DOF * W], wb[W], seb[W], hgb[W], ev[W], u1b[TSL_MAX_ELEM_DOF * W],
      R1b[TSL_MAX_ELEM_DOF * W], Rv1b[TSL_MAX_ELEM_DOF * W], w1b[W];
  const PetscReal h    = 1e-3;
  PetscReal       dmax = 0;
  TslElementInput in = *in0;
  int             expect = 0, mask;

  PetscFunctionBeginUser;
  for (PetscInt j = 0; j < W; j++) {
    for (PetscInt i = 0; i < 3 * TSL_MAX_ELEM_NODES; i++) x[i] = x0[i] + (x0[i] != 0 ? 0.02 * j * PetscSinReal(1.3 * i + j) : 0);
    for (PetscInt i = 0; i < nd; i++) u[i] = u0[i] * (1 + 0.3 * j), v[i] = v0[i] * (j - 1.5);
    in.x = x, in.u = u;
    CheckTrue(log, TslElementFastBuild(&in, rec), "%s (offset %g): lane %d's record built", t->name, (double)offset, (int)j);
    if (nl) { /* the lanes the generic kernel finds turned inside out */
      PetscReal Rg[TSL_MAX_ELEM_DOF];
      PetscBool inverted;
      PetscCall(TslElementInternal(&in, Rg, NULL, &inverted));
      expect |= inverted ? 1 << j : 0;
    }
    eta[j] = j == 2 ? 0 : 0.06e-4 * (1 + j), eta2[j] = j == 2 ? 0 : 1.44e-8;
    (void)TslElementFastForce(shape, nl, rec, u, ti0, v, eta[j], eta2[j], R[j], Rv[j], &w[j]);
    if (j == 2)
      for (PetscInt i = 0; i < nd; i++) Rv[j][i] = 0;
    TslElementFastEnergy(shape, nl, rec, u, ti0, &se[j], &hg[j]);
    TslElementFastInterleave(size, j, rec, batch);
    TslElementFastInterleave(nd, j, u, ub);
    TslElementFastInterleave(nd, j, v, vb);
    TslElementFastInterleave(n, j, ti0, tib);
  }
  for (PetscInt j = 0; j < W; j++) ev[j] = 0.125;
  mask = TslElementFastForceBatch(shape, nl, batch, ub, tib, vb, ev, 0, eta, eta2, Rb, Rvb, wb, NULL);
  CheckTrue(log, (PetscBool)(mask == expect), "%s (offset %g%s): lanes inverted %d, as the generic kernel's %d", t->name, (double)offset,
            nl ? ", finite strain" : "", mask, expect);
  TslElementFastEnergyBatch(shape, nl, batch, ub, tib, seb, hgb);
  for (PetscInt j = 0; j < W; j++) {
    for (PetscInt i = 0; i < nd; i++) dmax = PetscMax(dmax, PetscMax(PetscAbsReal(Rb[i * W + j] - R[j][i]), PetscAbsReal(Rvb[i * W + j] - Rv[j][i])));
    dmax = PetscMax(dmax, PetscMax(PetscAbsReal(wb[j] - w[j]), PetscAbsReal(seb[j] - se[j]) + PetscAbsReal(hgb[j] - hg[j])));
  }
  CheckAtMost(log, dmax, 0.0, "%s (offset %g%s): a batch of %d different elements, lane by lane, against each alone", t->name, (double)offset,
              nl ? ", finite strain" : "", (int)W);
  if (nl) { /* the rate is v's (ev untouched); lane 1 turned inside out (x -> -x through its first node): its bit alone */
    PetscReal ub2[TSL_MAX_ELEM_DOF * W];
    PetscBool kept = PETSC_TRUE;
    for (PetscInt j = 0; j < W; j++) kept = (PetscBool)(kept && ev[j] == 0.125);
    CheckTrue(log, kept, "%s (offset %g, finite strain): the kept centre strains are not touched", t->name, (double)offset);
    for (PetscInt i = 0; i < nd * W; i++) ub2[i] = ub[i];
    for (PetscInt a = 0; a < n; a++) {
      PetscReal xl[TSL_MAX_ELEM_NODES * 3];
      for (PetscInt k = 0; k < 3 * TSL_MAX_ELEM_NODES; k++) xl[k] = x0[k] + (x0[k] != 0 ? 0.02 * 1 * PetscSinReal(1.3 * k + 1) : 0);
      ub2[(t->ndof * a) * W + 1] = -2 * (xl[3 * a] - xl[0]); /* u_x = -2 (X - X_0): F_xx = -1 */
      for (PetscInt i = 1; i < t->dim; i++) ub2[(t->ndof * a + i) * W + 1] = 0;
    }
    mask = TslElementFastForceBatch(shape, nl, batch, ub2, tib, vb, NULL, 0, eta, eta2, Rb, Rvb, wb, NULL);
    CheckTrue(log, (PetscBool)(mask == (expect | 2)), "%s (offset %g, finite strain): lane 1 turned inside out flagged (%d)", t->name, (double)offset,
              mask);
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  /* the rate from the centre strains kept in ev: after the move u + h v, the viscous forces and power of the
   * difference quotient against those of v itself (which that move makes the same velocity) */
  for (PetscInt i = 0; i < nd * W; i++) u1b[i] = ub[i] + h * vb[i];
  (void)TslElementFastForceBatch(shape, nl, batch, u1b, tib, vb, NULL, 0, eta, eta2, Rb, Rvb, wb, NULL);
  (void)TslElementFastForceBatch(shape, nl, batch, u1b, tib, NULL, ev, 1 / h, eta, eta2, R1b, Rv1b, w1b, NULL);
  CheckAtMost(log, PetscMax(RelDiff(nd * W, Rv1b, Rvb), RelDiff(W, w1b, wb)), 1e-10,
              "%s (offset %g): bulk viscosity from the kept centre strains over h against the velocities' own", t->name, (double)offset);
  CheckAtMost(log, RelDiff(nd * W, R1b, Rb), 0.0, "%s (offset %g): the internal forces do not depend on where the rate came from", t->name,
              (double)offset);
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode CheckType(TestLog *log, const TslElementType *t, PetscReal offset, PetscBool nl, PetscInt *nrows)
{
  const TslGeometry  *g = t->geom;
  const PetscInt      n = g->nnode, ndof = t->ndof, nd = n * ndof;
  TslMaterial         mat;
  TslElementSection   sec;
  TslElementInput     in;
  TslElementFastShape shape;
  PetscReal           x[TSL_MAX_ELEM_NODES * 3], u[TSL_MAX_ELEM_DOF], v[TSL_MAX_ELEM_DOF], ti[TSL_MAX_ELEM_NODES], rec[1024], R[TSL_MAX_ELEM_DOF],
      Rg[TSL_MAX_ELEM_DOF], Rv[TSL_MAX_ELEM_DOF], Rvg[TSL_MAX_ELEM_DOF], w, wg;
  PetscBool inverted;
  PetscInt  size;

  PetscFunctionBeginUser;
  PetscCall(PetscMemzero(&mat, sizeof(mat)));
  Constant(&mat.prop[TSL_PROP_ELASTIC], 200e3, 0.3);
  Constant(&mat.prop[TSL_PROP_CONDUCTIVITY], 10, 0);
  Constant(&mat.prop[TSL_PROP_DENSITY], 2, 0);
  Constant(&mat.prop[TSL_PROP_SPECIFIC_HEAT], 3, 0);
  Constant(&mat.prop[TSL_PROP_EXPANSION], 1e-3, 0);
  sec = (TslElementSection){&mat, 0.5, 0, 0, 0};
  for (PetscInt a = 0; a < TslElementTypeNodes(t); a++) {
    for (PetscInt d = 0; d < 3; d++) {
      const PetscReal lo = g->node_xi[0][d] < 0 || g->node_xi[1][d] < 0 ? -1 : 0, unit = lo < 0 ? 0.5 * (g->node_xi[a][d] + 1) : g->node_xi[a][d];
      x[3 * a + d] = d < t->dim ? unit + 0.08 * PetscSinReal(3.1 * a + 1.3 * d + 0.7) + (d == 0 ? 1 : 0) + offset : 0;
    }
    ti[a] = 20 + 3 * PetscCosReal(1.7 * a);
    for (PetscInt i = 0; i < ndof; i++) {
      u[ndof * a + i] = i == ndof - 1 ? 40 + 7 * PetscSinReal(2.3 * a) : (nl ? 5e-2 : 1e-3) * PetscSinReal(1.9 * a + 0.6 * i + 0.2);
      v[ndof * a + i] = i == ndof - 1 ? 0 : 0.4 * PetscCosReal(0.9 * a + 1.1 * i);
    }
  }
  if (nl) /* turned by 40 degrees about the first node, in the (x, y) plane (the plane of the 2D kinematics) */
    for (PetscInt a = 0; a < TslElementTypeNodes(t); a++) {
      const PetscReal c = PetscCosReal(0.7), s = PetscSinReal(0.7), X = x[3 * a] - x[0], Y = x[3 * a + 1] - x[1];
      u[ndof * a] += (c - 1) * X - s * Y, u[ndof * a + 1] += s * X + (c - 1) * Y;
    }
  in = (TslElementInput){.type = t, .sec = &sec, .x = x, .u = u, .theta_init = ti, .nlgeom = nl};
  if (!TslElementFastShapeGet(t, &shape)) {
    CheckTrue(log, (PetscBool)(TslElementFastSize(&in) == 0), "%s: no fast row, no record", t->name);
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  if (nl && !TslElementTypeFiniteStrain(t)) PetscFunctionReturn(PETSC_SUCCESS);
  (*nrows)++;
  if (!strcmp(t->name, "C3D8T")) /* hex8, full rule */
    CheckTrue(log, shape.sf, "%s: the full rule's sum factorisation applies (checked against every derivative)", t->name);
  size = TslElementFastSize(&in);
  CheckTrue(log, (PetscBool)(size > 0 && size <= 1024), "%s: record of %d reals", t->name, (int)size);
  CheckTrue(log, TslElementFastBuild(&in, rec), "%s (offset %g): record built", t->name, (double)offset);
  (void)TslElementFastForce(&shape, nl, rec, u, ti, v, 0.06 * 1e-4, 1.44e-8, R, Rv, &w);
  PetscCall(TslElementInternal(&in, Rg, NULL, &inverted));
  CheckAtMost(log, RelDiff(nd, R, Rg), 1e-12, "%s (offset %g%s): internal force and heat flow against the generic kernel", t->name, (double)offset,
              nl ? ", finite strain" : "");
  {
    TslElementResult res;
    PetscReal        se, hg;
    PetscCall(TslElementOutput(&in, &res));
    TslElementFastEnergy(&shape, nl, rec, u, ti, &se, &hg);
    CheckRel(log, se, res.strain_energy, 1e-12, 1e-300, "%s (offset %g%s): strain energy against the generic output", t->name, (double)offset,
             nl ? ", finite strain" : "");
    CheckRel(log, hg, res.hourglass_energy, 1e-12, 1e-30 + 1e-12 * PetscAbsReal(res.strain_energy), "%s (offset %g): hourglass energy", t->name,
             (double)offset);
  }
  for (PetscInt sign = 1; sign >= -1; sign -= 2) { /* expansion and compression: the quadratic term in one only */
    for (PetscInt i = 0; i < nd; i++) v[i] = -v[i], Rvg[i] = 0;
    (void)TslElementFastForce(&shape, nl, rec, u, ti, v, 0.06 * 1e-4, 1.44e-8, R, Rv, &w);
    PetscCall(TslElementBulkViscosity(&in, v, 0.06 * 1e-4, 1.44e-8, Rvg, &wg, NULL));
    CheckAtMost(log, RelDiff(nd, Rv, Rvg), 1e-12, "%s (offset %g%s, velocities x %d): bulk viscosity forces against the generic kernel", t->name,
                (double)offset, nl ? ", finite strain" : "", (int)sign);
    CheckRel(log, w, wg, 1e-12, 1e-300, "%s (offset %g%s, velocities x %d): bulk viscosity power", t->name, (double)offset, nl ? ", finite strain" : "",
             (int)sign);
  }
  PetscCall(CheckBatch(log, &in, &shape, x, u, v, ti, offset, nl));
  if (t->kin == TSL_KIN_CONTINUUM_SHELL) { /* a section's thickness modulus in the record; other point counts: none */
    TslElementSection stm = {&mat, 0.5, 5, 3.3e4, 3}, s3 = {&mat, 0.5, 3, 0, 0};
    in.sec = &stm;
    CheckTrue(log, TslElementFastBuild(&in, rec), "%s (offset %g): record with THICKNESS MODULUS built", t->name, (double)offset);
    (void)TslElementFastForce(&shape, nl, rec, u, ti, v, 0, 0, R, Rv, &w);
    PetscCall(TslElementInternal(&in, Rg, NULL, &inverted));
    CheckAtMost(log, RelDiff(nd, R, Rg), 1e-12, "%s (offset %g): THICKNESS MODULUS: internal force against the generic kernel", t->name,
                (double)offset);
    in.sec = &s3;
    CheckTrue(log, (PetscBool)(TslElementFastSize(&in) == 0), "%s: a section of 3 points, no record", t->name);
    in.sec = &sec;
  }
  /* a temperature-dependent property: no record */
  mat.prop[TSL_PROP_CONDUCTIVITY].n        = 2;
  mat.prop[TSL_PROP_CONDUCTIVITY].theta[1] = 100, mat.prop[TSL_PROP_CONDUCTIVITY].value[1][0] = 12;
  CheckTrue(log, (PetscBool)(TslElementFastSize(&in) == 0), "%s: temperature-dependent conductivity, no record", t->name);
  PetscFunctionReturn(PETSC_SUCCESS);
}

int main(int argc, char **argv)
{
  TestLog  log   = {0, 0};
  PetscInt nrows = 0;

  PetscCall(PetscInitialize(&argc, &argv, NULL, NULL));
  for (PetscInt t = 0; t < TslElementTypeCount(); t++)
    for (PetscInt k = 0; k < 4; k++) PetscCall(CheckType(&log, TslElementTypeGet(t), k % 2 ? 1e4 : 0, (PetscBool)(k >= 2), &nrows));
  CheckTrue(&log, (PetscBool)(nrows == 4 * 27),
            "records for the 27 types of plane strain, plane stress, axisymmetric and 3D displacement formulations and the continuum shells (%d "
            "type-offset pairs, small and finite strain)",
            (int)nrows);
  PetscCall(PetscFinalize());
  return log.failures ? 1 : 0;
}
