# Sourced by the solver checks on the steady block of tests/bench/make_block.py (check_block_solves.sh,
# check_amg_jacobi.sh): with exe, mpiexec, out, bench, tools and size set, writes $out/block.inp of that size and
# defines
#   run NAME RANKS OPTIONS...  the job into $out/NAME (log $out/NAME.log); a failed job fails the check
#   cmp_h5 A B                 the two runs' HDF5 results agree to 1e-8 (compare_h5.py)
rm -rf "$out" && mkdir -p "$out" || exit 1
/usr/bin/python3 "$bench/make_block.py" "$size" "$out/block.inp" || exit 1
run() {
  name=$1 np=$2
  shift 2
  $mpiexec -n "$np" "$exe" "$out/block.inp" -o "$out/$name" "$@" > "$out/$name.log" 2>&1 || { cat "$out/$name.log"; echo "FAIL: $name"; exit 1; }
}
cmp_h5() { /usr/bin/python3 "$tools/compare_h5.py" "$out/$1/block.h5" "$out/$2/block.h5" 1e-8 || { echo "FAIL: $1 against $2"; exit 1; }; }
