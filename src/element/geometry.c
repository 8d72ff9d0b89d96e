/* The geometry families of the element catalogue: shape functions, quadrature, faces and the linear
 * subdivision of the second-order families.
 *
 * Node numbering is the Abaqus/CalculiX one (Abaqus Analysis User's Guide, "Solid (continuum)
 * elements", node ordering and face numbering figures):
 *   line3   1, 2 ends, 3 middle (the face of a quad8: S1 = element nodes 1, 2, 5)
 *   tri6    midsides 4 (1-2), 5 (2-3), 6 (3-1)
 *   quad8   midsides 5 (1-2), 6 (2-3), 7 (3-4), 8 (4-1)
 *   tet10   midsides 5 (1-2), 6 (2-3), 7 (3-1), 8 (1-4), 9 (2-4), 10 (3-4)
 *   wedge6  1-3 bottom triangle (zeta = -1), 4-6 top (zeta = +1), 1-2-3 counter-clockwise seen from the top
 *   wedge15 as wedge6, then midsides 7 (1-2), 8 (2-3), 9 (3-1), 10 (4-5), 11 (5-6), 12 (6-4), 13 (1-4), 14 (2-5), 15 (3-6)
 * The dialect lists the 3D faces with an inward right-hand normal (C3D8 S1 = 1-2-3-4, C3D4 S1 = 1-2-3,
 * C3D6 S3 = 1-4-5-2); face_node[] holds the same node sets in the reversed (outward) order, which is
 * what the face-load kernels assume. 2D faces keep the dialect's order (body on the left).
 *
 * Quadrature: Gauss-Legendre on lines and their tensor products; on triangles and tetrahedra the
 * centroid rule (degree 1) and the symmetric interior degree-2 rules of Hammer, Marlowe & Stroud
 * (1956): triangle points (2/3, 1/6, 1/6) in barycentric coordinates with weight 1/6 each, tetrahedron
 * points (a, b, b, b), a = (5 + 3 sqrt 5)/20, b = (5 - sqrt 5)/20, weight 1/24 each. All weights are
 * positive and all points inside the element; tests/element/test_geometry.c checks the degrees.
 *
 * A family that is the face of an element carries a rule exact for the product of two of its shape
 * functions (as_face): the face integrals of the film (int h N_a N_b dA) and of the flux are then the
 * consistent ones. Lines, quadrilaterals and tri3 reuse a rule above; tri6 (degree 4) takes the
 * symmetric 6-point rule of Strang & Fix (1973, table 4.1; Dunavant 1985): two orbits of barycentric
 * points (a, a, 1 - 2a) with weights w on the unit triangle,
 *   a = (8 - sqrt 10 +- sqrt(38 - 44 sqrt(2/5))) / 18,   w = (620 +- sqrt(213125 - 53320 sqrt 10)) / 7440,
 * the + signs together (a = 0.4459..., w = 0.1117...), the - signs together (a = 0.0916..., w = 0.0550...).
 * Solved again from the moment equations of the symmetric invariants 1, e2, e3, e2^2 of the barycentrics
 * (exact integrals 1/2, 1/8, 1/120, 1/30); positive weights, points inside, exact to degree 4 and not 5.
 */
#include "element_impl.h"

/* ---- shape functions ------------------------------------------------------------------------ */

static void ShapeLine2(const PetscReal xi[], PetscReal N[], PetscReal dN[])
{
  N[0]  = 0.5 * (1 - xi[0]);
  N[1]  = 0.5 * (1 + xi[0]);
  dN[0] = -0.5;
  dN[1] = 0.5;
}

/* Node order (end, end, middle), node_xi = -1, 1, 0. */
static void ShapeLine3(const PetscReal xi[], PetscReal N[], PetscReal dN[])
{
  const PetscReal s = xi[0];

  N[0]  = 0.5 * s * (s - 1);
  N[1]  = 0.5 * s * (s + 1);
  N[2]  = 1 - s * s;
  dN[0] = s - 0.5;
  dN[1] = s + 0.5;
  dN[2] = -2 * s;
}

/* Barycentric coordinates of the unit simplex of dimension dim, L_0 = 1 - sum_j xi_j and L_a = xi_{a-1},
 * and their (constant) gradients dL[a][j] = dL_a/dxi_j. */
static void Barycentric(PetscInt dim, const PetscReal xi[], PetscReal L[4], PetscReal dL[4][3])
{
  L[0] = 1;
  for (PetscInt j = 0; j < dim; j++) {
    L[0] -= xi[j];
    dL[0][j] = -1;
  }
  for (PetscInt a = 1; a <= dim; a++) {
    L[a] = xi[a - 1];
    for (PetscInt j = 0; j < dim; j++) dL[a][j] = (j == a - 1) ? 1 : 0;
  }
}

/* Linear simplex: N_a = L_a. */
static void ShapeSimplex1(PetscInt dim, const PetscReal xi[], PetscReal N[], PetscReal dN[])
{
  PetscReal L[4], dL[4][3];

  Barycentric(dim, xi, L, dL);
  for (PetscInt a = 0; a <= dim; a++) {
    N[a] = L[a];
    for (PetscInt j = 0; j < dim; j++) dN[dim * a + j] = dL[a][j];
  }
}

