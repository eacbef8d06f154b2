#!/bin/bash
#SBATCH --job-name=plantsim
#SBATCH --array=0-15
#SBATCH --cpus-per-task=8
#SBATCH --time=01:00:00
# One shard per array task; merge once every task has finished:
#   sbatch --dependency=afterok:<jobid> --wrap "build/plantsim merge results/shards/* --out results/merged"
build/plantsim batch scenarios/plants.yaml --quiet \
  --shard "${SLURM_ARRAY_TASK_ID}/${SLURM_ARRAY_TASK_COUNT}" \
  --threads "${SLURM_CPUS_PER_TASK}" --out "results/shards/${SLURM_ARRAY_TASK_ID}"
