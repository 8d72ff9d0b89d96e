/* kinematics.c for values alone (values.h). */
#include "values.h"
#include "../kinematics.c"