/* Quadratic simplex: corners N_a = L_a (2 L_a - 1), the midside node of edge (a, b) N = 4 L_a L_b.
 * edge[] lists the corner pairs of the midside nodes in node order (they follow the corners). */
static void ShapeSimplex2(PetscInt dim, PetscInt nedge, const PetscInt edge[][2], const PetscReal xi[], PetscReal N[], PetscReal dN[])
{
  PetscReal L[4], dL[4][3];

  Barycentric(dim, xi, L, dL);
  for (PetscInt a = 0; a <= dim; a++) {
    N[a] = L[a] * (2 * L[a] - 1);
    for (PetscInt j = 0; j < dim; j++) dN[dim * a + j] = (4 * L[a] - 1) * dL[a][j];
  }
  for (PetscInt e = 0; e < nedge; e++) {
    const PetscInt a = edge[e][0], b = edge[e][1], m = dim + 1 + e;
    N[m] = 4 * L[a] * L[b];
    for (PetscInt j = 0; j < dim; j++) dN[dim * m + j] = 4 * (L[b] * dL[a][j] + L[a] * dL[b][j]);
  }
}

static const PetscInt Tri6Edges[3][2]  = {{0, 1}, {1, 2}, {2, 0}};
static const PetscInt Tet10Edges[6][2] = {{0, 1}, {1, 2}, {2, 0}, {0, 3}, {1, 3}, {2, 3}};

static void ShapeTri3(const PetscReal xi[], PetscReal N[], PetscReal dN[])
{
  ShapeSimplex1(2, xi, N, dN);
}

static void ShapeTri6(const PetscReal xi[], PetscReal N[], PetscReal dN[])
{
  ShapeSimplex2(2, 3, Tri6Edges, xi, N, dN);
}

static void ShapeTet4(const PetscReal xi[], PetscReal N[], PetscReal dN[])
{
  ShapeSimplex1(3, xi, N, dN);
}

static void ShapeTet10(const PetscReal xi[], PetscReal N[], PetscReal dN[])
{
  ShapeSimplex2(3, 6, Tet10Edges, xi, N, dN);
}

static void ShapeQuad4(const PetscReal xi[], PetscReal N[], PetscReal dN[])
{
  static const PetscReal s[4] = {-1, 1, 1, -1}, t[4] = {-1, -1, 1, 1};
  for (int a = 0; a < 4; a++) {
    N[a]          = 0.25 * (1 + s[a] * xi[0]) * (1 + t[a] * xi[1]);
    dN[2 * a + 0] = 0.25 * s[a] * (1 + t[a] * xi[1]);
    dN[2 * a + 1] = 0.25 * t[a] * (1 + s[a] * xi[0]);
  }
}

/* Serendipity quad8: corners N = (1 + s xi)(1 + t eta)(s xi + t eta - 1)/4; midsides on eta = +-1
 * (s = 0) N = (1 - xi^2)(1 + t eta)/2, on xi = +-1 (t = 0) N = (1 + s xi)(1 - eta^2)/2. */
static void ShapeQuad8(const PetscReal xi[], PetscReal N[], PetscReal dN[])
{
  static const PetscReal s[8] = {-1, 1, 1, -1, 0, 1, 0, -1}, t[8] = {-1, -1, 1, 1, -1, 0, 1, 0};
  const PetscReal        x = xi[0], y = xi[1];

  for (int a = 0; a < 4; a++) {
    const PetscReal fs = 1 + s[a] * x, ft = 1 + t[a] * y, g = s[a] * x + t[a] * y - 1;
    N[a]          = 0.25 * fs * ft * g;
    dN[2 * a + 0] = 0.25 * s[a] * ft * (g + fs);
    dN[2 * a + 1] = 0.25 * t[a] * fs * (g + ft);
  }
  for (int a = 4; a < 8; a++) {
    if (s[a] == 0) {
      N[a]          = 0.5 * (1 - x * x) * (1 + t[a] * y);
      dN[2 * a + 0] = -x * (1 + t[a] * y);
      dN[2 * a + 1] = 0.5 * t[a] * (1 - x * x);
    } else {
      N[a]          = 0.5 * (1 + s[a] * x) * (1 - y * y);
      dN[2 * a + 0] = 0.5 * s[a] * (1 - y * y);
      dN[2 * a + 1] = -y * (1 + s[a] * x);
    }
  }
}

/* Wedge: triangle barycentrics in (xi, eta) times the linear interpolation in zeta. */
static void ShapeWedge6(const PetscReal xi[], PetscReal N[], PetscReal dN[])
{
  PetscReal L[4], dL[4][3];

  Barycentric(2, xi, L, dL);
  for (int a = 0; a < 6; a++) {
    const PetscInt  c  = a % 3;
    const PetscReal sz = a < 3 ? -1 : 1, fz = 0.5 * (1 + sz * xi[2]);
    N[a]          = L[c] * fz;
    dN[3 * a + 0] = dL[c][0] * fz;
    dN[3 * a + 1] = dL[c][1] * fz;
    dN[3 * a + 2] = 0.5 * sz * L[c];
  }
}

