/* Small compatibility layer over the PETSc version Debian ships (3.18). */
#pragma once
#include <petscsys.h>

#if !defined(PETSC_SUCCESS)
#define PETSC_SUCCESS ((PetscErrorCode)0)
#endif

/* Maximum length of a deck name (set, surface, material, amplitude...), including the NUL.
 * The keyword dialect allows 80 characters. */
#define TSL_NAME_LEN 81
