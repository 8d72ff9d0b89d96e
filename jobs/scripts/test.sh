#!/bin/bash
# The whole test suite: sets everything up, builds, and runs ctest (unit, verification, 2-rank, bad input)
# two at a time.
#   bash jobs/scripts/test.sh [ctest arguments]
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/env.sh"
bash "$TSL_ROOT/jobs/scripts/build.sh"
cd "$TSL_BUILD"
# -j2: the machine's two cores; 2-rank runs claim both (PROCESSORS 2, tests/CMakeLists.txt)
ctest --output-on-failure -LE "bench|long" -j2 "$@"
