#!/bin/bash
# One plantsim batch shard per Slurm array task. Submit from the checkout (or pass --chdir):
#
#   jobid=$(sbatch --parsable --chdir="$PWD" --array=0-15 --cpus-per-task=2 docs/slurm_batch.sh)
#   sbatch --chdir="$PWD" --dependency=afterok:$jobid --kill-on-invalid-dep=yes \
#          --wrap "build/plantsim merge results/shards/* --out results/merged"
#
# Size --array to the shards you want (n = array size; each task runs 1/n of the episodes) and
# --cpus-per-task to what one node offers (a request no node can meet stays PENDING forever).
# Every node must see the checkout, build/plantsim and the shared data at the same path.
# PLANTSIM_SCENARIO and PLANTSIM_SHARDS override the scenario and the output folder.
#SBATCH --job-name=plantsim
#SBATCH --array=0-15
#SBATCH --cpus-per-task=2
#SBATCH --time=01:00:00
set -euo pipefail
scenario=${PLANTSIM_SCENARIO:-data/scenarios/plants.yaml}
shards=${PLANTSIM_SHARDS:-results/shards}
if [ ! -x build/plantsim ]; then
  echo "slurm_batch.sh: no build/plantsim in $PWD: submit from the checkout or with --chdir=<checkout>" >&2
  exit 2
fi
exec build/plantsim batch "$scenario" --quiet --no-figures \
  --shard "${SLURM_ARRAY_TASK_ID}/${SLURM_ARRAY_TASK_COUNT}" \
  --threads "${SLURM_CPUS_PER_TASK:-1}" --out "$shards/${SLURM_ARRAY_TASK_ID}"
