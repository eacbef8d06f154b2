#!/usr/bin/env bash
# The reports as a browser shows them: a run report (with its replay), a batch report, a
# comparison and the dashboard linking them are made in a scratch folder and opened in headless
# Chromium. Fails when any image does not load (data-images-loaded on <html>, set by the page
# after its load event) or when the replay does not advance (data-replay-frames and
# data-replay-time on its section) or shows no estimator verdict (data-replay-estimator), or when the dashboard or any report page is wider than a
# 1,400-pixel window (data-page-width, the page's scroll width). Usage: scripts/browser_test.sh BUILD_DIR
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="$(cd "${1:?usage: browser_test.sh BUILD_DIR}" && pwd)"
plantsim="$build/plantsim"
browser="$(command -v chromium || command -v chromium-browser || true)"
if [ -z "$browser" ]; then
  echo "browser_test: chromium is not installed (./scripts/install_deps.sh test installs it)" >&2
  exit 1
fi
scratch="$(mktemp -d)"
trap 'rm -rf "$scratch"' EXIT
cd "$scratch"
"$plantsim" run "$root/data/worlds/examples/corridor_crossing.json" --out run > /dev/null
"$plantsim" batch "$root/tests/fixtures/browser_batch.yaml" --out batch --quiet > /dev/null
"$plantsim" compare "$root/data/worlds/examples/small_plant.json" --planners vg,grid --plan-only --out compare > /dev/null
"$plantsim" summarize run --html index.html --link batch/report.html --link compare/report.html > /dev/null

dom() {  # the page's DOM after its scripts ran for 4 s of virtual time, in a 1400 x 1000 window
  "$browser" --headless --no-sandbox --disable-gpu --disable-dev-shm-usage --no-first-run \
    --window-size=1400,1000 \
    --user-data-dir="$scratch/profile" --virtual-time-budget=4000 --dump-dom "file://$scratch/$1" 2> /dev/null
}
status=0
all_loaded='^data-images-loaded="all ([0-9]+)"$'
for page in index.html run/report.html batch/report.html compare/report.html; do
  html="$(dom "$page")"
  loaded="$(grep -o 'data-images-loaded="[^"]*"' <<< "$html" | head -1 || true)"
  if [[ "$loaded" =~ $all_loaded ]] && [ "${BASH_REMATCH[1]}" -gt 0 ]; then
    echo "browser_test: $page: ${BASH_REMATCH[1]} images loaded"
  else
    echo "browser_test: FAIL $page: images not all loaded (${loaded:-no marker: the page script did not run})" >&2
    status=1
  fi
  # Every report page, not the dashboard alone, fits a 1,400-pixel window (issue 89).
  page_width="$(grep -o 'data-page-width="[0-9]*"' <<< "$html" | grep -o '[0-9]\+' || echo none)"
  if [ "$page_width" != none ] && [ "$page_width" -le 1400 ]; then
    echo "browser_test: $page fits a 1400-pixel window ($page_width px)"
  else
    echo "browser_test: FAIL $page is $page_width px wide in a 1400-pixel window" >&2
    status=1
  fi
done
width="$(dom index.html | grep -o 'data-page-width="[0-9]*"' | grep -o '[0-9]\+' || echo none)"
if [ "$width" != none ] && [ "$width" -le 1400 ]; then
  echo "browser_test: the dashboard fits a 1400-pixel window ($width px)"
else
  echo "browser_test: FAIL the dashboard is $width px wide in a 1400-pixel window" >&2
  status=1
fi
html="$(dom run/report.html)"
frames="$(grep -o 'data-replay-frames="[0-9]*"' <<< "$html" | grep -o '[0-9]\+' || echo 0)"
time_s="$(grep -o 'data-replay-time="[0-9.]*"' <<< "$html" | grep -o '[0-9.]\+' || echo 0)"
if [ "${frames:-0}" -ge 10 ] && awk -v t="$time_s" 'BEGIN { exit !(t > 0) }'; then
  echo "browser_test: the replay advanced: $frames frames drawn, at t = $time_s s"
else
  echo "browser_test: FAIL the replay did not advance (frames ${frames:-none}, time ${time_s:-none})" >&2
  status=1
fi
estimator="$(grep -o 'data-replay-estimator="[a-z]*"' <<< "$html" | cut -d'"' -f2 || true)"
if [[ "$estimator" =~ ^(ok|degraded|lost)$ ]]; then
  echo "browser_test: the replay shows the estimator's verdict per frame ($estimator at the last frame drawn)"
else
  echo "browser_test: FAIL the replay shows no estimator verdict (${estimator:-none})" >&2
  status=1
fi
# A sampling controller's replay lists what it draws of it; a kidnapped robot's replay, opened at
# its last seconds (report.html#t=...), keeps the robot and its estimate in view after the
# failure (the view was locked on the failure's place while the robot drove on, lost).
"$plantsim" run "$root/data/worlds/examples/small_plant.json" --config "$root/tests/fixtures/replay_mppi.json" --out mppi > /dev/null
legend="$(dom mppi/report.html | grep -o 'data-replay-legend="[^"]*"' || true)"
if [[ "$legend" == *"sampled trajectories|chosen trajectory"* ]]; then
  echo "browser_test: the MPPI replay draws its sampled and chosen trajectories"
else
  echo "browser_test: FAIL the MPPI replay's legend lacks its trajectories (${legend:-none})" >&2
  status=1
fi
"$plantsim" run "$root/data/worlds/examples/small_plant.json" --config "$root/tests/fixtures/replay_kidnap.json" --out kidnap > /dev/null || true
in_view="$(dom 'kidnap/report.html#t=115' | grep -o 'data-replay-in-view="[^"]*"' | cut -d'"' -f2 || true)"
if [ "$in_view" = "robot estimate" ]; then
  echo "browser_test: after a kidnap's failure the replay keeps the robot and its estimate in view"
else
  echo "browser_test: FAIL after a kidnap's failure the replay shows '${in_view:-nothing}' of the robot and its estimate" >&2
  status=1
fi
exit $status
