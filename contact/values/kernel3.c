/* kernel3.c for values alone (values.h). */
#include "values.h"
#include "../kernel3.c"
