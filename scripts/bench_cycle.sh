#!/usr/bin/env bash
# Benchmark: one full 720° cycle of the example engine on the default film grid
# (48 x 144) with rigid bodies (HD, hd.yaml), the flexible piston (EHD, case.yaml) and the
# flexible piston + flexible liner (ehd_liner.yaml), each with its default output (history,
# summary, VTK snapshots every 10°, mode shapes). Target: the piston + liner cycle <= 60 s on
# 2 cores. Prints where the time goes, from summary.json timings_s (wall time, s):
#   film       Reynolds solves, asperity contact, film integrals (Jacobian solves included)
#   mapping    load and deformation mapping products (Φᵀ A p, D Φ y: modal force, elastic Δh)
#   modal      modal updates: quasi-static response C f and the IQN-ILS / Aitken accelerator
#   dynamics   Newton, step control, records (the rest of the step loop)
#   output     history.csv, VTK snapshots, mode-shape export
#   setup      reading the bodies, compliance, mapping operators and their modal products
# Each results directory is removed first, so the mode shapes are exported cold. The load
# average before and after each run is printed: the 2 cores may be shared.
# Makes the example's reduced bodies first if they are missing (as scripts/example.sh does).
# FLEXEHD_BUILD_DIR: the build to time (default build/); FLEXEHD_BENCH_OUT: the results
# directories (default out/bench_cycle/); FLEXEHD_BENCH_CASES: a subset, e.g. "hd ehd_liner".
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
load() { cut -d' ' -f1 /proc/loadavg; }
printf '%-10s %6s %6s %6s %7s %6s %8s %6s %6s %6s %8s  %s\n' case total setup film mapping modal dynamics output steps "solves/step" "cpu_s" "load before/after"
results="${FLEXEHD_BENCH_OUT:-$root/out/bench_cycle}"
for case in ${FLEXEHD_BENCH_CASES:-hd case ehd_liner}; do
  dir="$results/$case"
  rm -rf "$dir"; mkdir -p "$results"
  before=$(load)
  /usr/bin/time -f "%U %S" -o "$dir.cpu" "$flexehd" run "$root/examples/engine86/$case.yaml" --cycles 1 --quiet --out "$dir" >/dev/null
  after=$(load)
  /usr/bin/python3 - "$dir/summary.json" "$case" "$before" "$after" "$dir.cpu" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))
t, it = s["timings_s"], s["iterations"]
cpu = sum(float(x) for x in open(sys.argv[5]).read().split())
print(f"{sys.argv[2]:10s} {t['total']:6.1f} {t['setup']:6.1f} {t['film']:6.1f} {t.get('mapping', 0.0):7.1f} "
      f"{t.get('modal', 0.0):6.1f} {t['dynamics']:8.1f} {t['output']:6.1f} {it['steps']:6d} "
      f"{it['film_solves_per_step_mean']:6.2f} {cpu:8.1f}  {sys.argv[3]}/{sys.argv[4]}")
PY
  rm -f "$dir.cpu"
done
