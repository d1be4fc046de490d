#!/usr/bin/env bash
# One shard of `koppel atlas build` per process of a batch launcher, so that any existing engine
# spreads an atlas over machines: Open MPI's mpirun (OMPI_COMM_WORLD_RANK/SIZE), MPICH or Intel
# MPI (PMI_RANK/SIZE), a Slurm job array (SLURM_ARRAY_TASK_ID/COUNT). koppel itself holds no MPI
# code: each process draws its part of the indices and writes it; `koppel atlas merge` joins them.
#
#   mpirun -n 64 tools/atlas-shard.sh koppel --count 100000000 --seed 1 -o /shared/atlas
#
# writes /shared/atlas.part-K-of-N for K = 0 .. N-1 (the -o argument is the prefix).
set -euo pipefail
if [ $# -lt 2 ]; then
  echo "usage: $0 KOPPEL --count N [--seed S] -o PREFIX  (run under mpirun or as a job array)" >&2
  exit 2
fi
koppel=$1
shift
rank=${OMPI_COMM_WORLD_RANK:-${PMI_RANK:-${SLURM_ARRAY_TASK_ID:-}}}
size=${OMPI_COMM_WORLD_SIZE:-${PMI_SIZE:-${SLURM_ARRAY_TASK_COUNT:-}}}
if [ -z "$rank" ] || [ -z "$size" ]; then
  echo "$0: no rank: run it under mpirun or as a Slurm job array" >&2
  exit 2
fi
args=()
prefix=""
while [ $# -gt 0 ]; do
  case "$1" in
    -o|--output) prefix=$2; shift 2 ;;
    *) args+=("$1"); shift ;;
  esac
done
if [ -z "$prefix" ]; then
  echo "$0: -o PREFIX is required" >&2
  exit 2
fi
exec "$koppel" atlas build "${args[@]}" --shard "$rank/$size" -o "$prefix.part-$rank-of-$size"
