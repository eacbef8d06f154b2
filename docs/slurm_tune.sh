#!/bin/bash
# One plantsim tune shard per Slurm array task: task 0 runs NLopt's search, the others share
# random search's points (docs/tune.md). Submit from the checkout (or pass --chdir), then the
# merge, which takes the shards' evaluations, validates and writes the report:
#
#   jobid=$(sbatch --parsable --chdir="$PWD" --array=0-4 --cpus-per-task=2 docs/slurm_tune.sh)
#   sbatch --chdir="$PWD" --dependency=afterok:$jobid --kill-on-invalid-dep=yes --cpus-per-task=2 \
#          --wrap "build/plantsim tune data/scenarios/tune_speed.yaml --merge results/tune_shards/* --out results/tune_speed"
#
# NLopt's search is one chain of evaluations, each asking after the last: task 0 takes as long
# as the budget's evaluations on one task's cores, so more than budget/2 + 1 tasks gain nothing.
# Every node must see the checkout, build/plantsim and the shared data at the same path.
# PLANTSIM_SCENARIO and PLANTSIM_SHARDS override the scenario and the shards' folder.
#SBATCH --job-name=plantsim-tune
#SBATCH --array=0-4
#SBATCH --cpus-per-task=2
#SBATCH --time=02:00:00
set -euo pipefail
scenario=${PLANTSIM_SCENARIO:-data/scenarios/tune_speed.yaml}
shards=${PLANTSIM_SHARDS:-results/tune_shards}
if [ ! -x build/plantsim ]; then
  echo "slurm_tune.sh: no build/plantsim in $PWD: submit from the checkout or with --chdir=<checkout>" >&2
  exit 2
fi
if [ "${SLURM_ARRAY_TASK_COUNT:-1}" -lt 2 ]; then
  echo "slurm_tune.sh: submit as an array of at least 2 tasks (--array=0-N)" >&2
  exit 2
fi
exec build/plantsim tune "$scenario" --quiet \
  --shard "${SLURM_ARRAY_TASK_ID}/${SLURM_ARRAY_TASK_COUNT}" \
  --threads "${SLURM_CPUS_PER_TASK:-1}" --out "$shards/${SLURM_ARRAY_TASK_ID}"
