#!/bin/bash
# Steady coupled solve of a 3D block: time, memory and linear iterations as the mesh is refined
# (AMG should keep the iteration count), 1 rank vs 2 ranks, and CalculiX (ccx, its default direct
# solver) on the same deck when it is installed (apt-get install calculix-ccx). Prints figures only.
# usage: bench_steady.sh THERMOSLIDE [OUTDIR] [sizes...]     (default sizes: 8 16 24 32; 32 ~ 143k dofs)
set -u
exe=$1 out=${2:-$PWD/bench-out}
shift 2 || shift $#
sizes=${*:-8 16 24 32}
here=$(cd "$(dirname "$0")" && pwd)
mkdir -p "$out"
printf "%-6s %-5s %9s %8s %8s %9s %s\n" N ranks dofs time_s rss_MB newton linear_its
for n in $sizes; do
  deck=$out/block$n.inp
  /usr/bin/python3 "$here/make_block.py" "$n" "$deck"
  dofs=$(( (2*n+1)*(n+1)*(n+1)*4 ))
  for np in 1 2; do
    log=$out/block$n.np$np.log
    /usr/bin/time -f "%e %M" -o "$out/time" mpirun -n $np "$exe" "$deck" -o "$out/np$np" > "$log" 2>&1 || { echo "run failed: $log"; tail -5 "$log"; continue; }
    read -r t rss < "$out/time"
    its=$(grep -o "newton [0-9]*  linear [0-9]*" "$log" | tail -1)
    # max RSS is per process: with 2 ranks, report the sum over ranks approximately as 2x
    printf "%-6s %-5s %9d %8s %8d %9s %s\n" "$n" "$np" "$dofs" "$t" $(( rss * np / 1024 )) $(echo "$its" | awk '{print $2}') $(echo "$its" | awk '{print $4}')
  done
done
if command -v ccx > /dev/null; then
  n=$(echo $sizes | awk '{print $NF}')
  /usr/bin/python3 "$here/make_block.py" "$n" "$out/ccxblock.inp" C3D8
  (cd "$out" && OMP_NUM_THREADS=1 /usr/bin/time -f "%e %M" -o ccx.time ccx -i ccxblock > ccx.log 2>&1) || echo "ccx failed: $out/ccx.log"
  read -r t rss < "$out/ccx.time"
  printf "CalculiX ccx (default solver, 1 thread), N=%s: %s s, %d MB\n" "$n" "$t" $(( rss / 1024 ))
else
  echo "CalculiX not installed (apt-get install calculix-ccx) - comparison skipped"
fi
