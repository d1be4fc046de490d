#!/usr/bin/env bash
# CI proves the wiring of a distributed atlas build: `mpirun -n 2` runs tools/atlas-shard.sh, each
# rank builds its shard, `koppel atlas merge` joins them, and the result is byte for byte the atlas
# one `koppel atlas build` writes. Usage: atlas_mpi_test.sh KOPPEL MPIRUN SHARD_SCRIPT
set -euo pipefail
koppel=$1
mpirun=$2
shard=$3
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
# CI runs as root in a container: Open MPI wants to be told that this is intended
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
"$mpirun" -n 2 --oversubscribe "$shard" "$koppel" --count 4000 --seed 3 -o "$dir/atlas"
ls "$dir"/atlas.part-0-of-2 "$dir"/atlas.part-1-of-2 >/dev/null
"$koppel" atlas merge "$dir"/atlas.part-1-of-2 "$dir"/atlas.part-0-of-2 -o "$dir/merged.bin"
"$koppel" atlas build --count 4000 --seed 3 -o "$dir/whole.bin" --quiet
cmp "$dir/merged.bin" "$dir/whole.bin"
