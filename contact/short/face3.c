/* face3.c for the small elements' tangent (short.h). */
#include "short.h"
#include "../face3.c"
