#!/bin/bash
# Distributed HLOD bake on Slurm in one command (README "Baking on a farm"): plans here, then
# submits the shard array and the dependent final job.
#
#   scripts/slurm/submit.sh N CACHE PKG SCENE... [import, cluster and bake flags]
#
# 1. `hlod plan SCENE... --shards N --cache CACHE [flags]` on this machine (imports once,
#    clusters, writes the plan into CACHE);
# 2. `sbatch --array=0-(N-1) hlod-shard.sbatch CACHE N`;
# 3. `sbatch --dependency=afterok:ARRAY --kill-on-invalid-dep=yes hlod-final.sbatch SCENE...
#    -o PKG --cache CACHE [flags]`.
# CACHE, PKG and the scene files must be on storage every node sees, under the same paths (or
# give paths valid on the nodes). Prints "ARRAY_JOB_ID FINAL_JOB_ID" on stdout. Environment:
# HLOD (the hlod binary; default hlod on PATH), HLOD_SLURM_LOGS (folder of the job logs; default
# the current folder), HLOD_FINAL_FLAGS (flags for the final build only, e.g. --no-dlod: its lean
# step, which reads the plan and the shards' tiles instead of the scene), and any SBATCH_*
# variable of sbatch (partition, account, time limit...).
set -euo pipefail
if [[ $# -lt 4 ]]; then
    echo "usage: $0 N CACHE PKG SCENE... [flags]" >&2
    exit 2
fi
n="$1" cache="$2" pkg="$3"
shift 3
here="$(cd "$(dirname "$0")" && pwd)"
hlod="${HLOD:-hlod}"
logs="${HLOD_SLURM_LOGS:-$PWD}"
mkdir -p "$logs"
"$hlod" plan "$@" --shards "$n" --cache "$cache" >&2
array=$(sbatch --parsable --array="0-$((n - 1))" --output="$logs/hlod-shard-%A_%a.out" \
    "$here/hlod-shard.sbatch" "$cache" "$n")
array="${array%%;*}"
read -r -a final_flags <<< "${HLOD_FINAL_FLAGS:-}"
final=$(sbatch --parsable --dependency="afterok:$array" --kill-on-invalid-dep=yes \
    --output="$logs/hlod-final-%j.out" "$here/hlod-final.sbatch" "$@" "${final_flags[@]}" \
    -o "$pkg" --cache "$cache")
final="${final%%;*}"
echo "$array $final"
