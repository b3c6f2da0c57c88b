#!/usr/bin/env bash
# Speed-up of `flexehd sweep` from 1 process to 2 MPI ranks (docs/benchmarks.md, "Design
# study"): 8 variants of the rigid example (pin offset x clearance, one cycle, film
# grid FLEXEHD_BENCH_GRID="AXIAL CIRCUMFERENTIAL", default "32 96"), run once in one process
# and once with `mpirun -n 2`.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build="${FLEXEHD_BUILD_DIR:-$root/build}"
flexehd="$build/cosim/flexehd"
read -r axial circ <<< "${FLEXEHD_BENCH_GRID:-32 96}"
work=$(mktemp -d /tmp/flexehd_bench_sweep.XXXXXX)
trap 'rm -rf "$work"' EXIT
cat > "$work/study.yaml" <<YAML
name: bench sweep
base_case: $root/examples/engine86/hd.yaml
set:
  grid.axial_nodes: $axial
  grid.circumferential_nodes: $circ
  time.max_cycles: 1
  output.vtk_every_deg: 0
  output.mode_shapes: false
parameters:
  engine.pin_offset: [-1.0e-3, -0.5e-3, 0.5e-3, 1.0e-3]
  piston.clearance: [40e-6, 60e-6]
YAML
# Open MPI refuses root without these (containers); --oversubscribe allows more ranks than cores.
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
echo "grid $axial x $circ; cores: $(nproc), load before: $(cut -d' ' -f1-3 /proc/loadavg)"
t0=$(date +%s.%N)
"$flexehd" sweep "$work/study.yaml" --out "$work/one" --quiet --json >/dev/null
t1=$(date +%s.%N)
mpirun -n 2 --oversubscribe --bind-to none "$flexehd" sweep "$work/study.yaml" --out "$work/two" --quiet --json >/dev/null
t2=$(date +%s.%N)
echo "load after: $(cut -d' ' -f1-3 /proc/loadavg)"
python3 - "$t0" "$t1" "$t2" "$work" <<'PY'
import csv, sys
t0, t1, t2, work = float(sys.argv[1]), float(sys.argv[2]), float(sys.argv[3]), sys.argv[4]
one, two = t1 - t0, t2 - t1
def rows(d):
    with open(f"{work}/{d}/study.csv") as f:
        return [{k: v for k, v in r.items() if k != "run_time_s"} for r in csv.DictReader(f)]
for d in ("one", "two"):
    runs = [float(r["run_time_s"]) for r in csv.DictReader(open(f"{work}/{d}/study.csv"))]
    print(f"variant wall time ({d}): mean {sum(runs)/len(runs):.2f} s, min {min(runs):.2f}, max {max(runs):.2f}")
print(f"| ranks | wall time [s] | speed-up |\n|---|---|---|\n| 1 | {one:.1f} | 1.00 |\n| 2 | {two:.1f} | {one/two:.2f} |")
print("study.csv identical (but run times):", rows("one") == rows("two"))
PY
