/* The element catalogue: geometry families and deck type rows.
 *
 * Node numbering and face numbering follow the Abaqus/CalculiX dialect. Face node lists are ordered
 * so that the outward normal follows the right-hand rule (3D) or so that the body lies on the left of
 * the edge (2D), which is what the face-load kernels assume.
 */
#include "element_impl.h"
#include <ctype.h>
#include <string.h>

/* ---- shape functions ------------------------------------------------------------------------ */

static void ShapeLine2(const PetscReal xi[], PetscReal N[], PetscReal dN[])
{
  N[0]  = 0.5 * (1 - xi[0]);
  N[1]  = 0.5 * (1 + xi[0]);
  dN[0] = -0.5;
  dN[1] = 0.5;
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

/* ---- quadrature ------------------------------------------------------------------------------ */

#define G2 0.57735026918962576451 /* 1/sqrt(3) */

#define QUAD_LINE_1                                                                                                                                  \
  {                                                                                                                                                  \
    1, {{0, 0, 0}}, {2}, 1                                                                                                                           \
  }
#define QUAD_LINE_2                                                                                                                                  \
  {                                                                                                                                                  \
    2, {{-G2, 0, 0}, {G2, 0, 0}}, {1, 1}, 3                                                                                                          \
  }
#define QUAD_QUAD_1                                                                                                                                  \
  {                                                                                                                                                  \
    1, {{0, 0, 0}}, {4}, 1                                                                                                                           \
  }
#define QUAD_QUAD_4                                                                                                                                  \
  {                                                                                                                                                  \
    4, {{-G2, -G2, 0}, {G2, -G2, 0}, {G2, G2, 0}, {-G2, G2, 0}}, {1, 1, 1, 1}, 3                                                                     \
  }
#define QUAD_HEX_1                                                                                                                                   \
  {                                                                                                                                                  \
    1, {{0, 0, 0}}, {8}, 1                                                                                                                           \
  }
#define QUAD_HEX_8                                                                                                                                   \
  {                                                                                                                                                  \
    8, {{-G2, -G2, -G2}, {G2, -G2, -G2}, {G2, G2, -G2}, {-G2, G2, -G2}, {-G2, -G2, G2}, {G2, -G2, G2}, {G2, G2, G2}, {-G2, G2, G2}},                 \
        {1, 1, 1, 1, 1, 1, 1, 1}, 3                                                                                                                  \
  }

/* ---- geometry families ----------------------------------------------------------------------- */

static const TslGeometry GeomLine2 = {
    .name       = "line2",
    .dim        = 1,
    .nnode      = 2,
    .nface      = 0,
    .shape      = ShapeLine2,
    .full       = QUAD_LINE_2,
    .reduced    = QUAD_LINE_1,
    .xdmf_type  = 2,
    .node_xi    = {{-1, 0, 0}, {1, 0, 0}},
    .ref_volume = 2,
};

static const TslGeometry GeomQuad4 = {
    .name       = "quad4",
    .dim        = 2,
    .nnode      = 4,
    .nface      = 4,
    .face_nnode = {2, 2, 2, 2},
    .face_node  = {{0, 1}, {1, 2}, {2, 3}, {3, 0}},
    .face_geom  = {&GeomLine2, &GeomLine2, &GeomLine2, &GeomLine2},
    .shape      = ShapeQuad4,
    .node_xi    = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}},
    .ref_volume = 4,
    .full       = QUAD_QUAD_4,
    .reduced    = QUAD_QUAD_1,
    .xdmf_type  = 5,
};

static const TslGeometry GeomHex8 = {
    .name       = "hex8",
    .dim        = 3,
    .nnode      = 8,
    .nface      = 6,
    .face_nnode = {4, 4, 4, 4, 4, 4},
    .face_node  = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}},
    .face_geom  = {&GeomQuad4, &GeomQuad4, &GeomQuad4, &GeomQuad4, &GeomQuad4, &GeomQuad4},
    .shape      = ShapeHex8,
    .node_xi    = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1}, {-1, -1, 1}, {1, -1, 1}, {1, 1, 1}, {-1, 1, 1}},
    .ref_volume = 8,
    .full       = QUAD_HEX_8,
    .reduced    = QUAD_HEX_1,
    .xdmf_type  = 9,
};

/* ---- deck types -------------------------------------------------------------------------------- */

/* The kinematics of a row and what follows from it: kinematics, model dimension, unknowns per node and
 * their dialect dof numbers. */
#define PLANE_STRAIN                                                                                                                                 \
  TSL_KIN_PLANE_STRAIN, 2, 3,                                                                                                                        \
  {                                                                                                                                                  \
    1, 2, 11                                                                                                                                         \
  }
#define PLANE_STRESS                                                                                                                                 \
  TSL_KIN_PLANE_STRESS, 2, 3,                                                                                                                        \
  {                                                                                                                                                  \
    1, 2, 11                                                                                                                                         \
  }
#define AXISYMMETRIC                                                                                                                                 \
  TSL_KIN_AXISYMMETRIC, 2, 3,                                                                                                                        \
  {                                                                                                                                                  \
    1, 2, 11                                                                                                                                         \
  }
#define SOLID                                                                                                                                        \
  TSL_KIN_SOLID3D, 3, 4,                                                                                                                             \
  {                                                                                                                                                  \
    1, 2, 3, 11                                                                                                                                      \
  }

static const TslElementType Catalogue[] = {
    {"CPE4T", &GeomQuad4, &TslFormFull, PLANE_STRAIN, "4-node plane strain"},
    {"CPE4RT", &GeomQuad4, &TslFormReduced, PLANE_STRAIN, "4-node plane strain, reduced integration, hourglass control"},
    {"CPE4RHT", &GeomQuad4, &TslFormReducedHybrid, PLANE_STRAIN, "4-node plane strain, reduced integration, hourglass control, hybrid"},
    {"CPS4T", &GeomQuad4, &TslFormFull, PLANE_STRESS, "4-node plane stress"},
    {"CPS4RT", &GeomQuad4, &TslFormReduced, PLANE_STRESS, "4-node plane stress, reduced integration, hourglass control"},
    {"CAX4T", &GeomQuad4, &TslFormFull, AXISYMMETRIC, "4-node axisymmetric"},
    {"CAX4RT", &GeomQuad4, &TslFormReduced, AXISYMMETRIC, "4-node axisymmetric, reduced integration, hourglass control"},
    {"CAX4RHT", &GeomQuad4, &TslFormReducedHybrid, AXISYMMETRIC, "4-node axisymmetric, reduced integration, hourglass control, hybrid"},
    {"C3D8T", &GeomHex8, &TslFormFull, SOLID, "8-node brick"},
    {"C3D8RT", &GeomHex8, &TslFormReduced, SOLID, "8-node brick, reduced integration, hourglass control"},
    {"C3D8RHT", &GeomHex8, &TslFormReducedHybrid, SOLID, "8-node brick, reduced integration, hourglass control, hybrid"},
};

PetscInt TslElementTypeCount(void)
{
  return (PetscInt)(sizeof(Catalogue) / sizeof(Catalogue[0]));
}

const TslElementType *TslElementTypeGet(PetscInt index)
{
  if (index < 0 || index >= TslElementTypeCount()) return NULL;
  return &Catalogue[index];
}

PetscInt TslElementTypeFind(const char *name)
{
  for (PetscInt i = 0; i < TslElementTypeCount(); i++) {
    const char *a = Catalogue[i].name, *b = name;
    while (*a && *b && toupper((unsigned char)*a) == toupper((unsigned char)*b)) a++, b++;
    if (!*a && !*b) return i;
  }
  return -1;
}
