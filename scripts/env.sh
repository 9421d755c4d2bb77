# Sourced by the scripts: lets Open MPI's mpirun run as root (CI does) and
# start more ranks than cores; one OpenBLAS thread per MPI rank (the ranks
# already fill the cores; threads on top would oversubscribe them).
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export OMPI_MCA_rmaps_base_oversubscribe=1
export OPENBLAS_NUM_THREADS=1
