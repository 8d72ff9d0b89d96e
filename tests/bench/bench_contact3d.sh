#!/bin/bash
# Contact at scale (issue 7): the two-block C3D8T deck of make_contact_block.py N ((N+1)^2 secondary nodes
# against (N+1)^2 main faces, non-matching meshes, one steady coupled increment) solved by
#   - thermoslide on 1 and 2 ranks (-tsl_partition axis_x, so that both ranks own secondary nodes and each
#     holds its own part of the main surface), with the node-to-surface pair ("thermoslide") and with the
#     surface-to-surface pair ("ts s2s", the kind of pair CalculiX runs below; S2S=0 leaves it out),
#   - CalculiX 2.20 (ccx, face-to-face contact, its default direct solver, one thread) up to CCX_MAX_N
#     (default 32), stopped after CCX_TIMEOUT seconds if given (its time is then a lower bound, printed ">T", and
#     so are the time ratios; the memory is its peak until then). The issue's size is N = 224 (50 625 contact
#     nodes, 1.02 M unknowns): CCX_MAX_N=224 CCX_TIMEOUT=5400 bench_contact3d.sh EXE OUT 224 (CalculiX: 17 GB).
# Per run: total wall time, Newton iterations, the contact phase and the search inside it (pairing and the
# held-region check, without the matrix pattern rebuild) per Newton iteration, the search's share of the
# run (= its share of an iteration), the main faces held per rank, peak memory per rank, the heat crossing
# the interface (thermoslide: history column interface_heat; CalculiX: the heat entering at the hot face,
# *NODE PRINT RFL, which is the same in the steady state); then the ratios to CalculiX. Figures only, never
# pass/fail (ctest -L bench).
# usage: bench_contact3d.sh THERMOSLIDE [OUTDIR] [sizes...]   (default sizes: 16 32 64)
set -u
exe=$1 out=${2:-$PWD/bench-contact3d-out}
shift 2 || shift $#
sizes=${*:-16 32 64}
here=$(cd "$(dirname "$0")" && pwd)
ccx_max=${CCX_MAX_N:-32}
ccx_timeout=${CCX_TIMEOUT:-0}
mkdir -p "$out"
ccx_ok=1
command -v ccx > /dev/null || { ccx_ok=0; echo "ccx not installed (apt-get install calculix-ccx): CalculiX runs skipped"; }

