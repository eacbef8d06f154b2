#!/usr/bin/env bash
# Every test: installs what is missing, builds the normal tree and an ASan + UBSan tree, runs
# the whole GoogleTest suite (and, in the normal tree, the single-node Slurm cluster test and the
# headless Chromium test of the reports) through ctest in both, then fuzzes each input loader for
# 10 s, two at a time, from the sanitizer tree.
set -euo pipefail
cd "$(dirname "$0")/.."
root=$PWD
./scripts/install_deps.sh test
./scripts/build.sh build -DCMAKE_BUILD_TYPE=Release
(cd build && ctest --output-on-failure --parallel "$(nproc)")
# The sanitizer tree is built with clang: three times faster to compile under ASan + UBSan than
# g++ here (one app file: 23 s against 75 s at -O2 -g), so the whole test command fits its time.
# The same tree holds the fuzzers (scripts/sanitize_tree.sh).
./scripts/sanitize_tree.sh
# The docking suites run at a fortieth of their size there (at least 6 episodes each) (tests/test_docking_suite.cpp): enough to
# exercise every path under the sanitizers; the statistics are the Release tree's.
# intercept_tls_get_addr=0: LeakSanitizer's tracer read a dynamic-TLS entry of the main thread as
# a range from 0xa61 and crashed at exit ("Tracer caught signal 11", LSan's fatal error) in a
# render test that had opened OSMesa on demand, every time under ctest, never when run by hand;
# the heap, stacks, globals and static TLS are still scanned.
(cd build-sanitize && PLANTSIM_SUITE_SCALE=0.025 ASAN_OPTIONS=detect_leaks=1:intercept_tls_get_addr=0 UBSAN_OPTIONS=print_stacktrace=1 \
   LSAN_OPTIONS="suppressions=$root/tests/lsan.supp" \
   ctest --output-on-failure --parallel "$(nproc)")
# libFuzzer on every loader of untrusted input, 10 s each under ASan + UBSan after replaying every
# regression input (scripts/fuzz.sh): a smoke test that fits the test command's 20 minutes; the
# hour-long runs are `scripts/fuzz.sh 3600`, outside it (docs/testing.md).
./scripts/fuzz.sh 10
