#!/bin/bash
# One shard of a vobench run per task of a Slurm job array (README "Sweeps on a cluster").
#
#   sbatch --array=1-8 scripts/slurm-array.sh run datasets/suites/quick.json -o out/quick-{shard}.jsonl
#   sbatch --array=0-15 scripts/slurm-array.sh reproduce cook-table4 --full
#   vobench merge out/quick-*.jsonl -o out/quick.jsonl && vobench report out/quick.jsonl -o out/report
#
# Task K of the array runs `vobench ARGS --shard I/N` with N = SLURM_ARRAY_TASK_COUNT and
# I = K - SLURM_ARRAY_TASK_MIN + 1 (so --array=0-7 and --array=1-8 both work); every {shard}
# in ARGS becomes "IofN", so each task writes its own file (reproduce without -o already
# writes reports/out/NAME[-SCALE]-shardIofN). Every task computes the same partition: give
# them all the same --costs FILE, or none. For honest timings ask for whole nodes
# (#SBATCH --exclusive) and one task per node; a correctness sweep can share nodes.
# VOBENCH: the program (default: build/harness/cli/vobench beside this script's tree).
#SBATCH --job-name=vobench
#SBATCH --ntasks=1
#SBATCH --cpus-per-task=1
set -euo pipefail

if [ -z "${SLURM_ARRAY_TASK_ID:-}" ] || [ -z "${SLURM_ARRAY_TASK_COUNT:-}" ]; then
  echo "slurm-array.sh: not in a Slurm job array (SLURM_ARRAY_TASK_ID and SLURM_ARRAY_TASK_COUNT unset); submit with sbatch --array=1-N" >&2
  exit 2
fi
if [ $# -lt 1 ]; then
  echo "slurm-array.sh: usage: sbatch --array=1-N slurm-array.sh run|reproduce ARGS..." >&2
  exit 2
fi
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
# sbatch copies the script to a spool folder: prefer the folder it was submitted from.
[ -x "$here/build/harness/cli/vobench" ] || here="${SLURM_SUBMIT_DIR:-$here}"
vobench="${VOBENCH:-$here/build/harness/cli/vobench}"
count="$SLURM_ARRAY_TASK_COUNT"
index=$((SLURM_ARRAY_TASK_ID - ${SLURM_ARRAY_TASK_MIN:-1} + 1))
if [ "$index" -lt 1 ] || [ "$index" -gt "$count" ]; then
  echo "slurm-array.sh: task $SLURM_ARRAY_TASK_ID is not within the array's $count tasks (min ${SLURM_ARRAY_TASK_MIN:-1}; an array with a step is not supported)" >&2
  exit 2
fi
args=()
for a in "$@"; do args+=("${a//\{shard\}/${index}of${count}}"); done
echo "slurm-array.sh: task $SLURM_ARRAY_TASK_ID on $(hostname): $vobench ${args[*]} --shard $index/$count" >&2
exec "$vobench" "${args[@]}" --shard "$index/$count"
