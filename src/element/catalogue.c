/* The element catalogue: one row per deck type name, and the lookups.
 *
 * The geometry families the rows point at (shape functions, quadrature, faces in the dialect's
 * numbering) are in geometry.c.
 */
#include "element_impl.h"
#include <ctype.h>
#include <string.h>

/* ---- deck types -------------------------------------------------------------------------------- */

/* The kinematics of a row and what follows from it: kinematics, model dimension, unknowns per node and
 * their dialect dof numbers (0: a slot the kinematics does not use, held at zero), the extra nodes and their
 * dofs (generalized plane strain: the section's reference node, dofs 3, 4, 5). */
// clang-format off
#define PLANE_STRAIN TSL_KIN_PLANE_STRAIN, 2, 3, {1, 2, 11}, 0, {0}, PETSC_FALSE
#define PLANE_STRESS TSL_KIN_PLANE_STRESS, 2, 3, {1, 2, 11}, 0, {0}, PETSC_FALSE
#define GENPLANE     TSL_KIN_GENERALIZED_PLANE_STRAIN, 2, 4, {1, 2, 0, 11}, 1, {3, 4, 5, 0}, PETSC_FALSE
#define AXISYMMETRIC TSL_KIN_AXISYMMETRIC, 2, 3, {1, 2, 11}, 0, {0}, PETSC_FALSE
#define AXITWIST     TSL_KIN_AXISYMMETRIC_TWIST, 2, 4, {1, 2, 5, 11}, 0, {0}, PETSC_FALSE
#define SOLID        TSL_KIN_SOLID3D, 3, 4, {1, 2, 3, 11}, 0, {0}, PETSC_FALSE
#define CSHELL       TSL_KIN_CONTINUUM_SHELL, 3, 4, {1, 2, 3, 11}, 0, {0}, PETSC_FALSE
/* Plane strain with a pore pressure (dof 8) that the coupled temperature-displacement procedure does not
 * activate: the unknowns are plane strain's, the element its solid counterpart (docs/elements.md). */
#define PORE_PLANE   TSL_KIN_PLANE_STRAIN, 2, 3, {1, 2, 11}, 0, {0}, PETSC_TRUE
/* Heat transfer (the DC types): the temperature alone, on the measure of the plane (thickness), axisymmetric
 * (2 pi r) or solid kinematics; no displacement slot, so the kernels have no mechanical term to form. */
#define HEAT_PLANE   TSL_KIN_PLANE_STRAIN, 2, 1, {11}, 0, {0}, PETSC_FALSE
#define HEAT_AXI     TSL_KIN_AXISYMMETRIC, 2, 1, {11}, 0, {0}, PETSC_FALSE
#define HEAT_SOLID   TSL_KIN_SOLID3D, 3, 1, {11}, 0, {0}, PETSC_FALSE
/* a heat-transfer link: a line in the model's space (2D or 3D), its cross-section area the *SOLID SECTION's value */
#define HEAT_LINK    TSL_KIN_SOLID3D, 3, 1, {11}, 0, {0}, PETSC_FALSE

