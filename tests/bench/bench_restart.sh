#!/bin/bash
# Restart points at scale (issue 49): the two-block C3D8T contact deck of make_contact_block.py N (the contact
# benchmark's, tests/bench/bench_contact3d.sh: (N+1)^2 secondary nodes, one steady coupled increment) with
# *RESTART, WRITE, FREQUENCY=1 added to its step, run on 1 and 2 ranks (-tsl_partition axis_x) with the
# node-to-surface pair ("n2s") and the surface-to-surface pair ("s2s"; PAIRS="n2s" leaves it out). The step's one
# increment writes one point, <job>.restart.1.1.h5 (docs/running.md "Restart"). The issue's size is N = 224
# (1.02 M unknowns): bench_restart.sh EXE OUT 224.
# Per run: the total wall time; the increment's wall time, from the log's step header line to its increment line
# as printed (the lines are stamped as they arrive: the Newton solve with the step's set-up in it, the Jacobian
# pattern and the force records, without the frame's output and the point); its Newton iterations; the point's
# write time as the log's line gives it ("restart point ... X.XX s": the output's sync before it, the packing, the
# checksums, the HDF5 write and the rename; two decimals); the point file's size, its bytes per unknown and the
# ratio of write time to increment time; in MB (2^20 bytes; h5py, "-" without it) the point's vectors (X, Xprev,
# start_*, extra_*: 8 bytes per unknown each), its state in natural terms (natnode, blobs: contact nodes,
# surface-to-surface points; xelem) and what the file allocates beyond the data (the unused end of a dataset's last
# chunk); the deck copy the job keeps beside its points (<job>.restart.inp, once per job); peak memory per rank.
# Figures only, never pass/fail: the exit status is non-zero only when a thermoslide run fails (ctest -L bench).
# usage: bench_restart.sh THERMOSLIDE [OUTDIR] [sizes...]   (default sizes: 32 64; PAIRS, default "n2s s2s";
#        RANKS, default "1 2")
set -u
exe=$1 out=${2:-$PWD/bench-restart-out}
shift 2 || shift $#
sizes=${*:-32 64}
pairs=${PAIRS:-n2s s2s}
ranks=${RANKS:-1 2}
here=$(cd "$(dirname "$0")" && pwd)
mkdir -p "$out"
out=$(cd "$out" && pwd)
fail=0
h5=1
/usr/bin/python3 -c "import h5py" 2> /dev/null || { h5=0; echo "python3-h5py not installed: the point's vectors / state split is left out"; }

# seconds since the epoch in front of each line as it arrives (bash's EPOCHREALTIME: no process per line)
stamp() { while IFS= read -r l; do printf '%s %s\n' "$EPOCHREALTIME" "$l"; done; }

printf "\n%-4s %-4s %9s %-5s %8s %11s %6s %9s %9s %8s %10s %9s %8s %7s %9s %11s\n" N pair dofs ranks total_s increment_s newton write_s point_MB B/unknown write/inc vectors_MB state_MB pad_MB deck_MB mem_MB/rank
for n in $sizes; do
  # base (n+2) x 3 x (n+2) nodes, thin block (n+1) x 2 x (n+1) nodes, 4 unknowns each
  dofs=$(( ((n+2)*3*(n+2) + (n+1)*2*(n+1)) * 4 ))
  for pair in $pairs; do
    case $pair in
      n2s) name=rblock$n flavour=thermoslide ;;
      s2s) name=rblock${n}s2s flavour=s2s ;;
      *) echo "unknown pair $pair (PAIRS: n2s, s2s)"; continue ;;
    esac
    deck=$out/$name.inp
    /usr/bin/python3 "$here/make_contact_block.py" "$n" "$deck" "$flavour" || { echo "make_contact_block.py $n failed"; fail=1; continue; }
    # a restart point every increment: the step's one increment writes one
    sed -i 's/^\*END STEP$/*RESTART, WRITE, FREQUENCY=1\n*END STEP/' "$deck"
    grep -q "^\*RESTART, WRITE, FREQUENCY=1$" "$deck" || { echo "no *END STEP in $deck"; fail=1; continue; }
    for np in $ranks; do
      log=$out/$name.np$np.log run=$out/$pair$n.np$np
      rm -rf "$run" # a fresh job: no points of an earlier run beside this one's
      mpirun -n "$np" "$exe" "$deck" -o "$run" -tsl_partition axis_x 2>&1 | stamp > "$log"
      rc=${PIPESTATUS[0]}
      if [ "$rc" != 0 ] || ! grep -q "thermoslide: completed" "$log"; then
        echo "thermoslide failed ($rc): $log"; tail -3 "$log"; fail=1; continue
      fi
      t_step=$(awk '$2 == "step" && $4 ~ /^\(/ {print $1; exit}' "$log")
      incl=$(grep -m1 " step [0-9]* increment [0-9]*: .*newton" "$log")
      t_inc=$(echo "$incl" | awk '{print $1}')
      its=$(echo "$incl" | awk '{for(i=1;i<=NF;i++) if($i=="newton") print $(i+1)}')
      rl=$(grep -m1 "  restart point " "$log")
      point=$(echo "$rl" | awk '{print $4}')
      wt=$(echo "$rl" | awk '{print $(NF-1)}')
      w=$(grep "thermoslide: wall time" "$log" | sed 's/[:,;()]/ /g')
      tot=$(echo "$w" | awk '{print $5}')
      mem=$(echo "$w" | awk '{for(i=1;i<=NF;i++) if($i=="memory") print $(i+1)}')
      [ -n "$point" ] && [ -f "$point" ] || { echo "no restart point in $log"; fail=1; continue; }
      inc=$(echo "$t_inc - $t_step" | bc -l)
      bytes=$(stat -c %s "$point")
      vec=- st=- pad=-
      if [ $h5 = 1 ]; then
        # data bytes of the vectors and of the state (natnode, blobs, xelem); pad: what the file allocates beyond the
        # data (the unused end of a dataset's last chunk)
        read -r vec st pad < <(/usr/bin/python3 -c '
import h5py, sys
f = h5py.File(sys.argv[1], "r")
data = lambda k: f[k].size * f[k].dtype.itemsize if k in f else 0
v = sum(data(k) for k in f if k in ("X", "Xprev") or k.startswith("start_") or k.startswith("extra_"))
pad = sum(f[k].id.get_storage_size() - data(k) for k in f)
print("%.1f %.1f %.1f" % (v / 1048576.0, sum(map(data, ("natnode", "blobs", "xelem"))) / 1048576.0, pad / 1048576.0))' "$point")
      fi
      dk=$(stat -c %s "$run/$name.restart.inp" 2> /dev/null || echo 0)
      printf "%-4s %-4s %9d %-5s %8s %11.3g %6s %9s %9.1f %9.1f %10.2g %9s %8s %7s %9.1f %11s\n" "$n" "$pair" "$dofs" "$np" "$tot" "$inc" "$its" "$wt" \
        "$(echo "$bytes / 1048576" | bc -l)" "$(echo "$bytes / $dofs" | bc -l)" "$(echo "$wt / $inc" | bc -l)" "$vec" "$st" "$pad" \
        "$(echo "$dk / 1048576" | bc -l)" "$mem"
    done
  done
done
exit $fail
