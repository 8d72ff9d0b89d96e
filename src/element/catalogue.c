/* The element catalogue: one row per deck type name, and the lookups.
 *
 * The geometry families the rows point at (shape functions, quadrature, faces in the dialect's
 * numbering) are in geometry.c.
 */
#include "element_impl.h"
#include <ctype.h>
#include <string.h>

/* ---- deck types -------------------------------------------------------------------------------- */

static const TslElementType Catalogue[] = {
    {"CPE4T", &TslGeomQuad4, TSL_KIN_PLANE_STRAIN, 2, 3, PETSC_FALSE, PETSC_FALSE, "4-node plane strain, coupled temperature-displacement"},
    {"CPS4T", &TslGeomQuad4, TSL_KIN_PLANE_STRESS, 2, 3, PETSC_FALSE, PETSC_FALSE, "4-node plane stress, coupled temperature-displacement"},
    {"CAX4T", &TslGeomQuad4, TSL_KIN_AXISYMMETRIC, 2, 3, PETSC_FALSE, PETSC_FALSE, "4-node axisymmetric, coupled temperature-displacement"},
    {"C3D8T", &TslGeomHex8, TSL_KIN_SOLID3D, 3, 4, PETSC_FALSE, PETSC_FALSE, "8-node brick, coupled temperature-displacement"},
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
