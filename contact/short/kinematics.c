/* kinematics.c for the small elements' tangent (short.h). */
#include "short.h"
#include "../kinematics.c"
