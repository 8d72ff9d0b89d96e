#!/bin/bash
# The main job: sets everything up, runs the spec's interface-conductance series (a block pressed on a
# larger one, slid back and forth, then off; 5 steps) on 2 ranks with the contact pair split across the
# ranks, and prints its verification checks with their measured values.
#   bash jobs/scripts/demo.sh      (results in out/demo/: .h5 + .xmf for ParaView, .csv history)
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/env.sh"
bash "$TSL_ROOT/jobs/scripts/build.sh"
OUT=${OUT:-$TSL_ROOT/out/demo}
JOB=sliding_conductance_cpe4t
mpirun -n 2 "$TSL_BUILD/thermoslide" "$TSL_ROOT/jobs/verification/$JOB.inp" -o "$OUT" -tsl_partition axis_y
echo
echo "verification checks ($JOB, see docs/verification.md):"
/usr/bin/python3 "$TSL_ROOT/tests/verification/check_sliding.py" "$OUT" "$JOB" conductance
echo "results: $OUT/$JOB.xmf (open in ParaView), $OUT/$JOB.h5, $OUT/$JOB.csv"
