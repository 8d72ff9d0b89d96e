/* kernel3.c for the small elements' tangent (short.h). */
#include "short.h"
#include "../kernel3.c"
