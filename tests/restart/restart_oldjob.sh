#!/bin/bash
# A restart deck (*RESTART, READ with -oldjob DIR/JOB, docs/running.md "Restart"): the spec's friction series (press,
# slide, equilibrate) with *RESTART, WRITE, FREQUENCY=10 is the old job; restart decks that hold no model, only
# *RESTART, READ and a step appended after it:
#   STEP=2, INC=20 and the old deck's step 3 again: the old job's results and history (TOL: bitwise on one rank);
#   STEP=2 (the step's latest point, its end) and the same step: likewise;
#   STEP=2, INC=60, END STEP: the slide ends halfway (step time 1.5 of 3): the frictional heat stops at half the
#   series' 120 generated and 60 absorbed, and the equilibration follows from there;
# new sets and amplitudes defined after *RESTART, READ for the deck's own step; and bad restart decks (new model data
# other than sets, surfaces and amplitudes among them): an increment without a point, a step the old job does not have, no -oldjob, *RESTART, READ
# after model data, a corrupted point, no deck copy: each a clear error naming the deck line, no result written.
# usage: restart_oldjob.sh THERMOSLIDE MPIEXEC NP DECK OUTDIR PYTHON COMPARE TOL
set -u
exe=$1 mpiexec=$2 np=$3 deck=$4 out=$5 py=$6 compare=$7 tol=$8
rm -rf "$out" && mkdir -p "$out" || exit 1
awk '!d && toupper($0) ~ /^\*STEP/ {print "*RESTART, WRITE, FREQUENCY=10"; d = 1} {print}' "$deck" > "$out/old.inp"
$mpiexec -n "$np" "$exe" "$out/old.inp" -o "$out/oldrun" > "$out/old.log" 2>&1 || { cat "$out/old.log"; echo "FAIL: the old job"; exit 1; }
[ -s "$out/oldrun/old.restart.inp" ] || { echo "FAIL: the old job kept no deck copy (old.restart.inp)"; exit 1; }
step3=$(grep -n -i '^\*STEP' "$out/old.inp" | sed -n 3p | cut -d: -f1)
# restart DECKNAME READLINE: a restart deck of a heading, READLINE and the old deck's third step
restart() {
  { printf '*HEADING\nrestart of the friction series\n%s\n' "$2"; tail -n +"$step3" "$out/old.inp"; } > "$out/$1.inp"
}
fail=0
for c in "inc20:*RESTART, READ, STEP=2, INC=20" "latest:*RESTART, READ, STEP=2"; do
  name=${c%%:*}
  restart "$name" "${c#*:}"
  $mpiexec -n "$np" "$exe" "$out/$name.inp" -oldjob "$out/oldrun/old" -o "$out/$name" > "$out/$name.log" 2>&1 || { cat "$out/$name.log"; echo "FAIL: $name: the restart job"; fail=1; continue; }
  grep -o "continuing from restart point .*: step [0-9]* increment [0-9]*" "$out/$name.log"
  "$py" "$compare" "$out/oldrun/old.h5" "$out/$name/$name.h5" "$tol" || { echo "FAIL: $name: the results differ from the old job's"; fail=1; }
  [ "$(wc -l < "$out/oldrun/old.csv")" = "$(wc -l < "$out/$name/$name.csv")" ] || { echo "FAIL: $name: history rows lost or duplicated"; fail=1; }
done

restart endstep "*RESTART, READ, STEP=2, INC=60, END STEP"
if $mpiexec -n "$np" "$exe" "$out/endstep.inp" -oldjob "$out/oldrun/old" -o "$out/endstep" > "$out/endstep.log" 2>&1; then
  grep -q "step 2 ends at the restart point, step time 1.5 of 3" "$out/endstep.log" || { cat "$out/endstep.log"; echo "FAIL: endstep: the step did not end at the point"; fail=1; }
  "$py" - "$out/endstep/endstep.csv" << 'EOF' || fail=1
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
gen, absorbed = float(rows[-1]["friction_dissipation_total"]), float(rows[-1]["friction_heat_total"])
steps = [int(float(r["step"])) for r in rows]
ok = abs(gen - 60) < 0.06 and abs(absorbed - 30) < 0.03 and steps[-1] == 3
print("endstep: generated %.4f (60 +- 0.06), absorbed %.4f (30 +- 0.03), last step %d: %s" % (gen, absorbed, steps[-1], "ok" if ok else "FAIL"))
sys.exit(0 if ok else 1)
EOF
else
  cat "$out/endstep.log"; echo "FAIL: endstep: the restart job"; fail=1
fi

