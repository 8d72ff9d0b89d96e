#!/bin/bash
# *POST OUTPUT (the spec's eip2tssc_cpeg4rht_post: output recovered from the restart data of the CPEG4RHT run): the
# conductance series on CPEG4RHT with *RESTART, WRITE, FREQUENCY=5 (its checks: the spec's outcome), then POST OUTPUT
# decks holding nothing but a heading and *POST OUTPUT, run with -oldjob: ALL gives a frame of every point equal to
# the run's frame of that step and increment (TOL of each field's largest value), data lines give those points' frames
# only; ALL on another rank count gives the same frames; the deck's own field requests after *POST OUTPUT give frames
# of those fields alone; a data line without a point, ALL with data lines, a step, a printed table or an undefined set
# in the deck are errors at their line, with no result written.
# usage: restart_post.sh THERMOSLIDE MPIEXEC NP OUTDIR PYTHON SOURCE_DIR TOL
set -u
exe=$1 mpiexec=$2 np=$3 out=$4 py=$5 src=$6 tol=$7
rm -rf "$out" && mkdir -p "$out/deck" || exit 1
"$py" "$src/jobs/verification/make_decks.py" --sliding CPEG4RHT conductance "$out/deck" || exit 1
awk '!d && toupper($0) ~ /^\*STEP/ {print "*RESTART, WRITE, FREQUENCY=5"; d = 1} {print}' "$out/deck/sliding_conductance_cpeg4rht.inp" > "$out/run.inp"
$mpiexec -n "$np" "$exe" "$out/run.inp" -o "$out/run" > "$out/run.log" 2>&1 || { cat "$out/run.log"; echo "FAIL: the CPEG4RHT run"; exit 1; }
fail=0
"$py" "$src/tests/verification/check_sliding.py" "$out/run" run conductance | tail -n 1 | grep -q "all checks passed" || { echo "FAIL: the CPEG4RHT run's checks"; fail=1; }
post() { # NAME LINES...: a POST OUTPUT deck of a heading and LINES
  local name=$1
  shift
  { printf '*HEADING\nPOST OUTPUT of the CPEG4RHT conductance run\n'; printf '%s\n' "$@"; } > "$out/$name.inp"
  $mpiexec -n "${post_np:-$np}" "$exe" "$out/$name.inp" -oldjob "$out/run/run" -o "$out/$name" > "$out/$name.log" 2>&1
}
if post all "*POST OUTPUT, ALL"; then
  "$py" "$src/tests/tools/compare_post.py" "$out/run/run.h5" "$out/all/all.h5" "$tol" "$out/run" run || { echo "FAIL: all: the recovered frames"; fail=1; }
  ls "$out/all"/*.restart.* > /dev/null 2>&1 && { echo "FAIL: all: the POST OUTPUT job wrote restart data"; fail=1; }
else
  cat "$out/all.log"; echo "FAIL: all: the POST OUTPUT job"; fail=1
fi
# on another rank count: the points read by node, element and face
other=$((np == 1 ? 2 : 1))
if post_np=$other post other "*POST OUTPUT, ALL"; then
  grep -q "the point was written on $np ranks" "$out/other.log" || { cat "$out/other.log"; echo "FAIL: other: no word of the points' rank count"; fail=1; }
  "$py" "$src/tests/tools/compare_post.py" "$out/run/run.h5" "$out/other/other.h5" "$tol" "$out/run" run || { echo "FAIL: other: the frames recovered on $other ranks"; fail=1; }
else
  cat "$out/other.log"; echo "FAIL: other: the POST OUTPUT job on $other ranks"; fail=1
fi
if post two "*POST OUTPUT" " 2, 10" " 4, 1"; then
  "$py" "$src/tests/tools/compare_post.py" "$out/run/run.h5" "$out/two/two.h5" "$tol" || { echo "FAIL: two: the recovered frames"; fail=1; }
  n=$("$py" -c "import h5py, sys; print(len(h5py.File(sys.argv[1])['frames']))" "$out/two/two.h5")
  [ "$n" = 2 ] || { echo "FAIL: two: $n frames, expected 2"; fail=1; }
else
  cat "$out/two.log"; echo "FAIL: two: the POST OUTPUT job"; fail=1
fi
# the deck's own output requests after *POST OUTPUT: the frames hold those fields (NT and U here), not the run's
if post own "*POST OUTPUT, ALL" "*OUTPUT, FIELD" "*NODE OUTPUT" " NT, U"; then
  FIELDS="NT U" "$py" "$src/tests/tools/compare_post.py" "$out/run/run.h5" "$out/own/own.h5" "$tol" "$out/run" run || { echo "FAIL: own: the frames of the deck's own requests"; fail=1; }
else
  cat "$out/own.log"; echo "FAIL: own: the POST OUTPUT job with its own requests"; fail=1
fi
bad() { # NAME EXPECTED LINES...
  local name=$1 want=$2
  shift 2
  if post "$name" "$@" || ! grep -qF -- "$want" "$out/$name.log"; then cat "$out/$name.log"; echo "FAIL: $name: expected an error with: $want"; fail=1; return; fi
  ls "$out/$name"/*.h5 > /dev/null 2>&1 && { echo "FAIL: $name: results were written"; fail=1; }
  echo "$name: $(grep -m1 -F -- "$want" "$out/$name.log" | sed 's/^.*error: //')"
}
bad nopoint "$out/nopoint.inp:5: *POST OUTPUT, STEP=2, INC=7: the old job $out/run/run wrote no restart point there (its points of that step: increments 5, 10" "*POST OUTPUT" " 2, 5" " 2, 7"
bad alldata "$out/alldata.inp:4: *POST OUTPUT, ALL takes no data lines" "*POST OUTPUT, ALL" " 2, 5"
bad ownstep "$out/ownstep.inp:4: *STEP in a POST OUTPUT deck: after *POST OUTPUT it holds output requests only" "*POST OUTPUT, ALL" "*STEP" "*STATIC"
bad ownprint "$out/ownprint.inp:4: *NODE PRINT in a POST OUTPUT deck: its frames take field output requests" "*POST OUTPUT, ALL" "*NODE PRINT, NSET=ALL" " NT"
bad ownset "$out/ownset.inp:4: undefined node set NOSUCH" "*POST OUTPUT, ALL" "*NODE OUTPUT, NSET=NOSUCH" " NT"
[ $fail = 0 ] && echo PASS
exit $fail
