/* The contact kernels compiled a third time for the tangent of the small elements (the files of contact/short/,
 * each including one kernel source after this header): dual numbers with TSL_DUAL_SHORT_DOF unknowns' slots
 * instead of TSL_CONTACT_MAX_DOF, which every element with at most that many unknowns fits (2D linear faces,
 * with twist too; 3D tri3 and quad4 faces). The slots an element does not use were zeros carried through
 * every operation; without them the same operations on the slots it uses give the same bits.
 * TslContactElement and TslContactElement3 hand such an element to their copies here (contact/laws.c,
 * contact/kernel3.c). Their functions carry the suffix _Short (contact/variant.h). */
#pragma once
#define TSL_DUAL_SHORT     1
#define TSL_VARIANT_SUFFIX _Short
#include "../variant.h"
