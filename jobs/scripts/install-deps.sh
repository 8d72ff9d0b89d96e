#!/bin/bash
# Installs thermoslide's build and run dependencies from Debian's packages (idempotent).
# Needs root (or sudo). Packages: PETSc 3.18 (built with hypre, MUMPS, HDF5), METIS, parallel HDF5,
# Open MPI, CMake, Ninja, python3-h5py/numpy for the verification checks, valgrind for the memory check,
# CalculiX's test decks (calculix-ccx-test: decks we did not write, run as they stand by the suite), CalculiX itself
# (calculix-ccx: the suite runs its plasticity decks through it, small strain, for the reference; the benchmarks
# compare with it) and ParaView
# (paraview: its pvpython reads every element family's .xmf in the readers' test, output_readers_paraview) and Gmsh
# (gmsh: meshes the geometry of tests/gmsh for jobs/tools/gmsh2inp.py).
set -euo pipefail
PKGS="petsc-dev libmetis-dev libhdf5-openmpi-dev openmpi-bin cmake ninja-build pkg-config python3-h5py python3-numpy python3-meshio valgrind calculix-ccx-test calculix-ccx paraview gmsh"
missing=""
for p in $PKGS; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing="$missing $p"
done
if [ -n "$missing" ]; then
  SUDO=""
  [ "$(id -u)" -eq 0 ] || SUDO="sudo"
  echo "installing:$missing"
  $SUDO apt-get update -q
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -q --no-install-recommends $missing
fi
