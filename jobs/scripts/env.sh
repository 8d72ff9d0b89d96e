# Sourced by the scripts: lets Open MPI run as root (containers, CI) and without cross-memory attach.
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export OMPI_MCA_btl_vader_single_copy_mechanism=none OMPI_MCA_rmaps_base_oversubscribe=1
# Open MPI's ob1 messaging layer (shared memory between the ranks of one machine) unless the caller chose one:
# the default tries UCX first, which cannot open here and costs 0.2 s of every process (0.44 -> 0.23 s for a small job),
# a fifth of the test suite's time (651-712 -> 514 s). On a cluster's fast network leave OMPI_MCA_pml to the site (docs/running.md).
export OMPI_MCA_pml=${OMPI_MCA_pml:-ob1}
# When a rank exits non-zero, mpirun stops the others with SIGTERM and, a second later, SIGKILL; it waited those
# 2 s even when every rank had already exited (a deck error cost 2.25 s instead of 0.25). thermoslide's ranks
# decide a failure together and all pass a barrier before exiting, so nothing is cut short (docs/running.md).
export OMPI_MCA_odls_base_sigkill_timeout=${OMPI_MCA_odls_base_sigkill_timeout:-0}
TSL_ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
TSL_BUILD=${TSL_BUILD:-$TSL_ROOT/build}
