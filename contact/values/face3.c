/* face3.c for values alone (values.h). */
#include "values.h"
#include "../face3.c"
