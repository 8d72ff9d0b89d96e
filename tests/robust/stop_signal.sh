#!/bin/bash
# A job asked to stop by a signal (src/sys/stop.c) stops at its next check with the last converged state saved
# under the usual names, no .part file left, and the exit status 128 + the signal, on 2 ranks through mpirun:
#   implicit: the spec's conductance series, SIGUSR1 to mpirun (which forwards it) during step 2; the saved last
#             frame must equal the uninterrupted run's frame of that increment (1e-9);
#   explicit: a C3D8T block of 200 000 increments, SIGUSR1 once the first progress line is out; its last frame is
#             the increment the log names.
# The messages are matched anywhere on a line: the stop message goes to stderr, which may land mid-line of stdout.
# usage: stop_signal.sh THERMOSLIDE MPIEXEC OUTDIR DECKDIR MAKE_BLOCK
set -u
exe=$1 mpiexec=$2 out=$3 decks=$4 make_block=$5
rm -rf "$out" && mkdir -p "$out" || exit 1
cd "$out" || exit 1
fail=0
bad() { echo "FAIL: $*"; fail=1; }

# run_and_stop DECK DIR PATTERN: starts the job, waits for PATTERN in its log (60 s at most), sends SIGUSR1 to
# mpirun, waits for the job; sets rc
run_and_stop() {
  local deck=$1 dir=$2 pattern=$3 pid
  $mpiexec -n 2 "$exe" "$deck" -o "$dir" > "$dir.log" 2>&1 &
  pid=$!
  for _ in $(seq 1 3000); do grep -q "$pattern" "$dir.log" 2> /dev/null && break; kill -0 $pid 2> /dev/null || break; sleep 0.02; done
  kill -USR1 $pid 2> /dev/null
  wait $pid
  rc=$?
}

# implicit
$mpiexec -n 2 "$exe" "$decks/sliding_conductance_cpe4t.inp" -o ref > ref.log 2>&1 || bad "the uninterrupted run"
run_and_stop "$decks/sliding_conductance_cpe4t.inp" imp "step 2 increment 3:"
[ "$rc" = 138 ] || bad "implicit: exit status $rc, expected 138 (128 + SIGUSR1)"
grep -q "thermoslide: stopped: step 2: SIGUSR1 received at step time" imp.log || bad "implicit: no stop message"
ls imp/*.part > /dev/null 2>&1 && bad "implicit: .part files left"
line=$(grep "^results up to step 2 increment [0-9]* are saved in imp/sliding_conductance_cpe4t.h5$" imp.log)
[ -n "$line" ] || bad "implicit: where the results went is not said"
inc=$(echo "$line" | awk '{print $7}')
/usr/bin/python3 - "$inc" << 'PY' || fail=1
import sys, h5py, numpy as np
inc = int(sys.argv[1])
a, b = h5py.File("imp/sliding_conductance_cpe4t.h5", "r"), h5py.File("ref/sliding_conductance_cpe4t.h5", "r")
last = a["frames"][sorted(a["frames"])[-1]]
assert last.attrs["step"] == 2 and last.attrs["increment"] == inc, dict(last.attrs)
ref = [b["frames"][k] for k in b["frames"] if b["frames"][k].attrs["step"] == 2 and b["frames"][k].attrs["increment"] == inc][0]
d = max(np.abs(last[f][...] - ref[f][...]).max() / max(np.abs(ref[f][...]).max(), 1e-30) for f in ("U", "NT"))
print(f"implicit: stopped after step 2 increment {inc}; its frame against the uninterrupted run's: {d:.2e} (1e-9: two 2-rank runs of the same deck differ in the last digits, MUMPS's parallel factorisation)")
sys.exit(0 if d <= 1e-9 else 1)
PY

# explicit
/usr/bin/python3 "$make_block" 6 block.inp C3D8T explicit 200000 || bad "make_block"
run_and_stop block.inp exp "step 1 increment 5000:"
[ "$rc" = 138 ] || bad "explicit: exit status $rc, expected 138"
msg=$(grep -o "thermoslide: stopped: explicit step Step-1: SIGUSR1 received at step time.*" exp.log)
[ -n "$msg" ] || bad "explicit: no stop message"
ls exp/*.part > /dev/null 2>&1 && bad "explicit: .part files left"
inc=$(echo "$msg" | sed 's/.*in increment \([0-9]*\);.*/\1/')
/usr/bin/python3 -c "
import sys, h5py
f = h5py.File('exp/block.h5', 'r'); last = f['frames'][sorted(f['frames'])[-1]]
print('explicit: stopped at increment', last.attrs['increment'], 'of about 200 000, its frame saved')
sys.exit(0 if last.attrs['increment'] == int('$inc') else 1)" || bad "explicit: the last frame is not increment $inc"
[ $fail = 0 ] && echo PASS || echo FAIL
exit $fail
