/* The contact kernels compiled a second time for values alone (the files of contact/values/, each including one
 * kernel source after this header): dual numbers with the two surface-parameter slots only, so that an
 * evaluation without a tangent (explicit steps, residual evaluations) neither computes nor copies the
 * element unknowns' derivatives. The same operations on the values: the same bits. TslContactElement and
 * TslContactElement3 hand a call without K to their copies here (contact/laws.c, contact/kernel3.c).
 * Their functions carry the suffix _Values (contact/variant.h). */
#pragma once
#define TSL_DUAL_VALUES    1
#define TSL_VARIANT_SUFFIX _Values
#include "../variant.h"
