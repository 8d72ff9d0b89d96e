#!/bin/sh
# usage: fault.sh MPIEXEC THERMOSLIDE DECK OUTDIR KIND PYTHON CHECK_SLIDING
# A failure of KIND (converge | internal | output | element) injected on rank 1 only, in step 2, on 2 ranks with the
# contact pair split across them. Nothing may hang (timeout), print a trace or a source path, or leave
# temporary files; see tests/robust/CMakeLists.txt for what each kind must give.
mpiexec=$1 exe=$2 deck=$3 out=$4 kind=$5 py=$6 check=$7
job=$(basename "$deck" .inp)
rm -rf "$out" && mkdir -p "$out"
fail() { echo "FAIL: $*"; exit 1; }
# the frames kept are step 1's: the failure came in step 2 before a frame of it
steps_saved() {
  "$py" - "$out" "$job" <<'PY' || exit 1
import sys, h5py
f = h5py.File("%s/%s.h5" % (sys.argv[1], sys.argv[2]), "r")
steps = sorted(set(int(f["/frames/" + k].attrs["step"]) for k in f["/frames"]))
print("frames saved for steps %s (the last converged state is the end of step 1)" % steps)
sys.exit(0 if steps == [1] else 1)
PY
}
if [ "$kind" = output ]; then
  timeout 300 "$mpiexec" -n 2 "$exe" "$deck" -o "$out" > "$out/good.log" 2>&1 || { cat "$out/good.log"; fail "good run"; }
  before=$(cd "$out" && md5sum "$job.h5" "$job.xmf" "$job.csv")
fi
# An internal error abandons PETSc objects in mid-call by PETSc's design: -malloc_dump (set by the suite)
# would list them, which is not what this test is about.
[ "$kind" = converge ] || export PETSC_OPTIONS=""
timeout 300 "$mpiexec" -n 2 "$exe" "$deck" -o "$out" -tsl_partition axis_y -tsl_debug_fail_kind "$kind" -tsl_debug_fail_rank 1 \
  -tsl_debug_fail_step 2 > "$out/log" 2>&1
rc=$?
cat "$out/log"
[ $rc -ne 124 ] || fail "timed out: a rank hung"
grep -q "secondary nodes on ranks 1; main-surface nodes on ranks 0" "$out/log" || fail "the contact pair is not split across the ranks"
! grep -Eq '\.c:[0-9]|PETSC ERROR|error [0-9]+ in ' "$out/log" || fail "a trace or a source path in the log"
[ -z "$(ls "$out" | grep '\.part')" ] || fail "temporary files left: $(ls "$out" | grep '\.part')"
case $kind in
converge)
  [ $rc -eq 0 ] || fail "exit code $rc"
  grep -q "injected convergence failure.*(rank 1); cutback" "$out/log" || fail "no cutback naming the failure"
  "$py" "$check" "$out" "$job" friction || exit 1 ;;
internal)
  [ $rc -ne 0 ] || fail "exit code 0"
  [ "$(grep -c 'error' "$out/log")" -eq 1 ] || fail "not exactly one error message"
  grep -q "internal error (code [0-9]*): injected internal failure" "$out/log" || fail "no clear message"
  steps_saved ;;
element)
  [ $rc -ne 0 ] || fail "exit code 0"
  [ "$(grep -c 'error' "$out/log")" -eq 1 ] || fail "not exactly one error message"
  grep -q "internal error (code [0-9]*): .*injected element output failure" "$out/log" || fail "no clear message"
  steps_saved ;;
output)
  [ $rc -ne 0 ] || fail "exit code 0"
  [ "$(grep -c 'error' "$out/log")" -eq 1 ] || fail "not exactly one error message"
  grep -q "writing .*$job.h5.part failed" "$out/log" || fail "no clear message"
  after=$(cd "$out" && md5sum "$job.h5" "$job.xmf" "$job.csv")
  [ "$before" = "$after" ] || fail "earlier results changed" ;;
esac
echo "PASS: $kind failure on rank 1 handled on both ranks"
