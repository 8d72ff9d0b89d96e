#!/bin/sh
# Contact that does not settle, and the same model made continuous (decks/contact_closure_jump_c3d8.inp, written
# the way a CalculiX user writes it: C3D8 in a coupled step, *CONTROLS, a zero minimum increment).
#  1. As written, *GAP CONDUCTANCE has one row: it conducts only while the gap is closed. Closing cools the heated
#     block, which opens the gap again, so once the gap is about to close no state is consistent. The job must
#     stop with a non-zero exit, each cutback saying that contact did not settle (the cause explained once, with
#     the docs section), the minimum-increment error, and the results up to the last converged increment saved.
#  2. With the conductance falling from 1 at zero clearance to 0 at 1e-3 (continuous) the step completes and
#     ends steady: the interface heat of the last three rows equal to 1e-6, and the net heat through the
#     prescribed temperatures (in at the hot face, out at the bottom) below 1e-6 of it.
# usage: check_closure_jump.sh THERMOSLIDE MPIEXEC NP DECK OUTDIR
set -u
exe=$1 mpiexec=$2 np=$3 deck=$4 out=$5
rm -rf "$out" && mkdir -p "$out" || exit 1
$mpiexec -n "$np" "$exe" "$deck" -o "$out/jump" > "$out/jump.log" 2>&1
rc=$?
cat "$out/jump.log"
[ $rc -ne 0 ] || { echo "FAIL: the jump deck must stop with an error"; exit 1; }
grep -q "increment control: \*CONTROLS (.*contact_closure_jump_c3d8.inp:66): grow x1.5 after two increments of at most 4 Newton iterations" "$out/jump.log" || { echo "FAIL: the deck's *CONTROLS applied"; exit 1; }
n=$(grep -c "^    contact did not settle: in each of the last [0-9]* residual evaluations" "$out/jump.log")
[ "$n" -ge 2 ] || { echo "FAIL: every cutback should say that contact did not settle ($n)"; exit 1; }
[ "$(grep -c 'docs/contact.md, "Contact that does not settle"' "$out/jump.log")" = 1 ] || { echo "FAIL: the cause explained once"; exit 1; }
grep -q "error: step 1: the increment fell below the minimum 1e-08" "$out/jump.log" || { echo "FAIL: the minimum increment (0 in the deck: the default 1e-5 x period)"; exit 1; }
grep -q "results up to step 1 increment [1-9][0-9]* are saved in $out/jump/contact_closure_jump_c3d8.h5" "$out/jump.log" || { echo "FAIL: results saved"; exit 1; }

awk '/^\*GAP CONDUCTANCE/ {print; getline; print "1., 0."; print "0., 1.E-3"; next} 1' "$deck" > "$out/continuous.inp" || exit 1
$mpiexec -n "$np" "$exe" "$out/continuous.inp" -o "$out/continuous" > "$out/continuous.log" 2>&1 || { cat "$out/continuous.log"; echo "FAIL: the continuous deck"; exit 1; }
grep -q "contact did not settle" "$out/continuous.log" && { echo "FAIL: the continuous deck chattered"; exit 1; }
/usr/bin/python3 - "$out/continuous/continuous.csv" << 'PY' || exit 1
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
last = rows[-1]
q = [float(r["interface_heat"]) for r in rows[-3:]]
net = float(last["reaction_heat"])
print(f"end time {last['time']}, interface heat {q}, net heat through prescribed temperatures {net:.3e}")
ok = abs(float(last["time"]) - 1e-3) < 1e-12 and abs(q[0]) > 100 and max(abs(x - q[-1]) for x in q) <= 1e-6 * abs(q[-1]) and abs(net) <= 1e-6 * abs(q[-1])
print("PASS" if ok else "FAIL: not completed or not steady")
sys.exit(0 if ok else 1)
PY
