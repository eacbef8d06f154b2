#!/usr/bin/env bash
# The plugin story as a user lives it (issue 86): plantsim installed from the build tree into a
# fresh prefix, examples/plugin configured and built out of the tree against that installed
# package (find_package(plantsim CONFIG)), its components listed by `plantsim info --plugin`, and
# a batch comparing its Stanley follower with the built-ins, whose summary lists it as a row that
# docks. Usage: scripts/test_plugin_example.sh BUILD_DIR
set -euo pipefail
build=$(cd "$1" && pwd)
root=$(cd "$(dirname "$0")/.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cmake --install "$build" --prefix "$work/prefix" > "$work/install.log"
cmake -S "$root/examples/plugin" -B "$work/plugin" -DCMAKE_PREFIX_PATH="$work/prefix" \
  > "$work/configure.log"
cmake --build "$work/plugin" > "$work/build.log"
plugin="$work/plugin/plantsim_example_plugin.so"
plantsim="$work/prefix/bin/plantsim"
"$plantsim" info --plugin "$plugin" > "$work/info.txt"
grep -q "stanley  ($plugin)" "$work/info.txt"
grep -q "stanley.gain = 1.5  real in \[0, 20\]" "$work/info.txt"
grep -q "dead-reckoning  ($plugin)" "$work/info.txt"
"$plantsim" batch "$root/examples/plugin/compare.yaml" --plugin "$plugin" --out "$work/batch" \
  --quiet --no-figures --data "$root/../shared/data"
# One more row: stanley beside the built-ins, all of its episodes docked.
python3 - "$work/batch/summary.json" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))
rows = {}
def walk(x):
    if isinstance(x, dict):
        if "controller" in x and "episodes" in x and "succeeded" in x:
            rows.setdefault(x["controller"], [0, 0])
            rows[x["controller"]][0] += x["episodes"]; rows[x["controller"]][1] += x["succeeded"]
        for v in x.values(): walk(v)
    elif isinstance(x, list):
        for v in x: walk(v)
walk(s)
assert set(rows) >= {"pure-pursuit", "dwb", "stanley"}, rows
assert rows["stanley"][0] == 6 and rows["stanley"][1] == 6, rows
print("plugin example:", rows)
PY
