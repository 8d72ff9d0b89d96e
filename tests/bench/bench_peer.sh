#!/bin/bash
# thermoslide against the code a user would pick instead, in one run on this machine: the steady coupled
# C3D8T block of make_block.py N (2N x N x N hexahedra, 4 dofs per node) solved by
#   - thermoslide (its defaults; 1 and 2 ranks),
#   - a FEniCSx peer (peer_block.py: the same discretisation, one monolithic system, FGMRES with a
#     multiplicative field split, BoomerAMG on the temperature, GAMG with the rigid-body near-null space on
#     the displacement; Debian's python3-dolfinx, 1 and 2 ranks),
#   - CalculiX (ccx 2.20, C3D8 + *HEAT TRANSFER-free coupled steady step, its default direct solver, one
#     thread), up to CCX_MAX_N (default 24; above, its memory and time leave the machine's budget).
# Per run: wall time split into read + partition (peer: mesh), set-up (peer: fe set-up), assembly, solver
# set-up, linear solve, output; linear iterations; peak memory per rank. Then the ratios. The peer's total
# leaves out its Python imports (0.6 s) and JIT (cached: a warm-up run fills the cache). Figures only,
# never pass/fail (ctest -L bench). The peer's solution is compared with thermoslide's at each size
# (printed max relative difference).
# Each case runs REPEAT rounds (default 3) of one run per code, and each code's fastest run is reported: the
# machine's speed moves by 10-20 % between runs and drifts over minutes, and the rounds give every code the same
# slow and fast periods (before 2026-11-29 each code's runs came back to back). CalculiX runs once.
# thermoslide asks for transparent huge pages by default (docs/running.md, "Memory pages"); the peer runs as a
# user runs it (FEniCSx) and, unless PEER_THP=0, again with the same request (FEniCSx+THP: GLIBC_TUNABLES=
# glibc.malloc.hugetlb=1), so that the table shows what the pages give either code.
# usage: bench_peer.sh THERMOSLIDE [OUTDIR] [sizes...]      (default sizes: 16 32 50: 38 k, 283 k, 1.05 M dofs)
set -u
exe=$1 out=${2:-$PWD/bench-peer-out}
shift 2 || shift $#
sizes=${*:-16 32 50}
here=$(cd "$(dirname "$0")" && pwd)
ccx_max=${CCX_MAX_N:-24} repeat=${REPEAT:-3} peer_thp=${PEER_THP:-1}
mkdir -p "$out"
peer_ok=1
/usr/bin/python3 -c "import dolfinx" 2> /dev/null || { peer_ok=0; echo "python3-dolfinx not installed (apt-get install python3-dolfinx): peer runs skipped"; }
[ $peer_ok = 1 ] && /usr/bin/python3 "$here/peer_block.py" 2 "$out/warm" --no-output > /dev/null 2>&1

