/* laws.c for values alone (values.h). */
#include "values.h"
#include "../laws.c"