/* 15-node wedge: the tri6 of (xi, eta) times a quadratic in zeta, without the face and centre nodes of the full
 * product (the dialect's C3D15). Node order: corners 1-3 (zeta = -1), 4-6 (zeta = +1), the midsides of the bottom
 * edges 7 (1-2), 8 (2-3), 9 (3-1), of the top edges 10 (4-5), 11 (5-6), 12 (6-4), and of the vertical edges
 * 13 (1-4), 14 (2-5), 15 (3-6). With L the barycentrics and s = -1 below, +1 above:
 *   corner       N = L (2 L - 1)(1 + s zeta) / 2 - L (1 - zeta^2) / 2
 *   edge (a, b)  N = 2 L_a L_b (1 + s zeta)
 *   vertical     N = L (1 - zeta^2)
 * (each is 1 at its node and 0 at the others; they sum to one). */
static void ShapeWedge15(const PetscReal xi[], PetscReal N[], PetscReal dN[])
{
  PetscReal       L[4], dL[4][3];
  const PetscReal z = xi[2];

  Barycentric(2, xi, L, dL);
  for (int a = 0; a < 6; a++) {
    const PetscInt  c = a % 3;
    const PetscReal s = a < 3 ? -1 : 1, fz = 1 + s * z, gz = 1 - z * z, q = L[c] * (2 * L[c] - 1);
    N[a] = 0.5 * q * fz - 0.5 * L[c] * gz;
    for (int j = 0; j < 2; j++) dN[3 * a + j] = (0.5 * (4 * L[c] - 1) * fz - 0.5 * gz) * dL[c][j];
    dN[3 * a + 2] = 0.5 * q * s + L[c] * z;
  }
  for (int e = 0; e < 6; e++) {
    const PetscInt  ea = Tri6Edges[e % 3][0], eb = Tri6Edges[e % 3][1], m = 6 + e;
    const PetscReal s = e < 3 ? -1 : 1, fz = 1 + s * z;
    N[m] = 2 * L[ea] * L[eb] * fz;
    for (int j = 0; j < 2; j++) dN[3 * m + j] = 2 * (L[eb] * dL[ea][j] + L[ea] * dL[eb][j]) * fz;
    dN[3 * m + 2] = 2 * L[ea] * L[eb] * s;
  }
  for (int c = 0; c < 3; c++) {
    const PetscInt m = 12 + c;
    N[m]             = L[c] * (1 - z * z);
    for (int j = 0; j < 2; j++) dN[3 * m + j] = dL[c][j] * (1 - z * z);
    dN[3 * m + 2] = -2 * L[c] * z;
  }
}

static void ShapeHex8(const PetscReal xi[], PetscReal N[], PetscReal dN[])
{
  static const PetscReal s[8] = {-1, 1, 1, -1, -1, 1, 1, -1}, t[8] = {-1, -1, 1, 1, -1, -1, 1, 1}, r[8] = {-1, -1, -1, -1, 1, 1, 1, 1};
  for (int a = 0; a < 8; a++) {
    const PetscReal fs = 1 + s[a] * xi[0], ft = 1 + t[a] * xi[1], fr = 1 + r[a] * xi[2];
    N[a]          = 0.125 * fs * ft * fr;
    dN[3 * a + 0] = 0.125 * s[a] * ft * fr;
    dN[3 * a + 1] = 0.125 * t[a] * fs * fr;
    dN[3 * a + 2] = 0.125 * r[a] * fs * ft;
  }
}

/* 20-node serendipity brick: corners as hex8, then the midsides of the bottom edges 9 (1-2), 10 (2-3), 11 (3-4),
 * 12 (4-1), of the top edges 13 (5-6) ... 16 (8-5), and of the vertical edges 17 (1-5) ... 20 (4-8). A corner's
 * N = (1 + s xi)(1 + t eta)(1 + r zeta)(s xi + t eta + r zeta - 2) / 8; a midside with s = 0 (on an edge along
 * xi) N = (1 - xi^2)(1 + t eta)(1 + r zeta) / 4, and the same along eta and zeta. */
