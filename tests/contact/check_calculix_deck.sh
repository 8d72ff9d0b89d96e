#!/bin/sh
# A CalculiX deck runs unchanged: the contact benchmark's CalculiX flavour (tests/bench/make_contact_block.py N
# calculix: C3D8 elements in a coupled step, *SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR, face-to-face
# contact, *NODE PRINT, TOTALS=ONLY of RFL at the hot face) against thermoslide's own flavour of the same model
# (C3D8T, PENALTY with the same stiffness, TYPE=SURFACE TO SURFACE). The CalculiX deck, on 2 ranks, must say
# how it read C3D8, and its printed total RFL (the heat entering at the hot face, all of which crosses the
# interface in the steady state) must equal thermoslide's deck's interface heat (1 rank) to 1e-6 relative (the printed total has 7 digits):
# the two decks are one model. (CalculiX 2.20 itself gives 7401.31 at N = 8 against 7407.79 here.)
# usage: check_calculix_deck.sh THERMOSLIDE MPIEXEC OUTDIR BENCHDIR
set -u
exe=$1 mpiexec=$2 out=$3 bench=$4
rm -rf "$out" && mkdir -p "$out" || exit 1
/usr/bin/python3 "$bench/make_contact_block.py" 6 "$out/ccx.inp" calculix || exit 1
/usr/bin/python3 "$bench/make_contact_block.py" 6 "$out/own.inp" s2s || exit 1
$mpiexec -n 2 "$exe" "$out/ccx.inp" -o "$out/ccx" -tsl_partition axis_x > "$out/ccx.log" 2>&1 || { cat "$out/ccx.log"; exit 1; }
$mpiexec -n 1 "$exe" "$out/own.inp" -o "$out/own" > "$out/own.log" 2>&1 || { cat "$out/own.log"; exit 1; }
cat "$out/ccx.log"
[ "$(grep -c 'note: element type C3D8 read as C3D8T' "$out/ccx.log")" = 1 ] || { echo "FAIL: the C3D8 notes"; exit 1; }
grep -q "warning" "$out/ccx.log" && { echo "FAIL: a warning on the CalculiX deck"; exit 1; }
total=$(sed -n 's/^ *total RFL *//p' "$out/ccx.log")
[ "$(grep -c '^  *[0-9][0-9]* RFL' "$out/ccx.log")" = 0 ] || { echo "FAIL: TOTALS=ONLY printed rows"; exit 1; }
heat=$(/usr/bin/python3 -c 'import csv, sys; print(list(csv.DictReader(open(sys.argv[1])))[-1]["interface_heat"])' "$out/own/own.csv") || exit 1
echo "CalculiX deck: total RFL $total; thermoslide's deck: interface heat $heat"
awk -v a="$total" -v b="$heat" 'BEGIN {d = a + b; if (d < 0) d = -d; s = b < 0 ? -b : b; printf "relative difference %.2e (at most 1e-6)\n", d / s; exit !(a != "" && s > 0 && d <= 1e-6 * s)}' ||
  { echo "FAIL: the two decks disagree"; exit 1; }
echo "PASS"