field() { echo "$1" | tr ' ' '\n' | sed -n "s/^$2=//p"; }
# peer_run TUNABLES CODE R: run R of the peer with GLIBC_TUNABLES=TUNABLES (empty: as a user runs it); the
# fastest run's log is kept as the code's log (PB: its time, PF: a run failed)
declare -A PB PF
peer_run() {
  local tun=$1 code=$2 r=$3 cmp="" plog=$out/peer$n.np$np.$2.log t
  [ "${PF[$code]:-0}" = 1 ] && return 0
  [ $np = 1 ] && [ -z "$tun" ] && cmp="--compare $out/ts$n.np1/block$n.h5"
  if GLIBC_TUNABLES=$tun mpirun -x GLIBC_TUNABLES -n $np /usr/bin/python3 "$here/peer_block.py" "$n" "$out/peer$n.np$np" $cmp > "$plog.$r" 2>&1; then
    t=$(field "$(grep "^PEER " "$plog.$r")" total_excl_import)
    if [ -z "${PB[$code]:-}" ] || [ "$(echo "$t < ${PB[$code]}" | bc)" = 1 ]; then PB[$code]=$t; cp "$plog.$r" "$plog"; fi
  else
    PF[$code]=1; cp "$plog.$r" "$plog"
  fi
  return 0
}
# peer_row CODE: the code's fastest row; sets T[CODE,n,np] and T[CODEmem,n,np]
peer_row() {
  local code=$1 plog=$out/peer$n.np$np.$1.log p
  if [ "${PF[$code]:-0}" = 0 ] && [ -n "${PB[$code]:-}" ]; then
    p=$(grep "^PEER " "$plog")
    printf "%-4s %9d %-5s %-11s %7.3g %8.3g %7.3g %8.3g %8.3g %8.3g %7.3g %5s %9.0f\n" "$n" "$dofs" "$np" "$code" "$(field "$p" total_excl_import)" \
      "$(field "$p" mesh)" "$(field "$p" fe_setup)" "$(field "$p" assembly)" "$(field "$p" solver_setup)" "$(field "$p" solve)" "$(field "$p" output)" \
      "$(field "$p" its)" "$(field "$p" rss_max_mb)"
    T[$code,$n,$np]=$(field "$p" total_excl_import) T[${code}mem,$n,$np]=$(field "$p" rss_max_mb)
    [ $np = 1 ] && [ "$code" = FEniCSx ] && grep -i "compare\|differ" "$plog" | head -2 | sed 's/^/       /'
  else
    echo "peer failed: $plog"; tail -3 "$plog"
  fi
  return 0
}
printf "\n%-4s %9s %-5s %-11s %7s %8s %7s %8s %8s %8s %7s %5s %9s\n" N dofs ranks code total read+part set-up assembly pc_setup solve output its mem_MB
declare -A T
for n in $sizes; do
  deck=$out/block$n.inp
  /usr/bin/python3 "$here/make_block.py" "$n" "$deck"
  dofs=$(( (2*n+1)*(n+1)*(n+1)*4 ))
  for np in 1 2; do
    log=$out/block$n.np$np.log best=""
    PB=() PF=()
    # REPEAT rounds of one run of each code, the fastest of each kept: this machine's speed moves over
    # minutes, and rounds give every code the same slow and fast periods
    for r in $(seq "$repeat"); do
      mpirun -n $np "$exe" "$deck" -o "$out/ts$n.np$np" > "$log.$r" 2>&1 || { echo "thermoslide failed: $log.$r"; tail -3 "$log.$r"; continue 2; }
      t=$(grep "thermoslide: wall time" "$log.$r" | awk '{print $4}')
      if [ -z "$best" ] || [ "$(echo "$t < $best" | bc)" = 1 ]; then best=$t; cp "$log.$r" "$log"; fi
      if [ $peer_ok = 1 ]; then
        peer_run "" FEniCSx "$r"
        [ "$peer_thp" = 1 ] && peer_run glibc.malloc.hugetlb=1 FEniCSx+THP "$r"
      fi
    done
    w=$(grep "thermoslide: wall time" "$log" | sed 's/[:,;]/ /g')
    tot=$(echo "$w" | awk '{print $4}')
    rp=$(echo "$w" | awk '{for(i=1;i<=NF;i++){if($i=="read")r=$(i+1);if($i=="partition")p=$(i+1)}; printf "%.3g", r+p}')
    get() { echo "$w" | awk -v k="$1" '{for(i=1;i<=NF;i++) if($i==k) {print $(i+1); exit}}'; }
    su=$(get set-up) as=$(get assembly) ps=$(echo "$w" | awk '{for(i=1;i<=NF;i++) if($i=="solver" && $(i+1)=="set-up") print $(i+2)}')
    ls=$(echo "$w" | awk '{for(i=1;i<=NF;i++) if($i=="linear" && $(i+1)=="solve") print $(i+2)}') op=$(get output)
    mem=$(echo "$w" | awk '{for(i=1;i<=NF;i++) if($i=="memory") print $(i+1)}')
    its=$(grep -o "newton [0-9]*  linear [0-9]*" "$log" | tail -1 | awk '{print $4}')
    printf "%-4s %9d %-5s %-11s %7s %8s %7s %8s %8s %8s %7s %5s %9s\n" "$n" "$dofs" "$np" thermoslide "$tot" "$rp" "$su" "$as" "$ps" "$ls" "$op" "$its" "$mem"
    T[ts,$n,$np]=$tot T[tsmem,$n,$np]=$mem
    if [ $peer_ok = 1 ]; then
      peer_row FEniCSx
      [ "$peer_thp" = 1 ] && peer_row FEniCSx+THP
    fi
  done
  if command -v ccx > /dev/null && [ "$n" -le "$ccx_max" ]; then
    /usr/bin/python3 "$here/make_block.py" "$n" "$out/ccx$n.inp" C3D8
    if (cd "$out" && OMP_NUM_THREADS=1 /usr/bin/time -f "%e %M" -o ccx$n.time ccx -i ccx$n > ccx$n.log 2>&1); then
      read -r t rss < "$out/ccx$n.time"
      printf "%-4s %9d %-5s %-11s %7s %8s %7s %8s %8s %8s %7s %5s %9d\n" "$n" "$dofs" "1 thr" CalculiX "$t" - - - - - - direct $(( rss / 1024 ))
      T[ccx,$n]=$t T[ccxmem,$n]=$(( rss / 1024 ))
    else
      echo "ccx failed: $out/ccx$n.log"
    fi
  fi
done
echo
echo "ratios (other code's time / thermoslide's time; memory: thermoslide's / other's, per rank):"
for n in $sizes; do
  for np in 1 2; do
    [ -n "${T[ts,$n,$np]:-}" ] || continue
    line="N=$n ranks=$np:"
    sep=""
    for code in FEniCSx FEniCSx+THP; do
      [ -n "${T[$code,$n,$np]:-}" ] || continue
      line="$line$sep $code/thermoslide time $(awk -v a="${T[$code,$n,$np]}" -v b="${T[ts,$n,$np]}" 'BEGIN{printf "%.2f", a/b}'), memory $(awk -v a="${T[tsmem,$n,$np]}" -v b="${T[${code}mem,$n,$np]}" 'BEGIN{printf "%.2f", a/b}')"
      sep=";"
    done
    [ $np = 1 ] && [ -n "${T[ccx,$n]:-}" ] && line="$line; CalculiX/thermoslide time $(awk -v a="${T[ccx,$n]}" -v b="${T[ts,$n,1]}" 'BEGIN{printf "%.1f", a/b}'), memory $(awk -v a="${T[tsmem,$n,1]}" -v b="${T[ccxmem,$n]}" 'BEGIN{printf "%.2f", a/b}')"
    [ $np = 2 ] && [ -n "${T[ts,$n,1]:-}" ] && line="$line; thermoslide 2-rank speed-up $(awk -v a="${T[ts,$n,1]}" -v b="${T[ts,$n,2]}" 'BEGIN{printf "%.2f", a/b}')"
    echo "  $line"
  done
done