static void ShapeHex20(const PetscReal xi[], PetscReal N[], PetscReal dN[])
{
  static const PetscReal s[20] = {-1, 1, 1, -1, -1, 1, 1, -1, 0, 1, 0, -1, 0, 1, 0, -1, -1, 1, 1, -1};
  static const PetscReal t[20] = {-1, -1, 1, 1, -1, -1, 1, 1, -1, 0, 1, 0, -1, 0, 1, 0, -1, -1, 1, 1};
  static const PetscReal r[20] = {-1, -1, -1, -1, 1, 1, 1, 1, -1, -1, -1, -1, 1, 1, 1, 1, 0, 0, 0, 0};
  const PetscReal        x = xi[0], y = xi[1], z = xi[2];

  for (int a = 0; a < 20; a++) {
    const PetscReal fs = 1 + s[a] * x, ft = 1 + t[a] * y, fr = 1 + r[a] * z;
    if (a < 8) {
      const PetscReal g = s[a] * x + t[a] * y + r[a] * z - 2;
      N[a]              = 0.125 * fs * ft * fr * g;
      dN[3 * a + 0]     = 0.125 * s[a] * ft * fr * (g + fs);
      dN[3 * a + 1]     = 0.125 * t[a] * fs * fr * (g + ft);
      dN[3 * a + 2]     = 0.125 * r[a] * fs * ft * (g + fr);
    } else if (s[a] == 0) {
      N[a]          = 0.25 * (1 - x * x) * ft * fr;
      dN[3 * a + 0] = -0.5 * x * ft * fr;
      dN[3 * a + 1] = 0.25 * t[a] * (1 - x * x) * fr;
      dN[3 * a + 2] = 0.25 * r[a] * (1 - x * x) * ft;
    } else if (t[a] == 0) {
      N[a]          = 0.25 * (1 - y * y) * fs * fr;
      dN[3 * a + 0] = 0.25 * s[a] * (1 - y * y) * fr;
      dN[3 * a + 1] = -0.5 * y * fs * fr;
      dN[3 * a + 2] = 0.25 * r[a] * (1 - y * y) * fs;
    } else {
      N[a]          = 0.25 * (1 - z * z) * fs * ft;
      dN[3 * a + 0] = 0.25 * s[a] * (1 - z * z) * ft;
      dN[3 * a + 1] = 0.25 * t[a] * (1 - z * z) * fs;
      dN[3 * a + 2] = -0.5 * z * fs * ft;
    }
  }
}

/* ---- quadrature ------------------------------------------------------------------------------ */

#define G2  0.57735026918962576451 /* 1/sqrt(3): 2-point Gauss */
#define G3  0.77459666924148337704 /* sqrt(3/5): 3-point Gauss, weights 5/9, 8/9, 5/9 */
#define W3E (5.0 / 9.0)
#define W3C (8.0 / 9.0)
#define T1  (1.0 / 6.0) /* triangle degree-2 rule: barycentrics (2/3, 1/6, 1/6) */
#define T2  (2.0 / 3.0)
#define D4A 0.44594849091596488632 /* triangle degree-4 rule (Strang & Fix): orbit (a, a, 1 - 2a), weight w */
#define D4W 0.11169079483900573285
#define D4B 0.091576213509770743460 /*                                         second orbit */
#define D4V 0.054975871827660933819
#define TA  0.58541019662496845446 /* tetrahedron degree-2 rule: (5 + 3 sqrt 5)/20 */
#define TB  0.13819660112501051518 /*                             (5 - sqrt 5)/20 */

/* clang-format off */
#define QUAD_LINE_1 {.n = 1, .xi = {{0, 0, 0}}, .w = {2}, .degree = 1}
#define QUAD_LINE_2 {.n = 2, .xi = {{-G2, 0, 0}, {G2, 0, 0}}, .w = {1, 1}, .degree = 3}
#define QUAD_LINE_3 {.n = 3, .xi = {{-G3, 0, 0}, {0, 0, 0}, {G3, 0, 0}}, .w = {W3E, W3C, W3E}, .degree = 5}

#define QUAD_QUAD_1 {.n = 1, .xi = {{0, 0, 0}}, .w = {4}, .degree = 1}
#define QUAD_QUAD_4 {.n = 4, .xi = {{-G2, -G2, 0}, {G2, -G2, 0}, {G2, G2, 0}, {-G2, G2, 0}}, .w = {1, 1, 1, 1}, .degree = 3}
#define QUAD_QUAD_9 \
  {.n = 9, \
   .xi = {{-G3, -G3, 0}, {0, -G3, 0}, {G3, -G3, 0}, {-G3, 0, 0}, {0, 0, 0}, {G3, 0, 0}, {-G3, G3, 0}, {0, G3, 0}, {G3, G3, 0}}, \
   .w = {W3E * W3E, W3C * W3E, W3E * W3E, W3E * W3C, W3C * W3C, W3E * W3C, W3E * W3E, W3C * W3E, W3E * W3E}, .degree = 5}

#define QUAD_HEX_1 {.n = 1, .xi = {{0, 0, 0}}, .w = {8}, .degree = 1}
#define QUAD_HEX_8 \
  {.n = 8, \
   .xi = {{-G2, -G2, -G2}, {G2, -G2, -G2}, {G2, G2, -G2}, {-G2, G2, -G2}, {-G2, -G2, G2}, {G2, -G2, G2}, {G2, G2, G2}, {-G2, G2, G2}}, \
   .w = {1, 1, 1, 1, 1, 1, 1, 1}, .degree = 3}

