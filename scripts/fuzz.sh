#!/usr/bin/env bash
# Builds the libFuzzer harnesses with clang under ASan + UBSan (in the tree build-sanitize) and runs each
# for SECONDS (default 60) on a seed corpus made from the shipped files, after replaying the
# regression fixtures of fuzz/regressions/<harness>/ (inputs that once crashed). Prints the
# executions each harness reached; exits 1 on any crash, leak or timeout (the input is kept in
# build-fuzz/artifacts/). Usage: scripts/fuzz.sh [SECONDS] [HARNESS...]
set -euo pipefail
cd "$(dirname "$0")/.."
root=$PWD
seconds=${1:-60}
shift || true
harnesses=("$@")
[ ${#harnesses[@]} -gt 0 ] || harnesses=(world_json ros_map movingai episode_config scenario coverage_params names bounded_parsers tune_spec nav2_params actions)
data=$(cd ../shared/data && pwd)

./scripts/sanitize_tree.sh  # the harnesses are built in the sanitizer tree
mkdir -p build-fuzz

corpus=build-fuzz/corpus
rm -rf "$corpus"
mkdir -p "$corpus"/{world_json,ros_map,movingai,episode_config,scenario,coverage_params,names,bounded_parsers,tune_spec,nav2_params,actions} build-fuzz/artifacts
# Actions: the regression fixtures seed the corpus (their layout: fuzz/fuzz_actions.cpp).
cp fuzz/regressions/actions/* "$corpus/actions/"
small() { [ "$(stat -c %s "$1")" -le 65536 ]; }
for f in data/worlds/examples/*.json data/worlds/plants/*.json tests/fixtures/*.json "$data"/worlds/world_N10.json "$data"/worlds/world_N50.json; do
  small "$f" && cp "$f" "$corpus/world_json/$(basename "$f")"
done
for f in configs/*.json; do cp "$f" "$corpus/episode_config/"; done
cp configs/coverage_params.json "$corpus/coverage_params/"
printf '{"chnn": {"restarts": 3, "eta": 1e3}, "exact": {"max_prefixes": 10}}' > "$corpus/coverage_params/small.json"
for f in data/scenarios/*.yaml; do cp "$f" "$corpus/scenario/"; done
# The bounded readers: small JSON and YAML inputs of every kind (the regressions add the hostile ones).
for f in configs/*.json data/worlds/examples/*.json data/scenarios/*.yaml tests/fixtures/nav2/*.yaml; do
  small "$f" && cp "$f" "$corpus/bounded_parsers/$(basename "$f")"
done
# Tuning scenarios over the harness's own tiny world (w.json in its scratch folder).
for f in data/scenarios/tune_*.yaml data/scenarios/*_tuning.yaml; do
  sed -e '/^  - .*\.json$/d' -e 's/^worlds:.*$/worlds: [w.json]/' "$f" > "$corpus/tune_spec/$(basename "$f")"
done
printf 'worlds: [w.json]\nplanners: [vg]\nseeds: 2\ntune:\n  validation_seeds: [5, 6]\n  budget: 12\n  method: bobyqa\n  objective: success_then_time\n  min_wilson: 0.5\n  parameters: {tracking.max_linear_speed_mps: [0.3, 0.8], docking.approach_speed_mps: [0.04, 0.2]}\n' \
  > "$corpus/tune_spec/small.yaml"
for f in tests/fixtures/nav2/*.yaml; do cp "$f" "$corpus/nav2_params/"; done
# Names and words people and attackers use (issue 51's cases among them).
i=0
for n in "small_plant" "脱硫 plant #2 (100%)" "plant';touch\${IFS}X;'" "x'; touch F; echo '" $'\e[2Jwiped' \
         $'a\u202egnp.exe' "<!--<script>" "javascript:alert(1)" "=HYPERLINK(1)" "a|b" ".." " a"; do
  printf '%s' "$n" > "$corpus/names/$((i++))"
done
printf 'worlds: [w.json]\nplanners: [vg]\nfaults: {a: {lidar: {range_noise_m: 0.01}}, b: {unmapped_obstacles: 2}}\nseeds: 2\ngate: {min_success: 0.5, configurations: [{planner: vg, min_success: 0.9}]}\nsweep: {parameter: drive.tyre_friction, values: [0.1, 0.5]}\n' \
  > "$corpus/scenario/small.yaml"
# A small ROS map (a 12 x 10 PGM, text and binary) and a cut of the depot.
{ printf 'image: map.pgm\nresolution: 0.5\norigin: [0.0, 0.0, 0.0]\nnegate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.196\n\n--8<--\n'
  printf 'P2\n12 10\n255\n'; for y in $(seq 10); do for x in $(seq 12); do
    if [ "$y" = 1 ] || [ "$y" = 10 ] || [ "$x" = 1 ] || [ "$x" = 12 ]; then printf '0 '; else printf '254 '; fi; done; echo; done
} > "$corpus/ros_map/text.txt"
{ printf 'image: map.pgm\nresolution: 0.25\norigin: [-1.0, 2.0, 0.0]\noccupied_thresh: 0.65\nfree_thresh: 0.196\nmode: trinary\n\n--8<--\n'
  head -c 20000 "$data/ros_maps/depot.pgm"
} > "$corpus/ros_map/depot_cut.txt"
{ cat "$data/anyangle/arena.map"; printf '\n--8<--\n'; head -5 "$data/anyangle/arena.scen"; } > "$corpus/movingai/arena.txt"

# Two harnesses at a time (one per core of the development machine; FUZZ_JOBS to change it).
jobs=${FUZZ_JOBS:-$(nproc)}
rm -f build-fuzz/*.status
fuzz_one() {  # fuzz_one HARNESS: its regression fixtures, then SECONDS of fuzzing; status in build-fuzz/HARNESS.status
  local h=$1 bin=build-sanitize/fuzz/fuzz_$1 st=0
  if [ -d "fuzz/regressions/$h" ] && [ -n "$(ls -A "fuzz/regressions/$h")" ]; then
    "$bin" -runs=0 "fuzz/regressions/$h"/* > "build-fuzz/$h.regressions.log" 2>&1 \
      || { echo "fuzz: $h: a regression fixture fails again"; tail -30 "build-fuzz/$h.regressions.log"; st=1; }
  fi
  "$bin" "$corpus/$h" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -max_len=65536 \
    -artifact_prefix="build-fuzz/artifacts/${h}-" -print_final_stats=1 > "build-fuzz/$h.log" 2>&1 || {
    echo "fuzz: $h FOUND A PROBLEM (input in build-fuzz/artifacts/):"; grep -A25 "ERROR\|==ERROR\|runtime error\|deadly signal\|timeout" "build-fuzz/$h.log" | head -40; st=1; }
  local runs
  runs=$(grep -o "stat::number_of_executed_units: *[0-9]*" "build-fuzz/$h.log" | grep -o "[0-9]*$" || echo "?")
  echo "fuzz: $h: $runs executions in $seconds s"
  echo "$st" > "build-fuzz/$h.status"
}
for h in "${harnesses[@]}"; do
  while [ "$(jobs -rp | wc -l)" -ge "$jobs" ]; do wait -n || true; done
  fuzz_one "$h" &
done
wait
status=0
for h in "${harnesses[@]}"; do [ "$(cat "build-fuzz/$h.status" 2>/dev/null)" = 0 ] || status=1; done
exit $status
