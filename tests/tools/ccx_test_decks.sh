#!/bin/bash
# Decks we did not write: CalculiX's own test decks (Debian package calculix-ccx-test, installed by
# jobs/scripts/install-deps.sh), run through thermoslide as they stand. Each must either complete, or stop with
# an error that names the deck file and line (input thermoslide does not support, e.g. C3D20R or *STATIC),
# or stop in a step with the message and the results up to the last converged increment saved (a run that
# fails: e.g. contact that does not settle). A crash, a hang (TIMEOUT seconds), or an error without its place
# fails the test. Prints each deck's outcome and a count of the first errors.
# usage: ccx_test_decks.sh THERMOSLIDE MPIEXEC NP OUTDIR [coupled|all]
#   coupled: the decks with a *COUPLED TEMPERATURE-DISPLACEMENT step, a *CONTACT PAIR or a *GAP CONDUCTANCE, but
#   those that ccx_static_decks.sh checks (the suite); all: every deck (long)
set -u
exe=$1 mpiexec=$2 np=$3 out=$4 which=${5:-coupled}
src=/usr/share/doc/calculix-ccx-test/examples/test
timeout=${TIMEOUT:-120}
if ! ls "$src"/*.inp > /dev/null 2>&1; then
  echo "FAIL: CalculiX's test decks are not in $src (jobs/scripts/install-deps.sh installs calculix-ccx-test)"
  exit 1
fi
rm -rf "$out" && mkdir -p "$out" || exit 1
cp "$src"/* "$out"/ && gunzip -f "$out"/*.gz 2> /dev/null
cd "$out" || exit 1
decks=$(ls *.inp)
# coupled: without the contact decks that ccx_static_decks.sh runs and checks against CalculiX's printed
# displacements (verification_calculix_static_decks, also in the default suite: a stricter test of the same runs)
checked="contactenergy contact3 contact6 cubespring hueeber1 hueeber2 hueeber4 ring1 ring2"
if [ "$which" = coupled ]; then
  decks=$(grep -il "^\*coupled temperature-displacement\|^\*contact pair\|^\*gap conductance" $decks)
  for c in $checked; do decks=$(echo "$decks" | grep -vx "$c.inp"); done
fi
for f in $decks; do
  b=${f%.inp}
  timeout -s KILL "$timeout" $mpiexec -n "$np" "$exe" "$f" -o "run_$b" > "$b.log" 2>&1
  rc=$?
  err=$(grep -m1 "thermoslide: error:" "$b.log")
  if [ $rc -eq 0 ] && grep -q "^thermoslide: completed" "$b.log"; then
    outcome=completed
  elif [ $rc -ne 0 ] && [ $rc -lt 124 ] && echo "$err" | grep -qE "^thermoslide: error: [^ ]+:[0-9]+: "; then
    outcome=refused
  elif [ $rc -ne 0 ] && [ $rc -lt 124 ] && echo "$err" | grep -qE "^thermoslide: error: step [0-9]+: " &&
    grep -qE "^(results up to step [0-9]+ increment [0-9]+ are saved in |no increment converged: nothing was written)" "$b.log"; then
    # stopped in a step with its message: the converged increments saved, or none converged (nothing to save,
    # nothing overwritten)
    outcome=stopped
  else
    outcome="FAIL (exit $rc)"
    tail -5 "$b.log" >&2 # not into outcomes.txt, which counts one line per deck
  fi
  echo "$b: $outcome: ${err:-}"
done | tee outcomes.txt
n=$(wc -l < outcomes.txt)
echo
echo "first errors (type of each refusal):"
sed -n 's/^[^:]*: refused: thermoslide: error: [^ ]*:[0-9]*: //p' outcomes.txt | cut -c1-90 | sort | uniq -c | sort -rn | head -30
echo
echo "$n CalculiX test decks on $np rank(s): $(grep -c ': completed:' outcomes.txt) completed, $(grep -c ': refused:' outcomes.txt) refused at a file:line, $(grep -c ': stopped:' outcomes.txt) stopped in a step with the results saved (or none converged), $(grep -c ': FAIL' outcomes.txt) failed"
[ "$n" -gt 0 ] && ! grep -q ": FAIL" outcomes.txt && echo PASS