#define G3_(i)  ((i) == 0 ? -G3 : (i) == 1 ? 0 : G3)
#define W3_(i)  ((i) == 1 ? W3C : W3E)
#define P27(i, j, k) {G3_(i), G3_(j), G3_(k)}
#define W27(i, j, k) (W3_(i) * W3_(j) * W3_(k))
#define QUAD_HEX_27 \
  {.n = 27, \
   .xi = {P27(0,0,0), P27(1,0,0), P27(2,0,0), P27(0,1,0), P27(1,1,0), P27(2,1,0), P27(0,2,0), P27(1,2,0), P27(2,2,0), \
          P27(0,0,1), P27(1,0,1), P27(2,0,1), P27(0,1,1), P27(1,1,1), P27(2,1,1), P27(0,2,1), P27(1,2,1), P27(2,2,1), \
          P27(0,0,2), P27(1,0,2), P27(2,0,2), P27(0,1,2), P27(1,1,2), P27(2,1,2), P27(0,2,2), P27(1,2,2), P27(2,2,2)}, \
   .w = {W27(0,0,0), W27(1,0,0), W27(2,0,0), W27(0,1,0), W27(1,1,0), W27(2,1,0), W27(0,2,0), W27(1,2,0), W27(2,2,0), \
         W27(0,0,1), W27(1,0,1), W27(2,0,1), W27(0,1,1), W27(1,1,1), W27(2,1,1), W27(0,2,1), W27(1,2,1), W27(2,2,1), \
         W27(0,0,2), W27(1,0,2), W27(2,0,2), W27(0,1,2), W27(1,1,2), W27(2,1,2), W27(0,2,2), W27(1,2,2), W27(2,2,2)}, .degree = 5}

#define QUAD_TRI_1 {.n = 1, .xi = {{1.0 / 3, 1.0 / 3, 0}}, .w = {0.5}, .degree = 1}
#define QUAD_TRI_3 {.n = 3, .xi = {{T1, T1, 0}, {T2, T1, 0}, {T1, T2, 0}}, .w = {T1, T1, T1}, .degree = 2}
#define QUAD_TRI_6 \
  {.n = 6, \
   .xi = {{D4A, D4A, 0}, {1 - 2 * D4A, D4A, 0}, {D4A, 1 - 2 * D4A, 0}, {D4B, D4B, 0}, {1 - 2 * D4B, D4B, 0}, {D4B, 1 - 2 * D4B, 0}}, \
   .w = {D4W, D4W, D4W, D4V, D4V, D4V}, .degree = 4}

#define QUAD_TET_1 {.n = 1, .xi = {{0.25, 0.25, 0.25}}, .w = {1.0 / 6}, .degree = 1}
#define QUAD_TET_4 \
  {.n = 4, .xi = {{TB, TB, TB}, {TA, TB, TB}, {TB, TA, TB}, {TB, TB, TA}}, .w = {1.0 / 24, 1.0 / 24, 1.0 / 24, 1.0 / 24}, .degree = 2}

/* wedge: triangle rule times Gauss in zeta (6 points, total degree 2) or centroid (degree 1) */
#define QUAD_WEDGE_1 {.n = 1, .xi = {{1.0 / 3, 1.0 / 3, 0}}, .w = {1}, .degree = 1}
#define QUAD_WEDGE_6 \
  {.n = 6, .xi = {{T1, T1, -G2}, {T2, T1, -G2}, {T1, T2, -G2}, {T1, T1, G2}, {T2, T1, G2}, {T1, T2, G2}}, \
   .w = {T1, T1, T1, T1, T1, T1}, .degree = 2}
/* tet10's lumping rule (HRZ: N_a^2 is of degree 4): the symmetric 14-point degree-5 rule of Walkington (2000) /
 * Keast (1986), three orbits of barycentric points, positive weights (checked against the monomials' exact
 * integrals in tests/element/test_geometry.c): (a, a, a, 1 - 3a) twice and (b, b, 1/2 - b, 1/2 - b) */
#define K5A 0.0927352503108912 /* weight 0.0734930431163619 / 6 */
#define K5W (0.0734930431163619 / 6)
#define K5B 0.3108859192633006 /* weight 0.1126879257180162 / 6 */
#define K5V (0.1126879257180162 / 6)
#define K5C 0.0455037041256496 /* weight 0.0425460207770812 / 6 */
#define K5U (0.0425460207770812 / 6)
#define K5O(a) {a, a, a}, {1 - 3 * (a), a, a}, {a, 1 - 3 * (a), a}, {a, a, 1 - 3 * (a)}
#define QUAD_TET_14 \
  {.n = 14, \
   .xi = {K5O(K5A), K5O(K5B), {K5C, K5C, 0.5 - K5C}, {K5C, 0.5 - K5C, K5C}, {0.5 - K5C, K5C, K5C}, {0.5 - K5C, 0.5 - K5C, K5C}, \
          {0.5 - K5C, K5C, 0.5 - K5C}, {K5C, 0.5 - K5C, 0.5 - K5C}}, \
   .w = {K5W, K5W, K5W, K5W, K5V, K5V, K5V, K5V, K5U, K5U, K5U, K5U, K5U, K5U}, .degree = 5}

/* wedge15: the triangle's degree-4 rule times 3-point Gauss in zeta (18 points, total degree 4): exact for the
 * stiffness and conduction of a straight-sided element and for HRZ's N_a^2 */
