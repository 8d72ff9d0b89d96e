#!/bin/bash
# CalculiX's own *STATIC test decks (package calculix-ccx-test) run here as they stand and compared with the
# displacements CalculiX printed for them (their .dat.ref, 7 digits; tests/tools/compare_ccx_dat.py):
#   beam8p (a C3D8 cantilever under shear), beam8t (a bimetal beam heated by *TEMPERATURE), beam20p (C3D20, a
#   cantilever under shear), beamt (C3D20R heated by *TEMPERATURE against *EXPANSION, ZERO=), planestrain and
#   planestrain2 (CPE4, CPE8), contactenergy (two cubes in contact): 1e-6 of the largest displacement (the print);
#   contact3, contact6, cubespring, hueeber1, hueeber2, hueeber4 (C3D8 blocks in contact; hueeber1 pressed by a
#   nonzero model-data *BOUNDARY), ring1 and ring2 (CAX8 rings
#   pressed into contact by thermal expansion and by an interference): 1e-2 (measured 1.6e-4 - 4.3e-3: the contact
#   formulations differ, penalty stiffness and integration of the two codes); solidshell1 (an S8R cantilever hinged
#   to a C3D20 block, the shell expanded as CalculiX expands it): 1e-6 (measured 1.4e-10).
# With LIST=heat, CalculiX's *HEAT TRANSFER decks that use only what exists here, against the temperatures CalculiX
# printed (the same comparison on NT, relative to the largest printed T - T_min): beamhtbo (a C3D20R beam, steady, a
# *DFLUX and a *FILM), beamhtbf (the beam under a body flux, its temperature dof written 0), beamth (the beam
# transient, 3 prints), oneel20cf, oneel20df, oneel20fi, oneel20rs (one C3D20R element under concentrated fluxes on
# dof 0, a surface flux, a film, a steady restart), oneel8ra (one C3D8 radiating): 1e-6 (measured 4e-16 to 7.5e-8:
# the same finite elements, CalculiX's C3D20R being fully integrated in heat transfer as DC3D20 is).
# With LIST=plastic, CalculiX's *PLASTIC test decks against CalculiX itself (package calculix-ccx) at small strain: the
# decks ask NLGEOM, which CalculiX's plasticity takes as finite strain; thermoslide has finite strain for elastic
# elements but keeps plastic ones at small strain (issues 47, 48; it says so at the *STEP line), so both codes run each
# deck with NLGEOM taken off and the displacements of
# the last print are compared at 1e-6 of the largest (CalculiX prints 7 digits; measured 6.8e-9 to 3.3e-7):
#   beampiso  a C3D20R cantilever pulled past yield and back (isotropic hardening, two steps)
#   beampt    the same beam heated by *TEMPERATURE against its *EXPANSION while yielding (isotropic)
#   beampkin  linear kinematic hardening, the first step (CalculiX's small-strain run diverges in the reverse step, DIRECT)
#   beampd    linear kinematic hardening, the first step (its second is automatic: the two codes take other
#             increments there, and kinematic hardening depends on the path: 2e-3)
# With NLGEOM kept, CalculiX's finite-strain answer lies 12 % (beampiso), 11 % (beampkin), 0.1 % (beampd) and 0.4 %
# (beampt) away: the 2.5 % strain of the pulled beam shrinks its section.
# With LIST=nlgeom, CalculiX's geometrically nonlinear beams (C3D20R cantilevers, St Venant-Kirchhoff in both codes:
# CalculiX's reading of a linear elastic material under NLGEOM, docs/elements.md "Finite strain"), against CalculiX itself
# run with its Newton tolerances tightened (*CONTROLS, PARAMETERS=FIELD 1e-9, 1e-9 after *STATIC: its default criterion
# stops with 3e-6 of the displacement left, measured on beamnlp and beamnlmpc), and against the displacements it printed:
#   beamnld   the tip pulled axially by 0.1 (NLGEOM, DIRECT): 1e-6 (measured 2e-8)
#   beamnlmpc the beam under a tip shear through *EQUATION-tied nodes: 1e-6 (4.4e-7); printed 1e-5 (2.6e-6)
#   beamnlp   the beam bent by a tip shear to a deflection of 0.44: 1e-6 (1.1e-7); printed 1e-5 (3.9e-6)
#   beamnlt   the beam heated by 100 (alpha = 1.2e-5): against CalculiX 2.20's run 1e-5 (measured 7.5e-6); its printed
#             displacements come from a CalculiX that took the Green-Lagrange thermal strain as E_th = eps, where here
#             E_th = eps + eps^2 / 2 (a free body stress-free at any alpha dT, J = (1 + alpha dT)^3), so the free thermal
#             displacements differ by eps / 2 = 6e-4 of themselves: 7e-4 (measured 6.1e-4; 4.6e-7 with E_th = eps, tried)
# usage: ccx_static_decks.sh THERMOSLIDE MPIEXEC NP OUTDIR TOOLSDIR [static|heat|plastic|nlgeom]
set -u
exe=$1 mpiexec=$2 np=$3 out=$4 tools=$5 list=${6:-static}
src=/usr/share/doc/calculix-ccx-test/examples/test
# a file of the package, gzipped or not
get() { if [ -f "$src/$1" ]; then cat "$src/$1"; else zcat "$src/$1.gz"; fi; }
[ -f "$src/beam8p.inp" ] || [ -f "$src/beam8p.inp.gz" ] || { echo "FAIL: CalculiX's test decks are not in $src (jobs/scripts/install-deps.sh installs calculix-ccx-test)"; exit 1; }
rm -rf "$out" && mkdir -p "$out" || exit 1
fail=0
# CalculiX on DIR/B.inp, its printed results the reference $out/B.dat.ref (non-zero, and fail set, if it did not run)
ccx_reference() {
  if ! (cd "$1" && OMP_NUM_THREADS=1 timeout 300 ccx -i "$2" > "$2.ccx.log" 2>&1) || [ ! -s "$1/$2.dat" ]; then
    tail -5 "$1/$2.ccx.log"
    echo "$2: FAIL (CalculiX's run)"
    fail=1
    return 1
  fi
  mv "$1/$2.dat" "$out/$2.dat.ref"
}
specs="beam8p:1e-6 beam8t:1e-6 beam20p:1e-6 beamt:1e-6 planestrain:1e-6 planestrain2:1e-6 contactenergy:1e-6 contact3:1e-2 contact6:1e-2
  cubespring:1e-2 hueeber1:1e-2 hueeber2:1e-2 hueeber4:1e-2 ring1:1e-2 ring2:1e-2 solidshell1:1e-6"
