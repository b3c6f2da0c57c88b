#!/usr/bin/env bash
# Builds flexehd with AddressSanitizer and UndefinedBehaviorSanitizer in build-sanitize/ and
# runs the whole test suite under them. Any report of ours fails the run; the only suppressed
# reports are third-party ones, listed in scripts/sanitize.supp with the reason.
# Takes about 30 min on 2 cores (a full build without the compiler cache, then the suite at a
# few times its normal cost). README, "Tests".
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
bash "$root/scripts/install_deps.sh"
build="${FLEXEHD_SANITIZE_DIR:-$root/build-sanitize}"
flags="-fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=undefined"
FLEXEHD_BUILD_DIR="$build" CMAKE_BUILD_TYPE=RelWithDebInfo bash "$root/scripts/build.sh" \
  -DCMAKE_CXX_FLAGS="$flags" -DCMAKE_C_FLAGS="$flags" \
  -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=address,undefined" \
  -DCMAKE_SHARED_LINKER_FLAGS="-fsanitize=address,undefined"
supp="$root/scripts/sanitize.supp"
# detect_leaks=0: Gmsh, VTK and Open MPI keep process-lifetime allocations that LeakSanitizer
# would list; ASan's memory errors and UBSan's reports are what this run checks.
export ASAN_OPTIONS="detect_leaks=0:abort_on_error=0:halt_on_error=1:suppressions=$supp"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
export OPENBLAS_NUM_THREADS=1
export FLEXEHD_SANITIZE=1  # tests that limit the address space skip themselves
ctest --test-dir "$build" --output-on-failure -j "$(nproc)" --timeout 1800
