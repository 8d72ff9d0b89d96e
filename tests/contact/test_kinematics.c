/* Node-to-segment kinematics: projection and gap on flat, inclined and displaced segments, a node leaving
 * the segment, history transfer, and the smoothed normal on a curved polyline (continuity and C1 at the
 * nodes and at the edges of the rounded zones, continuous projection round a convex corner). */
#include "check.h"

static PetscErrorCode CheckFlat(TestLog *log)
{
  /* top face of a lower block, CCW element: m1 = (2,1) -> m2 = (0,1), outward normal (0,1) */
  const PetscReal x1[2] = {2, 1}, x2[2] = {0, 1}, above[2] = {0.5, 1.1}, below[2] = {0.5, 0.95};
  TslContactInput in = InputSetUp(above, x1, x2);
  PetscReal       xi, g, n[2];

  PetscFunctionBeginUser;
  PetscCall(TslContactProject(&in, &xi, &g, n));
  Check(log, xi, 0.75, 1e-14, "flat: xi");
  Check(log, g, 0.1, 1e-14, "flat: gap open");
  Check(log, n[0], 0, 1e-14, "flat: n_x");
  Check(log, n[1], 1, 1e-14, "flat: n_y (outward from the main body)");
  in = InputSetUp(below, x1, x2);
  PetscCall(TslContactProject(&in, &xi, &g, NULL));
  Check(log, g, -0.05, 1e-14, "flat: gap penetrating");
  Check(log, (PetscReal)TslContactProjectionSide(xi, 0), 0, 0, "flat: projection on the segment");
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Neighbouring segment end points (at rest) and the smoothing fraction of a corner test. */
static void SetNeighbours(TslContactInput *in, const PetscReal *prev, const PetscReal *next, PetscReal s)
{
  static const PetscReal rest[3] = {0, 0, 0};
  in->x_prev                     = prev;
  in->u_prev                     = rest;
  in->x_next                     = next;
  in->u_next                     = rest;
  in->smoothing                  = s;
}

static PetscErrorCode CheckInclined(TestLog *log)
{
  const PetscReal x1[2] = {0, 0}, x2[2] = {1, 1}, xs[2] = {1, 0};
  TslContactInput in = InputSetUp(xs, x1, x2);
  PetscReal       xi, g, n[2];

  PetscFunctionBeginUser;
  PetscCall(TslContactProject(&in, &xi, &g, n));
  Check(log, xi, 0.5, 1e-14, "inclined: xi");
  Check(log, g, PetscSqrtReal(0.5), 1e-14, "inclined: gap");
  Check(log, n[0], PetscSqrtReal(0.5), 1e-14, "inclined: n_x");
  Check(log, n[1], -PetscSqrtReal(0.5), 1e-14, "inclined: n_y");
  /* displacements: m2 moves to (2,1), s to (1.5, 0.2); current geometry is what counts */
  in.u[2][0] = 1;
  in.u[0][0] = 0.5;
  in.u[0][1] = 0.2;
  PetscCall(TslContactProject(&in, &xi, &g, n));
  {
    PetscReal e[2] = {2 / PetscSqrtReal(5), 1 / PetscSqrtReal(5)};
    Check(log, xi, (1.5 * e[0] + 0.2 * e[1]) / PetscSqrtReal(5), 1e-14, "displaced: xi");
    Check(log, g, 1.5 * e[1] - 0.2 * e[0], 1e-14, "displaced: gap");
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode CheckLeaving(TestLog *log)
{
  const PetscReal   x1[2] = {0, 0}, x2[2] = {1, 0}, xs[2] = {1.2, -0.1};
  TslContactInput   in = InputSetUp(xs, x1, x2);
  TslContactOutput  out;
  TslContactLaw     law;
  TslContactState h = {.xi_old = 0.9, .xi_anchor = 0.85};
  PetscReal         xi, g;

  PetscFunctionBeginUser;
  PetscCall(TslContactProject(&in, &xi, &g, NULL));
  Check(log, xi, 1.2, 1e-14, "leaving: raw xi beyond m2");
  Check(log, (PetscReal)TslContactProjectionSide(xi, 1e-10), 1, 0, "leaving: side +1");
  Check(log, (PetscReal)TslContactProjectionSide(-0.3, 1e-10), -1, 0, "leaving: side -1");
  Check(log, (PetscReal)TslContactProjectionSide(1 + 1e-12, 1e-10), 0, 0, "leaving: within tolerance");
  PetscCall(TslContactLawSetDefaults(&law));
  law.eps_n = 100;
  PetscCall(TslContactElement(&law, &in, NULL, NULL, &out));
  Check(log, out.xi, 1.2, 1e-14, "leaving: kernel keeps the extended segment until re-pairing");
  Check(log, (PetscReal)out.side, 1, 0, "leaving: kernel reports side");
  /* moving to the next segment of length 2: xi' = (xi - 1) L/L' */
  PetscCall(TslContactStateTransfer(1, 1, 2, &h));
  Check(log, h.xi_old, -0.05, 1e-15, "transfer: xi_old onto next segment");
  Check(log, h.xi_anchor, -0.075, 1e-15, "transfer: anchor onto next segment");
  PetscCall(TslContactStateTransfer(-1, 2, 1, &h));
  Check(log, h.xi_old, 0.9, 1e-15, "transfer: back again xi_old");
  Check(log, h.xi_anchor, 0.85, 1e-15, "transfer: back again anchor");
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Polyline inscribed in the unit circle, vertices at 30k degrees traversed counter-clockwise: the disc (main
 * body) is on the left and the outward normal points away from the centre. */
#define NV 7
static void Vertex(PetscInt k, PetscReal x[2])
{
  PetscReal a = (PETSC_PI / 6) * k;
  x[0]        = PetscCosReal(a);
  x[1]        = PetscSinReal(a);
}

static PetscErrorCode NormalOn(PetscInt seg, PetscReal s, PetscReal xi, PetscReal n[2])
{
  PetscReal x0[2], x1[2], x2[2], x3[2];

  PetscFunctionBeginUser;
  Vertex(seg - 1, x0);
  Vertex(seg, x1);
  Vertex(seg + 1, x2);
  Vertex(seg + 2, x3);
  PetscCall(TslContactSmoothedNormal(x0, x1, x2, x3, s, xi, n));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode CheckSmoothing(TestLog *log)
{
  const PetscReal s = 0.05, h = 1e-6;
  PetscReal       na[2], nb[2], nc[2], nd[2], L = 2 * PetscSinReal(PETSC_PI / 12);

  PetscFunctionBeginUser;
  /* mid-segment: the facet normal, pointing radially out at the mid-angle */
  PetscCall(NormalOn(2, s, 0.5, na));
  Check(log, na[0], PetscCosReal(2.5 * PETSC_PI / 6), 1e-14, "smooth: facet normal mid-segment x");
  Check(log, na[1], PetscSinReal(2.5 * PETSC_PI / 6), 1e-14, "smooth: facet normal mid-segment y");
  /* at the shared node both segments give the average normal = radial direction at the vertex */
  PetscCall(NormalOn(2, s, 1, na));
  PetscCall(NormalOn(3, s, 0, nb));
  Check(log, na[0] - nb[0], 0, 1e-15, "smooth: normal continuous at node (x)");
  Check(log, na[1] - nb[1], 0, 1e-15, "smooth: normal continuous at node (y)");
  Check(log, na[0], PetscCosReal(3 * PETSC_PI / 6), 1e-14, "smooth: node normal is the bisector (x)");
  /* C1 at the node: derivative w.r.t. arc length from both sides (both zero for this blend) */
  PetscCall(NormalOn(2, s, 1 - h, nc));
  PetscCall(NormalOn(3, s, h, nd));
  Check(log, (na[0] - nc[0]) / (h * L) - (nd[0] - nb[0]) / (h * L), 0, 1e-6, "smooth: C1 across node (dn_x/ds)");
  Check(log, (na[1] - nc[1]) / (h * L) - (nd[1] - nb[1]) / (h * L), 0, 1e-6, "smooth: C1 across node (dn_y/ds)");
  /* C1 at the edge of the rounded zone xi = s */
  {
    PetscReal l[2], m[2], r[2];
    PetscCall(NormalOn(2, s, s - h, l));
    PetscCall(NormalOn(2, s, s, m));
    PetscCall(NormalOn(2, s, s + h, r));
    /* one-sided differences differ by O(h n''), not O(1): the derivative is continuous (n'' jumps) */
    Check(log, (m[0] - l[0]) / h - (r[0] - m[0]) / h, 0, 1e3 * h, "smooth: C1 at edge of rounded zone");
    Check(log, m[0] - r[0], 0, 1e-14, "smooth: facet normal from xi = s on");
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* A node outside a convex corner: unsmoothed it projects beyond both facets (a dead zone); smoothed it
 * projects into one of them, and the gap varies continuously as it moves round the corner. */
static PetscErrorCode CheckCorner(TestLog *log)
{
  PetscReal       v[NV][2], gprev = 0;
  const PetscReal s       = 0.05;
  PetscBool       first   = PETSC_TRUE;
  PetscReal       maxjump = 0;

  PetscFunctionBeginUser;
  for (PetscInt k = 0; k < NV; k++) Vertex(k, v[k]);
  {
    PetscReal       p[2] = {1.1 * PetscCosReal(PETSC_PI / 2), 1.1 * PetscSinReal(PETSC_PI / 2)}, xa, xb;
    TslContactInput a = InputSetUp(p, v[2], v[3]), b = InputSetUp(p, v[3], v[4]);

    PetscCall(TslContactProject(&a, &xa, NULL, NULL));
    PetscCall(TslContactProject(&b, &xb, NULL, NULL));
    /* radial point over vertex 3 (angle 90): unsmoothed it projects beyond the end of segment 2 and before the
     * start of segment 3 */
    Check(log, (PetscReal)(xa > 1 && xb < 0), 1, 0, "corner unsmoothed: radial point xa = %g > 1, xb = %g < 0", (double)xa, (double)xb);
    p[0] = 1.1 * PetscCosReal(PETSC_PI / 2 + 0.01);
    p[1] = 1.1 * PetscSinReal(PETSC_PI / 2 + 0.01);
    a    = InputSetUp(p, v[2], v[3]);
    b    = InputSetUp(p, v[3], v[4]);
    PetscCall(TslContactProject(&a, &xa, NULL, NULL));
    PetscCall(TslContactProject(&b, &xb, NULL, NULL));
    Check(log, (PetscReal)(xa > 1 && xb < 0), 1, 0, "corner unsmoothed: dead zone (beyond both facets)");
    SetNeighbours(&a, v[1], v[4], s);
    SetNeighbours(&b, v[2], v[5], s);
    PetscCall(TslContactProject(&a, &xa, NULL, NULL));
    PetscCall(TslContactProject(&b, &xb, NULL, NULL));
    Check(log, (PetscReal)((xa >= 0 && xa <= 1) || (xb >= 0 && xb <= 1)), 1, 0, "corner smoothed: projects onto a facet (xa=%g, xb=%g)", (double)xa,
          (double)xb);
    /* on the bisector both segments own the point at their shared node, with the same gap */
    p[0]      = 0;
    p[1]      = 1.1;
    a.x[0][0] = b.x[0][0] = p[0];
    a.x[0][1] = b.x[0][1] = p[1];
    {
      PetscReal ga, gb;
      PetscCall(TslContactProject(&a, &xa, &ga, NULL));
      PetscCall(TslContactProject(&b, &xb, &gb, NULL));
      Check(log, xa, 1, 1e-12, "corner smoothed: bisector point at end of segment 2");
      Check(log, xb, 0, 1e-12, "corner smoothed: bisector point at start of segment 3");
      Check(log, ga - gb, 0, 1e-14, "corner smoothed: same gap from both segments");
      Check(log, ga, 0.1, 1e-12, "corner smoothed: gap = radial distance to the vertex");
    }
  }
  /* sweep a point at radius 1.05 round vertex 3: gap continuous, one of the segments always owns it */
  for (PetscInt i = -40; i <= 40; i++) {
    PetscReal       ang = PETSC_PI / 2 + 0.004 * i, p[2] = {1.05 * PetscCosReal(ang), 1.05 * PetscSinReal(ang)};
    PetscReal       xa, xb, ga, gb, g;
    TslContactInput a = InputSetUp(p, v[2], v[3]), b = InputSetUp(p, v[3], v[4]);

    SetNeighbours(&a, v[1], v[4], s);
    SetNeighbours(&b, v[2], v[5], s);
    PetscCall(TslContactProject(&a, &xa, &ga, NULL));
    PetscCall(TslContactProject(&b, &xb, &gb, NULL));
    if (xa >= 0 && xa <= 1)
      g = ga;
    else if (xb >= 0 && xb <= 1)
      g = gb;
    else {
      Check(log, 1, 0, 0, "corner sweep: no owner at angle %g", (double)ang);
      continue;
    }
    if (!first) maxjump = PetscMax(maxjump, PetscAbsReal(g - gprev));
    gprev = g;
    first = PETSC_FALSE;
  }
  Check(log, maxjump, 0, 1e-3, "corner sweep: max gap change between neighbouring points (step 0.0042)");
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* In the rounded zone the projection satisfies its definition: x_s - x_m(xi) parallel to n(xi). */
static PetscErrorCode CheckProjectionDefinition(TestLog *log)
{
  PetscReal       v[NV][2], xi, g, n[2];
  const PetscReal s = 0.2;

  PetscFunctionBeginUser;
  for (PetscInt k = 0; k < NV; k++) Vertex(k, v[k]);
  {
    PetscReal       p[2] = {1.02 * PetscCosReal(PETSC_PI / 2 - 0.03), 1.02 * PetscSinReal(PETSC_PI / 2 - 0.03)};
    TslContactInput a    = InputSetUp(p, v[2], v[3]);
    PetscReal       xm[2], r[2];

    a.x_prev    = v[1];
    a.u_prev    = (PetscReal[3]){0};
    a.x_next    = v[4];
    a.u_next    = (PetscReal[3]){0};
    a.smoothing = s;
    PetscCall(TslContactProject(&a, &xi, &g, n));
    for (PetscInt d = 0; d < 2; d++) {
      xm[d] = (1 - xi) * v[2][d] + xi * v[3][d];
      r[d]  = p[d] - xm[d];
    }
    Check(log, (PetscReal)(xi > 1 - s && xi < 1), 1, 0, "rounded zone: xi = %g inside the zone", (double)xi);
    Check(log, r[0] * n[1] - r[1] * n[0], 0, 1e-12, "rounded zone: (x_s - x_m) x n = 0");
    Check(log, g, PetscSqrtReal(r[0] * r[0] + r[1] * r[1]), 1e-12, "rounded zone: gap = distance along n");
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

int main(int argc, char **argv)
{
  TestLog log = {0, 0};

  PetscCall(PetscInitialize(&argc, &argv, NULL, NULL));
  PetscCall(CheckFlat(&log));
  PetscCall(CheckInclined(&log));
  PetscCall(CheckLeaving(&log));
  PetscCall(CheckSmoothing(&log));
  PetscCall(CheckCorner(&log));
  PetscCall(CheckProjectionDefinition(&log));
  PetscCall(PetscFinalize());
  return Summary(&log);
}
