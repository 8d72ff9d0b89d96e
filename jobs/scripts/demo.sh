#!/bin/bash
# The main job: sets everything up, runs a verification problem on 2 ranks and prints its checks.
#   bash jobs/scripts/demo.sh            (results in out/demo/: .h5 + .xmf for ParaView, .csv history)
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/env.sh"
bash "$TSL_ROOT/jobs/scripts/build.sh"
OUT=${OUT:-$TSL_ROOT/out/demo}
DECK=$TSL_ROOT/jobs/verification/conduction_transient_cpe4t.inp
mpirun -n 2 "$TSL_BUILD/thermoslide" "$DECK" -o "$OUT"
echo
echo "verification checks:"
/usr/bin/python3 "$TSL_ROOT/tests/verification/check_conduction_transient.py" "$OUT" conduction_transient_cpe4t