printf "\n%-4s %8s %9s %-5s %-11s %8s %6s %12s %12s %8s %-13s %9s %9s\n" N contacts dofs ranks code total newton contact/it search/it search% held_faces mem_MB/rank heat
declare -A T
for n in $sizes; do
  nc=$(( (n+1)*(n+1) ))
  # base (n+2) x 3 x (n+2) nodes, thin block (n+1) x 2 x (n+1) nodes, 4 unknowns each
  dofs=$(( ((n+2)*3*(n+2) + (n+1)*2*(n+1)) * 4 ))
  for pair in n2s s2s; do
    [ "$pair" = s2s ] && [ "${S2S:-1}" = 0 ] && continue
    name=block$n tag=ts code=thermoslide flavour=thermoslide
    [ "$pair" = s2s ] && name=block${n}s2s tag=s2s code="ts s2s" flavour=s2s
    deck=$out/$name.inp
    /usr/bin/python3 "$here/make_contact_block.py" "$n" "$deck" "$flavour"
    for np in 1 2; do
      log=$out/$name.np$np.log
      mpirun -n $np "$exe" "$deck" -o "$out/$tag$n.np$np" -tsl_partition axis_x > "$log" 2>&1 || { echo "thermoslide failed: $log"; tail -3 "$log"; continue; }
      w=$(grep "thermoslide: wall time" "$log" | sed 's/[:,;()]/ /g')
      tot=$(echo "$w" | awk '{print $4}')
      con=$(echo "$w" | awk '{for(i=1;i<=NF;i++) if($i=="contact" && $(i+1)!="search") {print $(i+1); exit}}')
      sea=$(echo "$w" | awk '{for(i=1;i<=NF;i++) if($i=="contact" && $(i+1)=="search") print $(i+2)}')
      mem=$(echo "$w" | awk '{for(i=1;i<=NF;i++) if($i=="memory") print $(i+1)}')
      its=$(grep -o "newton [0-9]*" "$log" | awk '{s+=$2} END {print s}')
      held=$(grep -o "main faces held by rank [0-9.]*: [0-9 ]* of" "$log" | sed 's/.*: //; s/ of//; s/ /+/g')
      heat=$(/usr/bin/python3 -c 'import csv, sys; print("%.6g" % abs(float(list(csv.DictReader(open(sys.argv[1])))[-1]["interface_heat"])))' \
        "$out/$tag$n.np$np/$name.csv" 2> /dev/null || echo -)
      printf "%-4s %8d %9d %-5s %-11s %8s %6s %12.3g %12.3g %7.2g%% %-13s %9s %9s\n" "$n" "$nc" "$dofs" "$np" "$code" "$tot" "$its" \
        "$(echo "$con / $its" | bc -l)" "$(echo "${sea:-0} / $its" | bc -l)" "$(echo "100 * ${sea:-0} / $tot" | bc -l)" "$held" "$mem" "$heat"
      T[$tag,$n,$np]=$tot T[${tag}mem,$n,$np]=$mem
    done
  done
  if [ $ccx_ok = 1 ] && [ "$n" -le "$ccx_max" ]; then
    cdir=$out/ccx$n
    mkdir -p "$cdir"
    /usr/bin/python3 "$here/make_contact_block.py" "$n" "$cdir/block.inp" calculix
    tmo=()
    [ "$ccx_timeout" -gt 0 ] && tmo=(timeout -s TERM "$ccx_timeout")
    (cd "$cdir" && OMP_NUM_THREADS=1 /usr/bin/time -f "%e %M" -o time.txt "${tmo[@]}" ccx -i block > ccx.log 2>&1)
    lb=""
    grep -q "Job finished" "$cdir/ccx.log" || { [ ${#tmo[@]} -gt 0 ] && grep -q "^[0-9.]* [0-9]*$" "$cdir/time.txt" && lb=">"; }
    if grep -q "Job finished" "$cdir/ccx.log" || [ -n "$lb" ]; then
      read -r ct cm < <(tail -1 "$cdir/time.txt")
      cm=$(echo "$cm / 1024" | bc)
      cits=$(grep -c "iteration [0-9]" "$cdir/ccx.log")
      cheat=$(grep -A2 "total heat generation for set HOT" "$cdir/block.dat" | awk 'NF == 1 {printf "%.6g", ($1 < 0 ? -$1 : $1)}')
      printf "%-4s %8d %9d %-5s %-11s %8s %6s %12s %12s %8s %-13s %9s %9s\n" "$n" "$nc" "$dofs" 1 CalculiX "$lb$ct" "$cits" - - - - "$cm" "${cheat:--}"
      [ -n "$lb" ] && echo "     CalculiX stopped after CCX_TIMEOUT=$ccx_timeout s, unfinished: $(grep -E "attempt|increment size" "$cdir/ccx.log" | tail -2 | tr -s ' ' | tr '\n' ';')"
      T[ccx,$n]=$ct T[ccxmem,$n]=$cm T[ccxlb,$n]=$lb
    else
      echo "ccx failed: $cdir/ccx.log"; tail -3 "$cdir/ccx.log"
    fi
  fi
done

echo
echo "ratios (CalculiX / thermoslide): time on 1 rank, memory on 1 rank, node-to-surface (and surface-to-surface); memory per rank 2 ranks / 1 rank"
for n in $sizes; do
  r="N=$n:"
  for tag in ts s2s; do
    [ -n "${T[$tag,$n,1]:-}" ] || continue
    label=node-to-surface
    [ $tag = s2s ] && label=surface-to-surface
    r="$r $label"
    if [ -n "${T[ccx,$n]:-}" ]; then
      r="$r time ${T[ccxlb,$n]}x$(echo "${T[ccx,$n]} / ${T[$tag,$n,1]}" | bc -l | xargs printf %.2g), memory ${T[ccxlb,$n]}x$(echo "${T[ccxmem,$n]} / ${T[${tag}mem,$n,1]}" | bc -l | xargs printf %.2g)"
    fi
    if [ -n "${T[${tag}mem,$n,2]:-}" ]; then
      r="$r, memory per rank 2/1 ranks $(echo "${T[${tag}mem,$n,2]} / ${T[${tag}mem,$n,1]}" | bc -l | xargs printf %.2g)"
    fi
    r="$r;"
  done
  echo "$r"
done
