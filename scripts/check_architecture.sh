#!/usr/bin/env bash
# Every source file of fem/, modal/, lube/, cosim/ and acoustics/ is named in docs/architecture.md (as
# `DIR/NAME.ext`, `DIR/NAME.*` or `DIR/NAME`, DIR the path below the module), so that the
# document is a complete map of where each concept lives. Lists the files it misses.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
doc="$root/docs/architecture.md"
missing=0
cd "$root"
for f in $(find fem modal lube cosim acoustics -name '*.cpp' -o -name '*.hpp' | sort); do
  rel=${f#*/}          # below the module: coupling/PistonSimulation.cpp
  stem=${rel%.*}       # coupling/PistonSimulation
  if ! grep -qF "\`$stem." "$doc" && ! grep -qF "\`$stem\`" "$doc"; then
    echo "docs/architecture.md does not name $f"
    missing=$((missing + 1))
  fi
done
if ((missing > 0)); then
  echo "$missing source file(s) missing from docs/architecture.md: add each to its module's table"
  exit 1
fi
echo "docs/architecture.md names every source file"
