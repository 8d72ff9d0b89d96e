#!/bin/sh
# usage: diverge.sh MPIEXEC NP THERMOSLIDE DECK OUTDIR PYTHON
# Step 2 is made to diverge (-tsl_debug_diverge_step 2): the increment must be cut back down to the
# minimum, the run must stop with a clear message and a non-zero exit, and the results of step 1 (the
# last converged state) must be saved.
mpiexec=$1 np=$2 exe=$3 deck=$4 out=$5 py=$6
job=$(basename "$deck" .inp)
rm -rf "$out" && mkdir -p "$out"
timeout 120 "$mpiexec" -n "$np" "$exe" "$deck" -o "$out" -tsl_debug_diverge_step 2 > "$out/log" 2>&1
rc=$?
cat "$out/log"
[ $rc -ne 0 ] && [ $rc -ne 124 ] || { echo "FAIL: exit code $rc"; exit 1; }
grep -q "cutback" "$out/log" || { echo "FAIL: no cutback"; exit 1; }
grep -q "fell below the minimum" "$out/log" || { echo "FAIL: no clear message"; exit 1; }
"$py" - "$out" "$job" <<'PY' || exit 1
import sys, h5py
f = h5py.File("%s/%s.h5" % (sys.argv[1], sys.argv[2]), "r")
steps = [int(f["/frames/" + k].attrs["step"]) for k in f["/frames"]]
ok = steps and max(steps) == 1
print("frames saved: steps %s -> %s" % (sorted(set(steps)), "PASS" if ok else "FAIL"))
sys.exit(0 if ok else 1)
PY
echo "PASS: cutback, message, last converged state saved"
