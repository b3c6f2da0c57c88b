#!/usr/bin/env bash
# README command 2: install what is missing, build, run the whole test suite.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
bash "$root/scripts/install_deps.sh"
bash "$root/scripts/build.sh"
build="${FLEXEHD_BUILD_DIR:-$root/build}"
# One BLAS thread per test: ctest runs nproc tests at once, and a threaded BLAS sums in an order
# that changes the round-off, which the run-level comparisons (e.g. FilmContacts, two contacts of
# half the viscosity against the whole skirt) see through the iteration's convergence decisions.
export OPENBLAS_NUM_THREADS=1
# Each test has its own TIMEOUT (tests/CMakeLists.txt); --timeout bounds those that have none.
ctest --test-dir "$build" --output-on-failure -j "$(nproc)" --timeout 600
