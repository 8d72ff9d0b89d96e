# Sourced by the scripts: lets Open MPI run as root (containers, CI) and without cross-memory attach.
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export OMPI_MCA_btl_vader_single_copy_mechanism=none OMPI_MCA_rmaps_base_oversubscribe=1
TSL_ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
TSL_BUILD=${TSL_BUILD:-$TSL_ROOT/build}
