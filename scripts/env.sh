# Sourced by the scripts: lets Open MPI's mpirun run as root (CI does) and
# start more ranks than cores; one OpenBLAS thread per MPI rank (the ranks
# already fill the cores; threads on top would oversubscribe them).
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export OMPI_MCA_rmaps_base_oversubscribe=1
export OPENBLAS_NUM_THREADS=1
# Open MPI's start-up, 0.3 s of every run, cut: a run on one rank (an MPI
# singleton) starts no supporting daemon, which tubeform never needs (it spawns
# no processes); and on a machine without InfiniBand or Omni-Path hardware the
# point-to-point layer is named as the one Open MPI falls back to (ob1) instead
# of probed for (docs/performance.md, "Open MPI's start-up"). A pml of your own
# is kept.
export OMPI_MCA_ess_singleton_isolated=1
[ -e /sys/class/infiniband ] || [ -n "${OMPI_MCA_pml:-}" ] || export OMPI_MCA_pml=ob1