#define W18(z) {D4A, D4A, z}, {1 - 2 * D4A, D4A, z}, {D4A, 1 - 2 * D4A, z}, {D4B, D4B, z}, {1 - 2 * D4B, D4B, z}, {D4B, 1 - 2 * D4B, z}
#define V18(w) D4W * (w), D4W * (w), D4W * (w), D4V * (w), D4V * (w), D4V * (w)
#define QUAD_WEDGE_18 {.n = 18, .xi = {W18(-G3), W18(0), W18(G3)}, .w = {V18(W3E), V18(W3C), V18(W3E)}, .degree = 4}
/* clang-format on */

/* ---- geometry families ----------------------------------------------------------------------- */

const TslGeometry TslGeomLine2 = {
    .name       = "line2",
    .dim        = 1,
    .nnode      = 2,
    .ncorner    = 2,
    .order      = 1,
    .nface      = 0,
    .shape      = ShapeLine2,
    .node_xi    = {{-1, 0, 0}, {1, 0, 0}},
    .ref_volume = 2,
    .full       = QUAD_LINE_2,
    .reduced    = QUAD_LINE_1,
    .as_face    = QUAD_LINE_2,
    .xdmf_type  = 2, /* Polyline (the links DC1D2; the writer adds the record's node count) */
};

const TslGeometry TslGeomLine3 = {
    .name       = "line3",
    .dim        = 1,
    .nnode      = 3,
    .ncorner    = 2,
    .order      = 2,
    .nface      = 0,
    .shape      = ShapeLine3,
    .node_xi    = {{-1, 0, 0}, {1, 0, 0}, {0, 0, 0}},
    .ref_volume = 2,
    .full       = QUAD_LINE_3,
    .reduced    = QUAD_LINE_2,
    .as_face    = QUAD_LINE_3,
    .xdmf_type  = 34, /* Edge_3 */
    .nsub       = 2,
    .sub_geom   = &TslGeomLine2,
    .sub_node   = {{0, 2}, {2, 1}},
};

const TslGeometry TslGeomTri3 = {
    .name       = "tri3",
    .dim        = 2,
    .nnode      = 3,
    .ncorner    = 3,
    .order      = 1,
    .nface      = 3,
    .face_nnode = {2, 2, 2},
    .face_node  = {{0, 1}, {1, 2}, {2, 0}},
    .face_geom  = {&TslGeomLine2, &TslGeomLine2, &TslGeomLine2},
    .shape      = ShapeTri3,
    .node_xi    = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}},
    .ref_volume = 0.5,
    .full       = QUAD_TRI_1,
    .reduced    = QUAD_TRI_1,
    .as_face    = QUAD_TRI_3,
    .xdmf_type  = 4,
};

/* Sub-triangles: the three corner triangles and the middle one, all counter-clockwise. */
const TslGeometry TslGeomTri6 = {
    .name       = "tri6",
    .dim        = 2,
    .nnode      = 6,
    .ncorner    = 3,
    .order      = 2,
    .nface      = 3,
    .face_nnode = {3, 3, 3},
    .face_node  = {{0, 1, 3}, {1, 2, 4}, {2, 0, 5}},
    .face_geom  = {&TslGeomLine3, &TslGeomLine3, &TslGeomLine3},
    .shape      = ShapeTri6,
    .node_xi    = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0.5, 0, 0}, {0.5, 0.5, 0}, {0, 0.5, 0}},
    .ref_volume = 0.5,
    .full       = QUAD_TRI_3,
    .reduced    = QUAD_TRI_1,
    .as_face    = QUAD_TRI_6,
    .lump       = QUAD_TRI_6, /* HRZ: N_a^2 of degree 4 */
    .xdmf_type  = 36,         /* Triangle_6 */
    .nsub       = 4,
    .sub_geom   = &TslGeomTri3,
    .sub_node   = {{0, 3, 5}, {3, 1, 4}, {5, 4, 2}, {3, 4, 5}},
};

const TslGeometry TslGeomQuad4 = {
    .name       = "quad4",
    .dim        = 2,
    .nnode      = 4,
    .ncorner    = 4,
    .order      = 1,
    .nface      = 4,
    .face_nnode = {2, 2, 2, 2},
    .face_node  = {{0, 1}, {1, 2}, {2, 3}, {3, 0}},
    .face_geom  = {&TslGeomLine2, &TslGeomLine2, &TslGeomLine2, &TslGeomLine2},
    .shape      = ShapeQuad4,
    .node_xi    = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}},
    .ref_volume = 4,
    .full       = QUAD_QUAD_4,
    .reduced    = QUAD_QUAD_1,
    .as_face    = QUAD_QUAD_4,
    .xdmf_type  = 5,
};

