#!/usr/bin/env bash
# Craig–Bampton benchmark: reduces the production piston mesh (second order, ~240k DOFs)
# with the pin bore as RBE2 interface, 30 fixed-interface modes and static correction on
# the skirt; prints wall time per step and peak memory. Figures: docs/benchmarks.md.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
bash "$root/scripts/build.sh" > /dev/null
flexehd="${FLEXEHD_BUILD_DIR:-$root/build}/cosim/flexehd"
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
cat > "$out/report.py" <<'PY'
import json, sys
d = json.load(sys.stdin)
print("DOFs", d["dofs"], "basis", d["basis"], "->", d["modes"], "modes")
for k, v in d["timings_s"].items():
    print(f"  {k:18s} {v:8.2f} s")
print(f"  peak memory        {d['peak_memory_mib']:8.0f} MiB")
PY
"$flexehd" reduce --mesh "$root/meshes/piston.geo" --size 0.0025 --E 7.5e10 --nu 0.33 --rho 2700 \
  --interface pin_bore:rbe2 --modes 30 --static-correction skirt --out "$out/piston.h5" --json |
  /usr/bin/python3 "$out/report.py"