static const TslElementType Catalogue[] = {
    {"CPE3T",   &TslGeomTri3,   &TslFormFull,           PLANE_STRAIN, "3-node plane strain"},
    {"CPE4T",   &TslGeomQuad4,  &TslFormFull,           PLANE_STRAIN, "4-node plane strain"},
    {"CPE4RT",  &TslGeomQuad4,  &TslFormReduced,        PLANE_STRAIN, "4-node plane strain, reduced integration, hourglass control"},
    {"CPE4RHT", &TslGeomQuad4,  &TslFormReducedHybrid,  PLANE_STRAIN, "4-node plane strain, reduced integration, hourglass control, hybrid"},
    {"CPE6MT",  &TslGeomTri6,   &TslFormModified,       PLANE_STRAIN, "6-node modified second-order plane strain"},
    {"CPE6MHT", &TslGeomTri6,   &TslFormModifiedHybrid, PLANE_STRAIN, "6-node modified second-order plane strain, hybrid"},
    {"CPE8T",   &TslGeomQuad8,  &TslFormFull,           PLANE_STRAIN, "8-node plane strain"},
    {"CPE8HT",  &TslGeomQuad8,  &TslFormHybrid,         PLANE_STRAIN, "8-node plane strain, hybrid"},
    {"CPE8RT",  &TslGeomQuad8,  &TslFormReducedQuadratic, PLANE_STRAIN, "8-node plane strain, reduced integration"},
    {"CPE8RHT", &TslGeomQuad8,  &TslFormReducedQuadraticHybrid, PLANE_STRAIN, "8-node plane strain, reduced integration, hybrid"},
    {"CPE6T",   &TslGeomTri6,   &TslFormFull,           PLANE_STRAIN, "6-node plane strain (CalculiX's CPE6 in a coupled step)"},
    {"CPE4IT",  &TslGeomQuad4,  &TslFormIncompatible,   PLANE_STRAIN, "4-node plane strain, incompatible modes (CalculiX's and Abaqus's CPE4I in a coupled or static step)"},
    {"CPE4PT",   &TslGeomQuad4, &TslFormFull,          PORE_PLANE,   "4-node plane strain, pore pressure (not active)"},
    {"CPE4PHT",  &TslGeomQuad4, &TslFormHybrid,        PORE_PLANE,   "4-node plane strain, pore pressure (not active), hybrid"},
    {"CPE4RPT",  &TslGeomQuad4, &TslFormReduced,       PORE_PLANE,   "4-node plane strain, pore pressure (not active), reduced integration, hourglass control"},
    {"CPE4RPHT", &TslGeomQuad4, &TslFormReducedHybrid, PORE_PLANE,   "4-node plane strain, pore pressure (not active), reduced integration, hourglass control, hybrid"},
    {"CPEG4T",   &TslGeomQuad4, &TslFormFull,           GENPLANE,     "4-node generalized plane strain"},
    {"CPEG4RT",  &TslGeomQuad4, &TslFormReduced,        GENPLANE,     "4-node generalized plane strain, reduced integration, hourglass control"},
    {"CPEG4RHT", &TslGeomQuad4, &TslFormReducedHybrid,  GENPLANE,     "4-node generalized plane strain, reduced integration, hourglass control, hybrid"},
    {"CPEG6MT",  &TslGeomTri6,  &TslFormModified,       GENPLANE,     "6-node modified second-order generalized plane strain"},
    {"CPEG6MHT", &TslGeomTri6,  &TslFormModifiedHybrid, GENPLANE,     "6-node modified second-order generalized plane strain, hybrid"},
    {"CPEG8T",   &TslGeomQuad8, &TslFormFull,           GENPLANE,     "8-node generalized plane strain"},
    {"CPS3T",   &TslGeomTri3,   &TslFormFull,           PLANE_STRESS, "3-node plane stress"},
    {"CPS4T",   &TslGeomQuad4,  &TslFormFull,           PLANE_STRESS, "4-node plane stress"},
    {"CPS4IT",  &TslGeomQuad4,  &TslFormIncompatible,   PLANE_STRESS, "4-node plane stress, incompatible modes (CPS4I in a coupled or static step)"},
    {"CPS4RT",  &TslGeomQuad4,  &TslFormReduced,        PLANE_STRESS, "4-node plane stress, reduced integration, hourglass control"},
    {"CPS6MT",  &TslGeomTri6,   &TslFormModified,       PLANE_STRESS, "6-node modified second-order plane stress"},
    {"CPS8T",   &TslGeomQuad8,  &TslFormFull,           PLANE_STRESS, "8-node plane stress"},
    {"CPS8RT",  &TslGeomQuad8,  &TslFormReducedQuadratic, PLANE_STRESS, "8-node plane stress, reduced integration"},
    {"CPS6T",   &TslGeomTri6,   &TslFormFull,           PLANE_STRESS, "6-node plane stress (CalculiX's CPS6 in a coupled step)"},
    {"CAX3T",   &TslGeomTri3,   &TslFormFull,           AXISYMMETRIC, "3-node axisymmetric"},
    {"CAX4T",   &TslGeomQuad4,  &TslFormFull,           AXISYMMETRIC, "4-node axisymmetric"},
    {"CAX4IT",  &TslGeomQuad4,  &TslFormIncompatible,   AXISYMMETRIC, "4-node axisymmetric, incompatible modes (CAX4I in a coupled or static step)"},
    {"CAX4RT",  &TslGeomQuad4,  &TslFormReduced,        AXISYMMETRIC, "4-node axisymmetric, reduced integration, hourglass control"},
    {"CAX4RHT", &TslGeomQuad4,  &TslFormReducedHybrid,  AXISYMMETRIC, "4-node axisymmetric, reduced integration, hourglass control, hybrid"},
    {"CAX6MT",  &TslGeomTri6,   &TslFormModified,       AXISYMMETRIC, "6-node modified second-order axisymmetric"},
    {"CAX6MHT", &TslGeomTri6,   &TslFormModifiedHybrid, AXISYMMETRIC, "6-node modified second-order axisymmetric, hybrid"},
    {"CAX8T",   &TslGeomQuad8,  &TslFormFull,           AXISYMMETRIC, "8-node axisymmetric"},
    {"CAX8RT",  &TslGeomQuad8,  &TslFormReducedQuadratic, AXISYMMETRIC, "8-node axisymmetric, reduced integration"},
    {"CAX8RHT", &TslGeomQuad8,  &TslFormReducedQuadraticHybrid, AXISYMMETRIC, "8-node axisymmetric, reduced integration, hybrid"},
    {"CAX6T",   &TslGeomTri6,   &TslFormFull,           AXISYMMETRIC, "6-node axisymmetric (CalculiX's CAX6 in a coupled step)"},
    {"CGAX4T",   &TslGeomQuad4, &TslFormFull,           AXITWIST,     "4-node axisymmetric with twist"},
    {"CGAX4RT",  &TslGeomQuad4, &TslFormReduced,        AXITWIST,     "4-node axisymmetric with twist, reduced integration, hourglass control"},
    {"CGAX4RHT", &TslGeomQuad4, &TslFormReducedHybrid,  AXITWIST,     "4-node axisymmetric with twist, reduced integration, hourglass control, hybrid"},
    {"CGAX6MT",  &TslGeomTri6,  &TslFormModified,       AXITWIST,     "6-node modified second-order axisymmetric with twist"},
    {"CGAX6MHT", &TslGeomTri6,  &TslFormModifiedHybrid, AXITWIST,     "6-node modified second-order axisymmetric with twist, hybrid"},
    {"CGAX8T",   &TslGeomQuad8, &TslFormFull,           AXITWIST,     "8-node axisymmetric with twist"},
    {"C3D4T",   &TslGeomTet4,   &TslFormFull,           SOLID,        "4-node tetrahedron"},
    {"C3D6T",   &TslGeomWedge6, &TslFormFull,           SOLID,        "6-node triangular prism"},
    {"C3D8T",   &TslGeomHex8,   &TslFormFull,           SOLID,        "8-node brick"},
    {"C3D8IT",  &TslGeomHex8,   &TslFormIncompatible,   SOLID,        "8-node brick, incompatible modes (C3D8I in a coupled or static step)"},
    {"C3D8RT",  &TslGeomHex8,   &TslFormReduced,        SOLID,        "8-node brick, reduced integration, hourglass control"},
    {"C3D8RHT", &TslGeomHex8,   &TslFormReducedHybrid,  SOLID,        "8-node brick, reduced integration, hourglass control, hybrid"},
    {"C3D10MT", &TslGeomTet10,  &TslFormModified,       SOLID,        "10-node modified second-order tetrahedron"},
    {"C3D10T",  &TslGeomTet10,  &TslFormFullSubFace,    SOLID,        "10-node tetrahedron, pressure on linear sub-faces"},
    {"C3D10HT", &TslGeomTet10,  &TslFormHybridSubFace, SOLID,  "10-node tetrahedron, hybrid, pressure on linear sub-faces"},
    {"C3D20T",  &TslGeomHex20,  &TslFormFull,           SOLID,        "20-node brick"},
    {"C3D20RT", &TslGeomHex20,  &TslFormReducedQuadratic, SOLID,      "20-node brick, reduced integration"},
    {"C3D15T",  &TslGeomWedge15, &TslFormFullSubFace,   SOLID,        "15-node triangular prism, pressure on linear sub-faces (CalculiX's C3D15 in a coupled step)"},
    {"S8RT",    &TslGeomHex20,  &TslFormReducedQuadraticShell, SOLID, "8-node shell expanded: a 20-node brick through half its thickness, reduced integration, pressure on linear sub-faces"},
    {"SC6RT",   &TslGeomWedge6, &TslFormContinuumShell, CSHELL,       "6-node triangular in-plane continuum shell, reduced integration"},
    {"SC8RT",   &TslGeomHex8,   &TslFormContinuumShell, CSHELL,       "8-node hexahedral continuum shell, reduced integration, hourglass control"},
    {"DC2D3",   &TslGeomTri3,   &TslFormFull,           HEAT_PLANE,   "3-node plane heat transfer"},
    {"DC2D4",   &TslGeomQuad4,  &TslFormFull,           HEAT_PLANE,   "4-node plane heat transfer"},
    {"DC2D6",   &TslGeomTri6,   &TslFormFull,           HEAT_PLANE,   "6-node plane heat transfer"},
    {"DC2D8",   &TslGeomQuad8,  &TslFormFull,           HEAT_PLANE,   "8-node plane heat transfer"},
    {"DCAX3",   &TslGeomTri3,   &TslFormFull,           HEAT_AXI,     "3-node axisymmetric heat transfer"},
    {"DCAX4",   &TslGeomQuad4,  &TslFormFull,           HEAT_AXI,     "4-node axisymmetric heat transfer"},
    {"DCAX6",   &TslGeomTri6,   &TslFormFull,           HEAT_AXI,     "6-node axisymmetric heat transfer"},
    {"DCAX8",   &TslGeomQuad8,  &TslFormFull,           HEAT_AXI,     "8-node axisymmetric heat transfer"},
    {"DC1D2",   &TslGeomLine2,  &TslFormFull,           HEAT_LINK,    "2-node heat-transfer link (2D or 3D)"},
    {"DC1D3",   &TslGeomLine3,  &TslFormFull,           HEAT_LINK,    "3-node heat-transfer link (2D or 3D)"},
    {"DC3D4",   &TslGeomTet4,   &TslFormFull,           HEAT_SOLID,   "4-node tetrahedral heat transfer"},
    {"DC3D6",   &TslGeomWedge6, &TslFormFull,           HEAT_SOLID,   "6-node triangular prism heat transfer"},
    {"DC3D8",   &TslGeomHex8,   &TslFormFull,           HEAT_SOLID,   "8-node brick heat transfer"},
    {"DC3D10",  &TslGeomTet10,  &TslFormFull,           HEAT_SOLID,   "10-node tetrahedral heat transfer"},
    {"DC3D15",  &TslGeomWedge15, &TslFormFull,          HEAT_SOLID,   "15-node triangular prism heat transfer"},
    {"DC3D20",  &TslGeomHex20,  &TslFormFull,           HEAT_SOLID,   "20-node brick heat transfer"},
};
// clang-format on