const TslGeometry TslGeomQuad8 = {
    .name       = "quad8",
    .dim        = 2,
    .nnode      = 8,
    .ncorner    = 4,
    .order      = 2,
    .nface      = 4,
    .face_nnode = {3, 3, 3, 3},
    .face_node  = {{0, 1, 4}, {1, 2, 5}, {2, 3, 6}, {3, 0, 7}},
    .face_geom  = {&TslGeomLine3, &TslGeomLine3, &TslGeomLine3, &TslGeomLine3},
    .shape      = ShapeQuad8,
    .node_xi    = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}, {0, -1, 0}, {1, 0, 0}, {0, 1, 0}, {-1, 0, 0}},
    .ref_volume = 4,
    .full       = QUAD_QUAD_9,
    .reduced    = QUAD_QUAD_4,
    /* as a face with positive pressure weights (the expanded S8RT's FaceRuleSub): no centre node, so the four
     * corner triangles and the quad of the midside nodes cut along m0-m2 (six tri3) */
    .nsub      = 6,
    .sub_geom  = &TslGeomTri3,
    .sub_node  = {{0, 4, 7}, {1, 5, 4}, {2, 6, 5}, {3, 7, 6}, {4, 5, 6}, {4, 6, 7}},
    .as_face   = QUAD_QUAD_9, /* the faces of hex20: N_a N_b is of degree 4 in each direction */
    .xdmf_type = 37,          /* Quadrilateral_8 */
};

/* Faces (outward): S1 1-3-2, S2 1-2-4, S3 2-3-4, S4 3-1-4. */
const TslGeometry TslGeomTet4 = {
    .name       = "tet4",
    .dim        = 3,
    .nnode      = 4,
    .ncorner    = 4,
    .order      = 1,
    .nface      = 4,
    .face_nnode = {3, 3, 3, 3},
    .face_node  = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {2, 0, 3}},
    .face_geom  = {&TslGeomTri3, &TslGeomTri3, &TslGeomTri3, &TslGeomTri3},
    .shape      = ShapeTet4,
    .node_xi    = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}},
    .ref_volume = 1.0 / 6,
    .full       = QUAD_TET_1,
    .reduced    = QUAD_TET_1,
    .xdmf_type  = 6,
};

/* Faces as tet4, each followed by its midsides on the face edges (c0-c1), (c1-c2), (c2-c0).
 * Sub-tetrahedra: the four corner tetrahedra (the parent shrunk by 1/2 about each corner) and the
 * inner octahedron cut along its diagonal 5-10 (midsides of edges 1-2 and 3-4) into four. */
const TslGeometry TslGeomTet10 = {
    .name       = "tet10",
    .dim        = 3,
    .nnode      = 10,
    .ncorner    = 4,
    .order      = 2,
    .nface      = 4,
    .face_nnode = {6, 6, 6, 6},
    .face_node  = {{0, 2, 1, 6, 5, 4}, {0, 1, 3, 4, 8, 7}, {1, 2, 3, 5, 9, 8}, {2, 0, 3, 6, 7, 9}},
    .face_geom  = {&TslGeomTri6, &TslGeomTri6, &TslGeomTri6, &TslGeomTri6},
    .shape      = ShapeTet10,
    .node_xi    = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0.5, 0, 0}, {0.5, 0.5, 0}, {0, 0.5, 0}, {0, 0, 0.5}, {0.5, 0, 0.5}, {0, 0.5, 0.5}},
    .ref_volume = 1.0 / 6,
    .full       = QUAD_TET_4,
    .reduced    = QUAD_TET_1,
    .lump       = QUAD_TET_14, /* HRZ: N_a^2 of degree 4 */
    .xdmf_type  = 38,          /* Tetrahedron_10 */
    .nsub       = 8,
    .sub_geom   = &TslGeomTet4,
    .sub_node   = {{0, 4, 6, 7}, {4, 1, 5, 8}, {6, 5, 2, 9}, {7, 8, 9, 3}, {4, 5, 6, 9}, {4, 6, 7, 9}, {4, 7, 8, 9}, {4, 8, 5, 9}},
};

/* XDMF and VTK number a wedge with its base 1-2-3 clockwise seen from the top (its right-hand normal points away
 * from 4-5-6), the dialect counter-clockwise: written in the dialect's order, ParaView measures every wedge with a
 * negative volume (vtkCellSizeFilter; tests/output/check_readers.py). The cell swaps 2 and 3, 5 and 6, and the
 * midsides with them: 7 (1-2) becomes 9 (3-1) and so on. */
static const PetscInt XdmfOrderWedge6[6]   = {0, 2, 1, 3, 5, 4};
static const PetscInt XdmfOrderWedge15[15] = {0, 2, 1, 3, 5, 4, 8, 7, 6, 11, 10, 9, 12, 14, 13};

