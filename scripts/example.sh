#!/usr/bin/env bash
# README command 1: install what is missing, build, run the shipped example — the
# eigenmodes of the example engine's piston (meshes/piston.geo, aluminium alloy, free
# body), written for ParaView to out/piston_modes/modes.pvd.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
bash "$root/scripts/install_deps.sh"
bash "$root/scripts/build.sh"
build="${FLEXEHD_BUILD_DIR:-$root/build}"
out="$root/out/piston_modes"
# Piston alloy (AlSi12CuNiMg class) at room temperature: E = 75 GPa, nu = 0.33, 2700 kg/m^3.
"$build/cosim/flexehd" modes --mesh "$root/meshes/piston.geo" \
  --E 7.5e10 --nu 0.33 --rho 2700 --count 16 --out "$out"
echo
echo "Mode shapes: open $out/modes.pvd in ParaView, apply Warp By Vector (displacement);"
echo "the time steps are the mode numbers (Filters > Animate Modes animates each one)."
