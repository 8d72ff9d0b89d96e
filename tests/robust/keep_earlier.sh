#!/bin/sh
# usage: keep_earlier.sh MPIEXEC NP THERMOSLIDE DECK OUTDIR PYTHON
# 1. A good run writes <job>.{h5,xmf,csv}.
# 2. A run whose first step diverges converges nothing: every byte of the earlier results stays, no
#    <job>.failed.* appears, and the log says so.
# 3. A run whose second step diverges keeps step 1 as <job>.failed.{h5,xmf,csv} (the .xmf naming its own
#    .h5) and leaves the earlier results as they were.
mpiexec=$1 np=$2 exe=$3 deck=$4 out=$5 py=$6
job=$(basename "$deck" .inp)
fail() { echo "FAIL: $*"; exit 1; }
rm -rf "$out" && mkdir -p "$out"
timeout 120 "$mpiexec" -n "$np" "$exe" "$deck" -o "$out" > "$out/good.log" 2>&1 || { cat "$out/good.log"; fail "good run"; }
before=$(cd "$out" && md5sum "$job.h5" "$job.xmf" "$job.csv")
timeout 120 "$mpiexec" -n "$np" "$exe" "$deck" -o "$out" -tsl_debug_diverge_step 1 > "$out/none.log" 2>&1 && fail "diverging run exited 0"
cat "$out/none.log"
grep -q "no increment converged: nothing was written; the earlier results stay in $out/$job.h5" "$out/none.log" || fail "no message"
[ "$before" = "$(cd "$out" && md5sum "$job.h5" "$job.xmf" "$job.csv")" ] || fail "earlier results changed"
[ -z "$(ls "$out" | grep -E '\.part|failed')" ] || fail "files left: $(ls "$out")"
timeout 120 "$mpiexec" -n "$np" "$exe" "$deck" -o "$out" -tsl_debug_diverge_step 2 > "$out/later.log" 2>&1 && fail "diverging run exited 0"
cat "$out/later.log"
grep -q "are saved in $out/$job.failed.h5; the earlier results stay in $out/$job.h5" "$out/later.log" || fail "no message"
[ "$before" = "$(cd "$out" && md5sum "$job.h5" "$job.xmf" "$job.csv")" ] || fail "earlier results changed"
[ -z "$(ls "$out" | grep '\.part')" ] || fail "temporary files left"
"$py" - "$out" "$job" <<'PY' || exit 1
import sys, h5py, meshio
out, job = sys.argv[1], sys.argv[2]
f = h5py.File("%s/%s.failed.h5" % (out, job), "r")
steps = sorted(set(int(f["/frames/" + k].attrs["step"]) for k in f["/frames"]))
text = open("%s/%s.failed.xmf" % (out, job)).read()
ok = steps == [1] and "%s.failed.h5:/mesh" % job in text and open("%s/%s.failed.csv" % (out, job)).readline().startswith("step,")
with meshio.xdmf.TimeSeriesReader("%s/%s.failed.xmf" % (out, job)) as r:
    r.read_points_cells()
print("failed run kept beside the earlier one: steps %s, .xmf names its .h5: %s" % (steps, "PASS" if ok else "FAIL"))
sys.exit(0 if ok else 1)
PY
echo "PASS: earlier results intact; a partial run kept beside them"