/* Faces (outward): S1 1-3-2, S2 4-5-6, S3 1-2-5-4, S4 2-3-6-5, S5 3-1-4-6. */
const TslGeometry TslGeomWedge6 = {
    .name       = "wedge6",
    .dim        = 3,
    .nnode      = 6,
    .ncorner    = 6,
    .order      = 1,
    .nface      = 5,
    .face_nnode = {3, 3, 4, 4, 4},
    .face_node  = {{0, 2, 1}, {3, 4, 5}, {0, 1, 4, 3}, {1, 2, 5, 4}, {2, 0, 3, 5}},
    .face_geom  = {&TslGeomTri3, &TslGeomTri3, &TslGeomQuad4, &TslGeomQuad4, &TslGeomQuad4},
    .shape      = ShapeWedge6,
    .node_xi    = {{0, 0, -1}, {1, 0, -1}, {0, 1, -1}, {0, 0, 1}, {1, 0, 1}, {0, 1, 1}},
    .ref_volume = 1,
    .full       = QUAD_WEDGE_6,
    .reduced    = QUAD_WEDGE_1,
    .xdmf_type  = 8,
    .xdmf_order = XdmfOrderWedge6,
};

const TslGeometry TslGeomHex8 = {
    .name       = "hex8",
    .dim        = 3,
    .nnode      = 8,
    .ncorner    = 8,
    .order      = 1,
    .nface      = 6,
    .face_nnode = {4, 4, 4, 4, 4, 4},
    .face_node  = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}},
    .face_geom  = {&TslGeomQuad4, &TslGeomQuad4, &TslGeomQuad4, &TslGeomQuad4, &TslGeomQuad4, &TslGeomQuad4},
    .shape      = ShapeHex8,
    .node_xi    = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1}, {-1, -1, 1}, {1, -1, 1}, {1, 1, 1}, {-1, 1, 1}},
    .ref_volume = 8,
    .full       = QUAD_HEX_8,
    .reduced    = QUAD_HEX_1,
    .xdmf_type  = 9,
};

/* Faces (outward) as hex8, each followed by its midsides on the face edges (c0-c1), (c1-c2), (c2-c3), (c3-c0). */
const TslGeometry TslGeomHex20 = {
    .name       = "hex20",
    .dim        = 3,
    .nnode      = 20,
    .ncorner    = 8,
    .order      = 2,
    .nface      = 6,
    .face_nnode = {8, 8, 8, 8, 8, 8},
    .face_node  = {{0, 3, 2, 1, 11, 10, 9, 8},
                   {4, 5, 6, 7, 12, 13, 14, 15},
                   {0, 1, 5, 4, 8, 17, 12, 16},
                   {1, 2, 6, 5, 9, 18, 13, 17},
                   {2, 3, 7, 6, 10, 19, 14, 18},
                   {3, 0, 4, 7, 11, 16, 15, 19}},
    .face_geom  = {&TslGeomQuad8, &TslGeomQuad8, &TslGeomQuad8, &TslGeomQuad8, &TslGeomQuad8, &TslGeomQuad8},
    .shape      = ShapeHex20,
    .node_xi    = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1}, {-1, -1, 1}, {1, -1, 1}, {1, 1, 1},   {-1, 1, 1}, {0, -1, -1}, {1, 0, -1},
                   {0, 1, -1},   {-1, 0, -1}, {0, -1, 1}, {1, 0, 1},   {0, 1, 1},   {-1, 0, 1}, {-1, -1, 0}, {1, -1, 0}, {1, 1, 0},   {-1, 1, 0}},
    .ref_volume = 8,
    .full       = QUAD_HEX_27,
    .reduced    = QUAD_HEX_8,
    .xdmf_type  = 48, /* Hexahedron_20 */
};

/* Faces (outward) as wedge6, each followed by its midsides on the face edges: S1 1-3-2 (9, 8, 7), S2 4-5-6
 * (10, 11, 12), S3 1-2-5-4 (7, 14, 10, 13), S4 2-3-6-5 (8, 15, 11, 14), S5 3-1-4-6 (9, 13, 12, 15). */
const TslGeometry TslGeomWedge15 = {
    .name       = "wedge15",
    .dim        = 3,
    .nnode      = 15,
    .ncorner    = 6,
    .order      = 2,
    .nface      = 5,
    .face_nnode = {6, 6, 8, 8, 8},
    .face_node  = {{0, 2, 1, 8, 7, 6}, {3, 4, 5, 9, 10, 11}, {0, 1, 4, 3, 6, 13, 9, 12}, {1, 2, 5, 4, 7, 14, 10, 13}, {2, 0, 3, 5, 8, 12, 11, 14}},
    .face_geom  = {&TslGeomTri6, &TslGeomTri6, &TslGeomQuad8, &TslGeomQuad8, &TslGeomQuad8},
    .shape      = ShapeWedge15,
    .node_xi    = {{0, 0, -1},
                   {1, 0, -1},
                   {0, 1, -1},
                   {0, 0, 1},
                   {1, 0, 1},
                   {0, 1, 1},
                   {0.5, 0, -1},
                   {0.5, 0.5, -1},
                   {0, 0.5, -1},
                   {0.5, 0, 1},
                   {0.5, 0.5, 1},
                   {0, 0.5, 1},
                   {0, 0, 0},
                   {1, 0, 0},
                   {0, 1, 0}},
    .ref_volume = 1,
    .full       = QUAD_WEDGE_18,
    .reduced    = QUAD_WEDGE_6,
    .xdmf_type  = 40, /* Wedge_15 */
    .xdmf_order = XdmfOrderWedge15,
};
