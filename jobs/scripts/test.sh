#!/bin/bash
# The whole test suite: sets everything up, builds, and runs ctest (unit, verification, 2-rank, bad input).
#   bash jobs/scripts/test.sh [ctest arguments]
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/env.sh"
bash "$TSL_ROOT/jobs/scripts/build.sh"
cd "$TSL_BUILD"
ctest --output-on-failure -LE bench "$@"
