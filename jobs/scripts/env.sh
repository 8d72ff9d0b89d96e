# Sourced by the scripts: lets Open MPI run as root (containers, CI) and without cross-memory attach.
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export OMPI_MCA_btl_vader_single_copy_mechanism=none OMPI_MCA_rmaps_base_oversubscribe=1
# Open MPI's ob1 messaging layer (shared memory between the ranks of one machine) unless the caller chose one:
# the default tries UCX first, which cannot open here and costs 0.2 s of every process (0.44 -> 0.23 s for a small job),
# a fifth of the test suite's time (651-712 -> 514 s). On a cluster's fast network leave OMPI_MCA_pml to the site (docs/running.md).
export OMPI_MCA_pml=${OMPI_MCA_pml:-ob1}
TSL_ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
TSL_BUILD=${TSL_BUILD:-$TSL_ROOT/build}
