#!/usr/bin/env bash
# The main job: installs what is missing, builds, and runs the demo episodes. Each run
# writes results/<world>/{summary.json,trajectory.csv,run.png}; results/summary.md gathers them.
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/install_deps.sh
./scripts/build.sh build -DCMAKE_BUILD_TYPE=Release
mkdir -p results
worlds=(worlds/examples/small_plant.json ../shared/data/worlds/world_N10.json ../shared/data/worlds/world_N50.json ../shared/data/worlds/world_N200.json)
status=0
dirs=()
for w in "${worlds[@]}"; do
  name=$(basename "$w" .json)
  ./build/plantsim run "$w" --out "results/$name" || status=1
  dirs+=("results/$name")
done
./build/plantsim summarize "${dirs[@]}" --out results/summary.md
echo "demo: figures and summaries in results/ (overview: results/summary.md)"
exit $status
