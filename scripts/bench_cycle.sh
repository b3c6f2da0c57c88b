#!/usr/bin/env bash
# Benchmark of issue 6: one full 720° cycle of the example engine with flexible piston and
# flexible liner on the default film grid (48 x 144), timed per component (summary.json
# timings_s: setup, film, structure, dynamics, output). Target: <= 60 s on 2 cores.
# Makes the example's reduced bodies first if they are missing (as scripts/example.sh does).
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build="${FLEXEHD_BUILD_DIR:-$root/build}"
flexehd="$build/cosim/flexehd"
out="$root/out/engine86"
mkdir -p "$out"
[[ -f "$out/piston.h5" ]] || "$flexehd" reduce --mesh "$root/meshes/piston.geo" --size 0.0065 --E 7.5e10 \
  --nu 0.33 --rho 2700 --interface pin_bore:rbe2@0,0,0 --modes 20 --static-correction skirt --out "$out/piston.h5" >/dev/null
[[ -f "$out/liner.h5" ]] || "$flexehd" reduce --mesh "$root/meshes/liner.geo" --size 0.009 --E 1.1e11 --nu 0.26 \
  --rho 7200 --interface top_seat:rbe2 --interface bottom_seat:rbe2 --modes 20 --static-correction bore \
  --axial-hats 17 --out "$out/liner.h5" >/dev/null
for case in hd case ehd_liner; do
  "$flexehd" run "$root/examples/engine86/$case.yaml" --cycles 1 --quiet --out "$root/out/bench_cycle/$case" >/dev/null
  /usr/bin/python3 - "$root/out/bench_cycle/$case/summary.json" "$case" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))
t, it = s["timings_s"], s["iterations"]
print(f"{sys.argv[2]:10s} total {t['total']:6.1f} s  setup {t['setup']:5.1f}  film {t['film']:5.1f}  "
      f"structure {t['structure']:5.1f}  dynamics {t['dynamics']:5.1f}  output {t['output']:5.1f}  "
      f"steps {it['steps']}  film solves/step {it['film_solves_per_step_mean']:.2f}")
PY
done