[ "$list" = heat ] && specs="beamhtbo:1e-6:NT beamhtbf:1e-6:NT beamth:1e-6:NT oneel20cf:1e-6:NT oneel20df:1e-6:NT oneel20fi:1e-6:NT oneel20rs:1e-6:NT
  oneel8ra:1e-6:NT"
[ "$list" = plastic ] && specs="beampiso:1e-6 beampt:1e-6 beampkin:1e-6 beampd:1e-6"
[ "$list" = nlgeom ] && specs="beamnld:1e-6:U:1e-6 beamnlmpc:1e-6:U:1e-5 beamnlp:1e-6:U:1e-5 beamnlt:1e-5:U:7e-4"
{ [ "$list" != plastic ] && [ "$list" != nlgeom ]; } || command -v ccx > /dev/null ||
  { echo "FAIL: CalculiX (ccx) is not installed (jobs/scripts/install-deps.sh installs calculix-ccx)"; exit 1; }
for spec in $specs; do
  b=${spec%%:*} rest=${spec#*:}
  tol=${rest%%:*} field=U printed=
  [ "$rest" != "$tol" ] && field=${rest#*:}
  [ "$field" != "${field%%:*}" ] && printed=${field#*:} field=${field%%:*}
  # on 2 ranks hueeber2 (hard contact, 15 s) is left to the 1-rank run; hueeber4 is the same two cubes, soft;
  # hueeber1 (its pressing displacement a nonzero model-data *BOUNDARY, CalculiX's reading) on 1 rank too
  [ "$np" != 1 ] && { [ "$b" = hueeber2 ] || [ "$b" = hueeber1 ]; } && continue
  if [ "$list" = plastic ]; then
    # NLGEOM off, beampkin and beampd up to their first *END STEP; CalculiX's own run is the reference
    first=all
    { [ "$b" = beampkin ] || [ "$b" = beampd ]; } && first=first
    get "$b.inp" | awk -v first="$first" '{ l = $0; if (toupper(l) ~ /^\*STEP/) gsub(/, *[Nn][Ll][Gg][Ee][Oo][Mm]/, "", l); print l;
      if (first == "first" && toupper(l) ~ /^\*END STEP/) exit }' > "$out/$b.inp" || { echo "FAIL: $b not in the package"; fail=1; continue; }
    ccx_reference "$out" "$b" || continue
  elif [ "$list" = nlgeom ]; then
    # CalculiX's own run with its Newton tolerances tightened is the reference; its printed answer is compared after
    # (thermoslide runs the deck as it stands)
    mkdir -p "$out/ccx" && get "$b.inp" > "$out/$b.inp" && get "$b.dat.ref" > "$out/$b.dat.printed" &&
      awk '{ print } toupper($0) ~ /^\*STATIC/ && !done { print "*CONTROLS, PARAMETERS=FIELD"; print "1e-9, 1e-9"; done = 1 }' "$out/$b.inp" \
      > "$out/ccx/$b.inp" || { echo "FAIL: $b not in the package"; fail=1; continue; }
    ccx_reference "$out/ccx" "$b" || continue
  else
    get "$b.inp" > "$out/$b.inp" && get "$b.dat.ref" > "$out/$b.dat.ref" || { echo "FAIL: $b not in the package"; fail=1; continue; }
  fi
  if ! (cd "$out" && timeout 300 $mpiexec -n "$np" "$exe" "$b.inp" -o "run_$b" > "$b.log" 2>&1); then
    tail -5 "$out/$b.log"
    echo "$b: FAIL (the run)"
    fail=1
    continue
  fi
  printf "%s: " "$b"
  /usr/bin/python3 "$tools/compare_ccx_dat.py" "$out/run_$b/$b.h5" "$out/$b.dat.ref" "$tol" "$field" || { echo "$b: FAIL"; fail=1; }
  if [ -n "$printed" ]; then
    printf "%s (against CalculiX's printed displacements): " "$b"
    /usr/bin/python3 "$tools/compare_ccx_dat.py" "$out/run_$b/$b.h5" "$out/$b.dat.printed" "$printed" "$field" || { echo "$b: FAIL"; fail=1; }
  fi
done
[ $fail = 0 ] && echo PASS
exit $fail
