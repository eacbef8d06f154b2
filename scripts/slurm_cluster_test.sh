#!/usr/bin/env bash
# The Slurm path as users take it, on a real single-node cluster: starts munged, slurmctld and
# slurmd (background processes in a private folder, no systemd), submits the shipped array
# script docs/slurm_batch.sh and the merge with --dependency=afterok and --kill-on-invalid-dep,
# checks that the merge equals one uninterrupted run; the same for a tuning split by
# docs/slurm_tune.sh; then stops the daemons.
# Usage: scripts/slurm_cluster_test.sh [BUILD_DIR]   (needs root, slurm-wlm and munge)
set -euo pipefail
cd "$(dirname "$0")/.."
root=$PWD
build=${1:-build}
case $build in /*) ;; *) build=$root/$build ;; esac
plantsim=$build/plantsim
work=$(mktemp -d /tmp/plantsim_slurm.XXXXXX)
pids=()
cleanup() {
  for pid in "${pids[@]}"; do kill "$pid" 2>/dev/null || true; done
  sleep 1
  for pid in "${pids[@]}"; do kill -9 "$pid" 2>/dev/null || true; done
  rm -rf "$work"
}
trap cleanup EXIT
fail() { echo "slurm_cluster_test: FAIL: $*" >&2; for f in "$work"/*.log; do echo "== $f"; tail -20 "$f"; done >&2; exit 1; }

for tool in munged slurmctld slurmd sbatch squeue; do command -v "$tool" > /dev/null || fail "$tool is not installed"; done
[ "$(id -u)" -eq 0 ] || fail "needs root to start slurmd"
host=$(hostname -s)
cpus=$(nproc)

# munge: a private key and socket, so a system munged (if any) is left alone.
mkdir -p "$work/munge"
chmod 700 "$work/munge"
dd if=/dev/urandom of="$work/munge/munge.key" bs=1 count=1024 status=none
chmod 400 "$work/munge/munge.key"
munged --force --key-file="$work/munge/munge.key" --socket="$work/munge/munge.socket" \
  --pid-file="$work/munge/munged.pid" --log-file="$work/munged.log" --seed-file="$work/munge/seed" \
  || fail "munged did not start"
pids+=("$(cat "$work/munge/munged.pid")")

mkdir -p "$work/state" "$work/spool"
cat > "$work/slurm.conf" <<CONF
ClusterName=plantsimci
SlurmctldHost=$host
SlurmctldPort=16817
SlurmdPort=16818
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
AuthInfo=socket=$work/munge/munge.socket
CredType=cred/munge
StateSaveLocation=$work/state
SlurmdSpoolDir=$work/spool
SlurmctldPidFile=$work/slurmctld.pid
SlurmdPidFile=$work/slurmd.pid
SlurmctldLogFile=$work/slurmctld.log
SlurmdLogFile=$work/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
MpiDefault=none
SchedulerType=sched/backfill
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
ReturnToService=2
JobCompType=jobcomp/none
AccountingStorageType=accounting_storage/none
MailProg=/bin/true
NodeName=$host CPUs=$cpus State=UNKNOWN
PartitionName=ci Nodes=$host Default=YES MaxTime=INFINITE State=UP
CONF
export SLURM_CONF=$work/slurm.conf
slurmctld -D -i -f "$SLURM_CONF" > "$work/slurmctld.out.log" 2>&1 &
pids+=($!)
slurmd -D -f "$SLURM_CONF" > "$work/slurmd.out.log" 2>&1 &
pids+=($!)
for _ in $(seq 60); do
  if sinfo -h -o %T 2>/dev/null | grep -qE "^idle"; then break; fi
  sleep 1
done
sinfo -h -o %T | grep -qE "^idle" || fail "the node did not come up idle"

# A small scenario: 2 worlds x 2 faults x 3 seeds = 12 episodes, in 4 shards.
mkdir -p "$work/run"
cat > "$work/run/scenario.yaml" <<YAML
name: slurm_ci
worlds: [$root/data/worlds/examples/small_plant.json, \$data/worlds/world_N10.json]
faults:
  none: {}
  noisy: {lidar: {range_noise_m: 0.03}}
seeds: 3
gate: {min_success: 0.5}
YAML
ln -s "$root/docs" "$work/run/docs"
mkdir -p "$work/run/build" && ln -s "$plantsim" "$work/run/build/plantsim"
export PLANTSIM_DATA=$(cd "$root/../shared/data" && pwd)
# Waits up to 10 minutes for the jobs (a comma-separated list) to leave the queue; 1 if they did not.
wait_for_jobs() {
  for _ in $(seq 600); do
    [ -z "$(squeue -h -j "$1" 2>/dev/null)" ] && return 0
    sleep 1
  done
  return 1
}
# Submitted from elsewhere, with --chdir naming the checkout the tasks run in.
cd /
jobid=$(sbatch --parsable --chdir="$work/run" --array=0-3 --cpus-per-task=1 --output="$work/task_%a.log" \
  --export=ALL,PLANTSIM_SCENARIO=scenario.yaml,PLANTSIM_SHARDS=shards "$work/run/docs/slurm_batch.sh") || fail "sbatch of the array"
merge=$(sbatch --parsable --chdir="$work/run" --dependency=afterok:"$jobid" --kill-on-invalid-dep=yes \
  --output="$work/merge.log" --wrap "build/plantsim merge shards/0 shards/1 shards/2 shards/3 --out merged") || fail "sbatch of the merge"
wait_for_jobs "$jobid,$merge" && squeue_done=1 || fail "jobs still queued after 10 minutes: $(squeue)"
[ -f "$work/run/merged/episodes.jsonl" ] || fail "the merge job wrote nothing"
grep -q "12 of 12 episodes" "$work/merge.log" || fail "merge log: $(cat "$work/merge.log")"

# One uninterrupted run of the same scenario, then the same records and summary.
cd "$work/run"
"$plantsim" batch scenario.yaml --out whole --quiet --no-figures > "$work/whole.log" 2>&1 || fail "the single run"
# Without the wall-time fields and columns (controller_ms_*: the controller's compute time, which
# differs from run to run of the same episode; docs/batch.md).
strip_wall_records() { python3 -c 'import json,sys; print("\n".join(sorted(json.dumps({k: v for k, v in json.loads(l).items() if not k.startswith("controller_ms_")}, sort_keys=True) for l in open(sys.argv[1]))))' "$1"; }
strip_wall_columns() { python3 -c 'import csv,sys; rows=list(csv.reader(open(sys.argv[1]))); keep=[i for i,h in enumerate(rows[0]) if not h.startswith("controller_ms_")]; print("\n".join(",".join(r[i] for i in keep) for r in rows))' "$1"; }
diff <(strip_wall_records whole/episodes.jsonl) <(strip_wall_records merged/episodes.jsonl) > /dev/null || fail "merged records differ from one run"
diff <(strip_wall_columns whole/summary.csv) <(strip_wall_columns merged/summary.csv) > /dev/null || fail "merged summary differs from one run"

# A tuning split the same way: 3 tasks (NLopt's search, random search's points in two), the merge
# validating; its evaluations and best.json equal one run's.
cat > "$work/run/tune.yaml" <<YAML
name: slurm_tune_ci
worlds: [$root/data/worlds/examples/small_plant.json]
seeds: 2
tune:
  validation_seeds: [11, 12]
  budget: 2
  parameters: {tracking.max_linear_speed_mps: [0.3, 0.8]}
YAML
cd /
tune_job=$(sbatch --parsable --chdir="$work/run" --array=0-2 --cpus-per-task=1 --output="$work/tune_task_%a.log" \
  --export=ALL,PLANTSIM_SCENARIO=tune.yaml,PLANTSIM_SHARDS=tune_shards "$work/run/docs/slurm_tune.sh") || fail "sbatch of the tuning array"
tune_merge=$(sbatch --parsable --chdir="$work/run" --dependency=afterok:"$tune_job" --kill-on-invalid-dep=yes \
  --output="$work/tune_merge.log" --wrap "build/plantsim tune tune.yaml --merge tune_shards/0 tune_shards/1 tune_shards/2 --out tuned --no-figures") || fail "sbatch of the tuning merge"
wait_for_jobs "$tune_job,$tune_merge" || fail "tuning jobs still queued after 10 minutes: $(squeue)"
[ -f "$work/run/tuned/best.json" ] || fail "the tuning merge wrote no best.json: $(cat "$work/tune_merge.log")"
grep -q "taken from 3 shard folder" "$work/tune_merge.log" || fail "tuning merge log: $(cat "$work/tune_merge.log")"
cd "$work/run"
"$plantsim" tune tune.yaml --out tune_whole --quiet --no-figures > "$work/tune_whole.log" 2>&1 || fail "the single tuning"
cmp tune_whole/best.json tuned/best.json || fail "the merged tuning's best.json differs from one run's"
strip_wall() { python3 -c 'import json,sys; print("\n".join(sorted(json.dumps({k: v for k, v in json.loads(l).items() if k != "wall_s"}, sort_keys=True) for l in open(sys.argv[1]))))' "$1"; }
diff <(strip_wall tune_whole/evaluations.jsonl) <(strip_wall tuned/evaluations.jsonl) > /dev/null || fail "the merged tuning's evaluations differ from one run's"

# A dependency that can never be met is cancelled, not left waiting forever.
bad=$(sbatch --parsable --chdir="$work/run" --dependency=afterok:999999 --kill-on-invalid-dep=yes --wrap true 2>/dev/null || echo refused)
if [ "$bad" != refused ]; then
  for _ in $(seq 30); do [ -z "$(squeue -h -j "$bad" 2>/dev/null)" ] && break; sleep 1; done
  [ -z "$(squeue -h -j "$bad" 2>/dev/null)" ] || fail "a job with an invalid dependency stayed queued"
fi
echo "slurm_cluster_test: array of 4 shards + merge on a single-node cluster equals one run (${squeue_done:+12 episodes}); a tuning in 3 shards + merge equals one tuning"
