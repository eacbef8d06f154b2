#!/usr/bin/env bash
# Every test: installs what is missing, builds the normal tree and an ASan + UBSan tree, runs
# the whole GoogleTest suite (and, in the normal tree, the single-node Slurm cluster test and the
# headless Chromium test of the reports) through ctest in both (eight long tests in the normal
# tree only, below), then fuzzes each input loader for 6 s, two at a time, from the sanitizer tree.
set -euo pipefail
cd "$(dirname "$0")/.."
root=$PWD
./scripts/install_deps.sh test
# The sanitizer tree is built with clang: three times faster to compile under ASan + UBSan than
# g++ here (one app file: 23 s against 75 s at -O2 -g), so the whole test command fits its time.
# The same tree holds the fuzzers (scripts/sanitize_tree.sh). It builds from the start, in a
# session of its own at the lowest priority, while the Release tree builds and its tests run:
# it takes only the CPU they leave idle (links, the build's last units, the Slurm test that runs
# alone, the last tests ending one by one). The session's autogroup gets nice 19 too: with the
# kernel's autogroups (sched_autogroup_enabled), a nice 19 process in a session of its own
# would otherwise get the same share as the Release tree's, and the Release ctest took 240 s
# instead of about 140.
mkdir -p build-sanitize
setsid -w bash -c 'echo 19 > /proc/self/autogroup 2> /dev/null; exec nice -n 19 ./scripts/sanitize_tree.sh' \
  > build-sanitize/build.log 2>&1 &
sanitize_build=$!
stop_sanitize_build() { kill -- -"$sanitize_build" 2>/dev/null || kill "$sanitize_build" 2>/dev/null || true; }
./scripts/build.sh build -DCMAKE_BUILD_TYPE=Release || { stop_sanitize_build; exit 1; }
(cd build && ctest --output-on-failure --parallel "$(nproc)") || { stop_sanitize_build; exit 1; }
wait "$sanitize_build" || { cat build-sanitize/build.log; echo "test.sh: the sanitizer tree did not build" >&2; exit 1; }
# The docking suites run at a fortieth of their size there (at least 6 episodes each) (tests/test_docking_suite.cpp): enough to
# exercise every path under the sanitizers; the statistics are the Release tree's.
# Eight long tests run in the Release tree only; what they exercise runs under the sanitizers in
# shorter tests (costs under ASan + UBSan on 25ddb9d): the particle filter's kidnap and docking
# (20 s; BatchFiles.AKidnappedParticleFilterConfirmsItsPlaceAtAYardsCorner), MPPI docking on a
# plant (15.5 s; MppiOptimizer.* and the DWB instance of the same SamplingController test), a
# tuning split in shards and merged (14.7 s; Cli.TuneEndToEndHeldOutResumableAndItsBestRuns and
# BatchFiles.FourShardsMergedEqualOneRun), the sweep model's order cost (10 s; ThreeShares/Shares.*),
# the coverage figure's panels (10 s; the other FigureLayout tests), the exact order on the pit
# (9.6 s; ExactOrder.TheRelaxation*), seed 001's pursuit among moving obstacles (9.2 s;
# PotentialField.CatchesATargetSlowerThanItself), MPPI passing a box (7.1 s; MppiOptimizer.StopsShortOfABoxOnThePlan).
release_only='^(Localization\.ParticlesFindAKidnappedRobotAgainAndDock|Nav2/SamplingControllers\.DockWithoutContact/"mppi"|Cli\.TuneShardsJoinedByAMergeEqualOneRun|SweepModel\.TheOrderCostIsThePathsOwnTravelAndTurns|FigureLayout\.CoveragePanelsListTheirCellTintsAndSayHowEachOrderWasFound|ExactOrder\.NoOtherMethodsOrderIsCheaperOnThePit|Seed001\.CatchesATargetSlowerThanItselfAmongMovingObstacles|MppiOptimizer\.PassesABoxBesideThePlan)$'
# intercept_tls_get_addr=0: LeakSanitizer's tracer read a dynamic-TLS entry of the main thread as
# a range from 0xa61 and crashed at exit ("Tracer caught signal 11", LSan's fatal error) in a
# render test that had opened OSMesa on demand, every time under ctest, never when run by hand;
# the heap, stacks, globals and static TLS are still scanned.
(cd build-sanitize && PLANTSIM_SUITE_SCALE=0.025 ASAN_OPTIONS=detect_leaks=1:intercept_tls_get_addr=0 UBSAN_OPTIONS=print_stacktrace=1 \
   LSAN_OPTIONS="suppressions=$root/tests/lsan.supp" \
   ctest --output-on-failure --parallel "$(nproc)" -E "$release_only")
# libFuzzer on every loader of untrusted input, 6 s each under ASan + UBSan after replaying every
# regression input (scripts/fuzz.sh): a smoke test that fits the test command's 15 minutes; the
# hour-long runs are `scripts/fuzz.sh 3600`, outside it (docs/testing.md).
./scripts/fuzz.sh 6
