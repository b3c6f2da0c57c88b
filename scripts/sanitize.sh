#!/usr/bin/env bash
# Builds flexehd with AddressSanitizer and UndefinedBehaviorSanitizer in build-sanitize/ and
# runs the whole test suite under them. Any report fails the run; nothing is suppressed.
# Takes about 35 min on 2 cores (a 15-min build without the compiler cache, then the suite at a
# few times its normal cost). README, "Tests".
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
bash "$root/scripts/install_deps.sh"
build="${FLEXEHD_SANITIZE_DIR:-$root/build-sanitize}"
# EIGEN_MALLOC_ALREADY_ALIGNED=1: under AddressSanitizer Eigen 3.4 switches to its own aligned
# malloc (an offset into a malloc block), while libgmsh, built without it, frees Eigen storage
# with plain free(). Where an Eigen function is instantiated in both (PartialPivLU inside Gmsh's
# meshing), storage from ours is freed by Gmsh's: a "bad-free" that is this mismatch, not a bug
# of either. glibc's malloc on x86-64 is 16-byte aligned, Eigen's default alignment here.
flags="-fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=undefined -DEIGEN_MALLOC_ALREADY_ALIGNED=1"
FLEXEHD_BUILD_DIR="$build" CMAKE_BUILD_TYPE=RelWithDebInfo bash "$root/scripts/build.sh" \
  -DCMAKE_CXX_FLAGS="$flags" -DCMAKE_C_FLAGS="$flags" \
  -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=address,undefined" \
  -DCMAKE_SHARED_LINKER_FLAGS="-fsanitize=address,undefined" \
  -DFLEXEHD_TEST_TIMEOUT_SCALE=10  # the per-test budgets of tests/CMakeLists.txt, for the slower build
# detect_leaks=0: Gmsh, VTK and Open MPI keep process-lifetime allocations that LeakSanitizer
# would list; ASan's memory errors and UBSan's reports are what this run checks.
export ASAN_OPTIONS="detect_leaks=0:abort_on_error=0:halt_on_error=1"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
export OPENBLAS_NUM_THREADS=1
export FLEXEHD_SANITIZE=1  # tests that limit the address space skip themselves
ctest --test-dir "$build" --output-on-failure -j "$(nproc)" --timeout 1800