# new sets and amplitudes for the restart deck's own step (the dialect allows them after *RESTART, READ): the slide
# ends at its end point, then node 1031 (a new node set) is pushed to u1 = 0.2 along a new amplitude
cat > "$out/newdata.inp" << 'EOF'
*HEADING
restart with a new amplitude and a new node set
*RESTART, READ, STEP=2, END STEP
*AMPLITUDE, NAME=BACK
 0.0, 0.0, 1.0, 1.0
*NSET, NSET=PUSH
 1031
*STEP, NAME=BACK, INC=100
*COUPLED TEMPERATURE-DISPLACEMENT
 0.1, 1.0
*BOUNDARY, AMPLITUDE=BACK
 PUSH, 1, 1, 0.2
*END STEP
EOF
if $mpiexec -n "$np" "$exe" "$out/newdata.inp" -oldjob "$out/oldrun/old" -o "$out/newdata" > "$out/newdata.log" 2>&1; then
  "$py" - "$out/newdata/newdata.h5" << 'EOF' || fail=1
import sys
import h5py
import numpy as np
f = h5py.File(sys.argv[1], "r")
i = int(np.where(f["mesh/node_ids"][...] == 1031)[0][0])
bad = n = 0
for k in sorted(f["frames"]):
    g = f["frames"][k]
    if int(g.attrs["step"]) != 3:
        continue
    t = float(g.attrs["time"]) - 4.0  # step 3's time: the old job's steps took 1 + 3
    n += 1
    bad += abs(float(g["U"][i][0]) - 0.2 * t) > 1e-12
print("newdata: u1 of node 1031 in %d frames of step 3 along the new amplitude (0.2 t): %s" % (n, "ok" if n and not bad else "FAIL"))
sys.exit(1 if bad or not n else 0)
EOF
else
  cat "$out/newdata.log"; echo "FAIL: newdata: the restart job with a new amplitude and node set"; fail=1
fi

# bad restart decks: NAME READLINE EXPECTED [DECK-EDIT]
bad() {
  local name=$1 line=$2 want=$3 opts=${4:--oldjob $out/oldrun/old}
  restart "$name" "$line"
  # shellcheck disable=SC2086
  $mpiexec -n "$np" "$exe" "$out/$name.inp" $opts -o "$out/$name.out" > "$out/$name.log" 2>&1
  local rc=$?
  if [ $rc = 0 ] || ! grep -qF -- "$want" "$out/$name.log"; then cat "$out/$name.log"; echo "FAIL: $name: expected an error with: $want"; fail=1; return; fi
  ls "$out/$name.out"/*.h5 > /dev/null 2>&1 && { echo "FAIL: $name: results were written"; fail=1; }
  echo "$name: $(grep -m1 -F -- "$want" "$out/$name.log" | sed 's/^.*error: //')"
}
bad noinc "*RESTART, READ, STEP=2, INC=25" "$out/noinc.inp:3: *RESTART, READ, STEP=2, INC=25: the old job $out/oldrun/old wrote no restart point there (its points of that step: increments 10, 20, 30, 40, 50, 60, 70, 80, 90, 100, 110, 120)"
bad nostep "*RESTART, READ, STEP=9" "$out/nostep.inp:3: *RESTART, READ, STEP=9: the old job $out/oldrun/old wrote no restart point there (none in that step)"
bad nooldjob "*RESTART, READ, STEP=2" "$out/nooldjob.inp:3: *RESTART, READ continues an old job: name it with -oldjob DIR/JOB" " "
bad afternode "*NODE
 999, 0., 0.
*RESTART, READ, STEP=2" "$out/afternode.inp:5: *RESTART, READ comes first in its deck"
bad newmaterial "*RESTART, READ, STEP=2, END STEP
*MATERIAL, NAME=NEW" "$out/newmaterial.inp:4: *MATERIAL is model data: it belongs before the first *STEP"
cp -r "$out/oldrun" "$out/nocopy" && rm "$out/nocopy/old.restart.inp"
bad nocopy "*RESTART, READ, STEP=2" "the old job's deck copy $out/nocopy/old.restart.inp is not there" "-oldjob $out/nocopy/old"
cp -r "$out/oldrun" "$out/corrupt"
"$py" -c "import h5py, sys; f = h5py.File(sys.argv[1], 'r+'); x = f['X']; v = x[...]; v.flat[len(v.flat) // 2] += 1e-3; x[...] = v" "$out/corrupt/old.restart.2.20.h5" || exit 1
bad corrupt "*RESTART, READ, STEP=2, INC=20" "$out/corrupt.inp:3: *RESTART, READ: restart point $out/corrupt/old.restart.2.20.h5 is not usable: corrupted" "-oldjob $out/corrupt/old"
[ $fail = 0 ] && echo PASS
exit $fail
