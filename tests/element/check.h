/* The element unit tests' checks: the shared harness (tests/common/tsl_check.h). */
#pragma once
#include <thermoslide/element.h>
#include "../common/tsl_check.h"
