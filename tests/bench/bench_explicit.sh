#!/bin/bash
# Explicit dynamics speed (issue 9, "Speed"): increments per second and time per element per increment of
# the explicit update on 1 and 2 ranks, figures only, never pass/fail (ctest -L bench).
#   - block: make_block.py N ... explicit INC, 2N x N x N hexahedra (C3D8T and C3D8RT), fixed increments
#     (DIRECT USER CONTROL), film, pressure and a prescribed temperature, default bulk viscosity;
#   - contact: make_contact_block.py N ... explicit INC, the two-block deck ((N+1)^2 secondary nodes on a
#     penalty node-to-surface pair, pairing searched every 10 increments).
# One output frame at the end, no history rows between frames (-tsl_explicit_history 0). The time per
# increment is the step's loop ("N increments in T s") less its output phase; set-up (element stable
# increments, lumped mass) is printed apart. A size is skipped when the memory extrapolated from the
# largest one run so far (per element) exceeds MemAvailable / 1.5.
# usage: bench_explicit.sh THERMOSLIDE [OUTDIR]
#   env: SIZES (block N, default "16 40 80": 8 k, 128 k, 1.02 M elements), CSIZES (contact N, default "32 64"),
#        INC (increments, default 200; INC_LARGE for blocks of 500 k elements or more, default 50),
#        TYPES (default "C3D8T C3D8RT"), RANKS (default "1 2"), REPEAT (runs of each case, the fastest
#        reported: default 3)
set -u
exe=$1 out=${2:-$PWD/bench-explicit-out}
here=$(cd "$(dirname "$0")" && pwd)
sizes=${SIZES:-16 40 80} csizes=${CSIZES:-32 64} types=${TYPES:-C3D8T C3D8RT} ranks=${RANKS:-1 2}
inc=${INC:-200} inc_large=${INC_LARGE:-50} repeat=${REPEAT:-3}
mkdir -p "$out"
avail=$(awk '/MemAvailable/ {print int($2 / 1024)}' /proc/meminfo)
mb_per_elem=0

# run DECK NP TAG NELEM: REPEAT runs (the fastest counts: this machine's speed moves between runs); prints a
# table row and sets T1 (seconds per increment on 1 rank)
run() {
  local deck=$1 np=$2 tag=$3 nel=$4 log=$out/$3.np$2.log
  local line wall n loop outp setup mem per="" p s r
  for r in $(seq "$repeat"); do
    mpirun -n "$np" "$exe" "$deck" -o "$out/$tag.np$np" -tsl_explicit_history 0 -tsl_partition axis_x > "$log" 2>&1 ||
      { echo "thermoslide failed: $log"; tail -3 "$log"; return 1; }
    line=$(grep -E "^  step 1: [0-9]+ increments in" "$log")
    n=$(echo "$line" | awk '{print $3}') loop=$(echo "$line" | awk '{print $6}')
    wall=$(grep "thermoslide: wall time" "$log" | sed 's/[:,;()]/ /g')
    outp=$(echo "$wall" | awk '{for(i=1;i<=NF;i++) if($i=="output") print $(i+1)}')
    s=$(echo "$wall" | awk '{for(i=1;i<=NF;i++) if($i=="set-up") {print $(i+1); exit}}')
    mem=$(echo "$wall" | awk '{for(i=1;i<=NF;i++) if($i=="memory") print $(i+1)}')
    p=$(echo "($loop - $outp) / $n" | bc -l)
    # the output phase counts the frame at the end too, which can fall outside the printed loop: where it
    # exceeds the loop (a short loop, a slow write), the loop alone
    [ "$(echo "$p <= 0" | bc)" = 1 ] && p=$(echo "$loop / $n" | bc -l)
    if [ -z "$per" ] || [ "$(echo "$p < $per" | bc)" = 1 ]; then per=$p; fi
    if [ -z "${setup:-}" ] || [ "$r" = 1 ] || [ "$(echo "$s < $setup" | bc)" = 1 ]; then setup=$s; fi
  done
  [ "$np" = 1 ] && T1=$per
  printf "%-22s %9d %5s %6d %9.3f %9.4f %10.1f %12.0f %8s %8s\n" "$tag" "$nel" "$np" "$n" "$setup" "$per" "$(echo "1 / $per" | bc -l)" \
    "$(echo "1000000000 * $per / $nel" | bc -l)" "$(echo "$T1 / $per" | bc -l | xargs printf %.2f)" "$mem"
  local m=$(echo "$mem * $np / $nel" | bc -l)
  [ "$(echo "$m > $mb_per_elem" | bc)" = 1 ] && mb_per_elem=$m
  return 0
}

printf "%-22s %9s %5s %6s %9s %9s %10s %12s %8s %8s\n" deck elements ranks incs set-up_s s/inc inc/s ns/elem/inc speed-up MB/rank
for t in $types; do
  for n in $sizes; do
    nel=$((2 * n * n * n)) k=$inc
    [ $nel -ge 500000 ] && k=$inc_large
    need=$(echo "$mb_per_elem * $nel" | bc -l | xargs printf %.0f)
    if [ "$(echo "$need * 1.5 > $avail" | bc)" = 1 ]; then
      echo "block $t N=$n: $nel elements need about $need MB (extrapolated), $avail MB available: skipped"
      continue
    fi
    deck=$out/block_${t}_$n.inp
    /usr/bin/python3 "$here/make_block.py" "$n" "$deck" "$t" explicit "$k"
    for np in $ranks; do run "$deck" "$np" "block_${t}_$n" "$nel"; done
  done
done
for n in $csizes; do
  # base (N+1) x 2 x (N+1) hexahedra, thin block N x 1 x N
  nel=$((2 * (n + 1) * (n + 1) + n * n))
  deck=$out/contact_C3D8T_$n.inp
  /usr/bin/python3 "$here/make_contact_block.py" "$n" "$deck" explicit "$inc"
  for np in $ranks; do run "$deck" "$np" "contact_C3D8T_$n" "$nel"; done
done
echo "s/inc: wall time of the step's increment loop less its output phase, per increment (largest over the ranks; the fastest of $repeat runs);"
echo "ns/elem/inc: that over the elements (all ranks); speed-up: 1-rank time per increment / this one"
