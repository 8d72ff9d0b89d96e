#!/bin/sh
# Writes make_family_decks.py's decks into OUTDIR/decks and runs each on 1 rank into OUTDIR/<deck>/ (the 2-rank
# writing of /mesh/connectivity is output_write_single_type_np3's, and every single-type deck's np1_vs_np2
# comparison elsewhere: radiate_*, dload_*, the verification decks).
# usage: run_family_decks.sh MPIEXEC THERMOSLIDE PYTHON OUTDIR
set -u
mpiexec=$1 exe=$2 python=$3 out=$4
rm -rf "$out" && mkdir -p "$out/decks" || exit 1
"$python" "$(dirname "$0")/make_family_decks.py" "$out/decks" || exit 1
for deck in "$out"/decks/*.inp; do
  name=$(basename "$deck" .inp)
  "$mpiexec" -n 1 "$exe" "$deck" -o "$out/$name" > "$out/$name.log" 2>&1 || { cat "$out/$name.log"; echo "FAIL: $name"; exit 1; }
done
echo "PASS: $(ls "$out"/decks/*.inp | wc -l) decks written and run"
