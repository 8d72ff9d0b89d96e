#!/bin/sh
# Implicit residuals from the element force records (-tsl_implicit_records, docs/running.md): every deck run with
# the records (the default) and with the generic kernels (-tsl_implicit_records 0) gives the same results, HDF5 to
# 1e-8 (compare_h5.py) and the history's energies (strain, hourglass) and heat columns to 1e-8 of the
# column's largest value, with the records in use (the log's count above zero). Decks: the spec's friction series
# (CPE4T, contact, 3 steps), the transient conduction deck (capacity terms), and from make_decks.py the
# conductance series on C3D8RT (hourglass energy) and CAX8T (axisymmetric quadratic).
# usage: check_implicit_records.sh THERMOSLIDE MPIEXEC NP OUTDIR JOBSDIR TOOLSDIR
set -u
exe=$1 mpiexec=$2 np=$3 out=$4 jobs=$5 tools=$6
rm -rf "$out" && mkdir -p "$out/decks" || exit 1
cp "$jobs/sliding_friction_cpe4t.inp" "$jobs/conduction_transient_cpe4t.inp" "$out/decks/" || exit 1
/usr/bin/python3 "$jobs/make_decks.py" --sliding C3D8RT conductance "$out/decks" > /dev/null || exit 1
/usr/bin/python3 "$jobs/make_decks.py" --sliding CAX8T conductance "$out/decks" > /dev/null || exit 1
for deck in "$out"/decks/*.inp; do
  job=$(basename "$deck" .inp)
  for mode in records generic; do
    opt=""
    [ $mode = generic ] && opt="-tsl_implicit_records 0"
    # shellcheck disable=SC2086
    $mpiexec -n "$np" "$exe" "$deck" -o "$out/$mode/$job" $opt > "$out/$job.$mode.log" 2>&1 || { cat "$out/$job.$mode.log"; echo "FAIL: $job ($mode)"; exit 1; }
  done
  n=$(sed -n 's/.*force records: \([0-9]*\) of.*/\1/p' "$out/$job.records.log" | head -1)
  echo "$job: $n elements with a record"
  [ "${n:-0}" -gt 0 ] || { echo "FAIL: $job: no element took a record"; exit 1; }
  /usr/bin/python3 "$tools/compare_h5.py" "$out/records/$job/$job.h5" "$out/generic/$job/$job.h5" 1e-8 || { echo "FAIL: $job: HDF5"; exit 1; }
  /usr/bin/python3 - "$out/records/$job/$job.csv" "$out/generic/$job/$job.csv" <<'PY' || { echo "FAIL: $job: history"; exit 1; }
import csv, sys
a, b = (list(csv.DictReader(open(f))) for f in sys.argv[1:3])
assert len(a) == len(b), "different numbers of history rows"
for col in ("strain_energy", "hourglass_energy", "balance_residual", "film_heat_out", "interface_heat"):
    if col not in a[0]:
        continue
    # the balance is a round-off residual: measured against the heat that flows
    cols = ("heat_in", "film_heat_out", "interface_heat", col) if col == "balance_residual" else (col,)
    scale = max(max(abs(float(r[c])) for r in a for c in cols), 1e-300)
    d = max(abs(float(x[col]) - float(y[col])) for x, y in zip(a, b))
    print(f"  {col}: largest difference {d:.3e} of {scale:.4g}")
    assert d <= 1e-8 * scale or d <= 1e-12, col
PY
done
echo "PASS"
