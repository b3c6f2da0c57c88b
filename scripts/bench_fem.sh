#!/usr/bin/env bash
# FEM benchmark: assembly, factorization, eigen-solve times and peak memory on the
# production-size second-order piston mesh (~240k DOFs), and assembly alone on a
# ~1.1M-DOF piston mesh. Builds first. Figures are recorded in docs/benchmarks.md.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
bash "$root/scripts/build.sh" > /dev/null
bench="${FLEXEHD_BUILD_DIR:-$root/build}/bench/bench_fem"
echo "== production piston mesh: assembly + factorization + 20 modes =="
"$bench" "$root/meshes/piston.geo" 0.0025 --modes 20
echo
echo "== fine piston mesh: assembly only =="
"$bench" "$root/meshes/piston.geo" "${FLEXEHD_BENCH_FINE_SIZE:-0.0014}" --assembly-only
