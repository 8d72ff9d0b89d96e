#!/bin/bash
# Installs the dependencies if missing, then configures and builds thermoslide in $TSL_BUILD (default build/).
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/env.sh"
bash "$TSL_ROOT/jobs/scripts/install-deps.sh"
cmake -S "$TSL_ROOT" -B "$TSL_BUILD" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DTSL_WERROR=ON
cmake --build "$TSL_BUILD"