/* Rows whose name is not one of the dialect's: the coupled counterparts of CalculiX's mechanical CPE6, CPS6, CAX6
 * and C3D15, which Abaqus has no coupled temperature-displacement type for (its coupled triangles are the modified
 * ones, CPE6MT, ...; its coupled wedges C3D6T), and of the incompatible-mode types C3D8I, CPE4I, CPS4I, CAX4I (no
 * coupled incompatible-mode type in either). A deck reaches them by the mechanical name in a coupled or static step
 * (src/deck/deck.c); the name with T is refused as the dialect refuses it. */
static const char *const MechanicalOnly[] = {"CPE6T", "CPS6T", "CAX6T", "C3D15T", "CPE4IT", "CPS4IT", "CAX4IT", "C3D8IT"};

PetscBool TslElementTypeMechanicalOnly(const TslElementType *t)
{
  for (size_t i = 0; i < sizeof(MechanicalOnly) / sizeof(MechanicalOnly[0]); i++)
    if (!strcmp(t->name, MechanicalOnly[i])) return PETSC_TRUE;
  return PETSC_FALSE;
}

/* The heat-transfer row of a type's interpolation and measure: a DC row is its own; a coupled or mechanical-name row
 * (C3D8T, C3D8RT, CPS4T, ...) maps to the DC row on its geometry family with its measure (revolved or not), its
 * reduced integration, hybrid pressure and hourglass control being mechanical alone. -1 where none exists (the
 * extra nodes of generalized plane strain; the continuum shells, whose *SHELL SECTION a solid row does not take). */
PetscInt TslElementTypeHeatCounterpart(const TslElementType *t)
{
  if (t->nextra || TslKinematicsRowGet(t->kin)->shell) return -1;
  for (PetscInt i = 0; i < TslElementTypeCount(); i++) {
    const TslElementType *c = &Catalogue[i];
    if (TslElementTypeHeatOnly(c) && c->geom == t->geom && c->dim == t->dim && TslKinematicsRevolves(c->kin) == TslKinematicsRevolves(t->kin))
      return i;
  }
  return -1;
}

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
