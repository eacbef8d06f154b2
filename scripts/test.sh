#!/usr/bin/env bash
# Every test: installs what is missing, builds the normal tree and an ASan + UBSan tree,
# and runs the whole GoogleTest suite through ctest in both.
set -euo pipefail
cd "$(dirname "$0")/.."
root=$PWD
./scripts/install_deps.sh test
./scripts/build.sh build -DCMAKE_BUILD_TYPE=Release
(cd build && ctest --output-on-failure --parallel "$(nproc)")
./scripts/build.sh build-sanitize -DCMAKE_BUILD_TYPE=RelWithDebInfo -DPLANTSIM_SANITIZE=ON
# The docking suites run at a quarter of their size there (tests/test_docking_suite.cpp).
(cd build-sanitize && PLANTSIM_SUITE_SCALE=0.25 ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 \
   LSAN_OPTIONS="suppressions=$root/tests/lsan.supp" \
   ctest --output-on-failure --parallel "$(nproc)")
