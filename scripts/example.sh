#!/usr/bin/env bash
# README command 1: install what is missing, build, and run the shipped example — the seed
# paper's engine (examples/engine86/: SI single cylinder, 86 x 86 mm, 50 um clearance, firing
# at 1000 rpm, fully flooded): reduce the piston (and the liner) from meshes/, run the piston's
# secondary motion with rigid bodies (HD) and with the flexible piston (EHD) until the cycle is
# periodic, compute the thermal state (flexehd thermal) and run HD with it, run HD with the
# mass-conserving film flooded and starved (a 3 um liner oil layer), with the ring pack flooded
# and on that layer, and plot the comparisons
# (like the seed's Fig. 5; flooded vs starved). Results in out/engine86/.
# FLEXEHD_EXAMPLE_LINER=1 also runs the flexible piston + flexible liner case;
# FLEXEHD_EXAMPLE_RIGID_RATE=1 also EHD with the rigid film thickness's rate only in the squeeze
# term (ehd_rigid_rate.yaml, about 40 s more; docs/coupling.md section 3);
# FLEXEHD_EXAMPLE_STARVED_EHD=1 also the flexible piston on the 3 um liner oil layer
# (starved_ehd.yaml, about 3 minutes more; docs/coupling.md section 6) with its plots against
# the flooded EHD run and the starved HD run.
# FLEXEHD_EXAMPLE_NOISE=1 also slap noise: the liner bonded in its block section
# (meshes/liner_block.geo) reduced, the flexible piston run on it with the block's outer walls'
# vibration recorded (ehd_block.yaml, acoustics), its ERP plots, and the pin-offset study at 1000 and
# 3000 rpm (study_slap_noise.yaml) ranked by ERP (about 20 minutes more on one core).
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
bash "$root/scripts/install_deps.sh" --with-python  # the plots at the end need numpy and matplotlib
bash "$root/scripts/build.sh"
build="${FLEXEHD_BUILD_DIR:-$root/build}"
flexehd="$build/cosim/flexehd"
out="$root/out/engine86"
mkdir -p "$out"

# Reduced bodies (docs/modal.md, docs/case-file.md): piston alloy E 75 GPa, nu 0.33,
# 2700 kg/m^3, pin bore tied to the pin axis; grey-iron liner E 110 GPa, nu 0.26, 7200 kg/m^3,
# both seats tied. Coarse meshes keep the example to a few minutes. The piston's uniform-pressure
# patterns: the crown (the cylinder's gas) and each land, groove root and groove flank of the ring
# belt (the ring pack's gas and flank forces on the piston in ehd_rings.yaml; the bands, z in m,
# are those the run asks for: docs/coupling.md section 2).
echo "== reducing the piston and the liner"
ring_belt=()
for band in ring_lands@0.0265: ring_lands@0.0213:0.0253 ring_lands@0.0163:0.0198 \
            ring_grooves@0.02531:0.02649 ring_grooves@0.02529:0.02531 ring_grooves@0.02649:0.02651 \
            ring_grooves@0.01981:0.02129 ring_grooves@0.01979:0.01981 ring_grooves@0.02129:0.02131 \
            ring_grooves@0.01381:0.01629 ring_grooves@0.01379:0.01381 ring_grooves@0.01629:0.01631; do
  ring_belt+=(--pressure-pattern "$band")
done
"$flexehd" reduce --mesh "$root/meshes/piston.geo" --size 0.0065 --E 7.5e10 --nu 0.33 --rho 2700 \
  --interface pin_bore:rbe2@0,0,0 --modes 20 --static-correction skirt --pressure-pattern crown "${ring_belt[@]}" \
  --out "$out/piston.h5" | tail -n 2
"$flexehd" reduce --mesh "$root/meshes/liner.geo" --size 0.009 --E 1.1e11 --nu 0.26 --rho 7200 \
  --interface top_seat:rbe2 --interface bottom_seat:rbe2 --modes 20 --static-correction bore \
  --axial-hats 17 --out "$out/liner.h5" | tail -n 2

echo "== HD: rigid piston and liner"
"$flexehd" run "$root/examples/engine86/hd.yaml"
echo "== HD with the ring pack (examples/engine86/rings.yaml)"
"$flexehd" run "$root/examples/engine86/hd_rings.yaml"
/usr/bin/python3 "$root/scripts/plot_results.py" "$out/hd_rings" --compare "$out/hd" \
  --labels "HD with rings" "HD, skirt alone" --out "$out/plots_rings"
echo "== EHD: flexible piston"
"$flexehd" run "$root/examples/engine86/case.yaml"
echo "== EHD with the ring pack (gas, ring lift), the gas pressure, inertia and ring-belt loads on the flexible piston"
"$flexehd" run "$root/examples/engine86/ehd_rings.yaml"
/usr/bin/python3 "$root/scripts/plot_results.py" "$out/ehd_rings" --compare "$out/ehd" \
  --labels "EHD with rings, gas and inertia on the piston" "EHD, skirt alone" --out "$out/plots_rings_ehd"
echo "== thermal state of piston and liner (templug calibration, thermal expansion)"
"$flexehd" thermal "$root/examples/engine86/thermal.yaml" | tail -n 4
echo "== HD with the thermal state: cold clearance 75 um, hot running clearance 20-40 um"
"$flexehd" run "$root/examples/engine86/thermal_hd.yaml"
dirs=("$out/hd" "$out/ehd" "$out/thermal_hd")
labels=(HD EHD "HD hot")
if [[ "${FLEXEHD_EXAMPLE_LINER:-0}" == 1 ]]; then
  echo "== EHD: flexible piston and liner"
  "$flexehd" run "$root/examples/engine86/ehd_liner.yaml"
  dirs+=("$out/ehd_liner")
  labels+=("EHD+liner")
fi
if [[ "${FLEXEHD_EXAMPLE_RIGID_RATE:-0}" == 1 ]]; then
  echo "== EHD: flexible piston, rigid film thickness's rate only in the squeeze term"
  "$flexehd" run "$root/examples/engine86/ehd_rigid_rate.yaml"
  dirs+=("$out/ehd_rigid_rate")
  labels+=("EHD rigid rate")
fi

echo "== HD with the mass-conserving film: flooded, and on a 3 um liner oil layer (starved)"
"$flexehd" run "$root/examples/engine86/mass_conserving.yaml"
"$flexehd" run "$root/examples/engine86/starved.yaml"

/usr/bin/python3 "$root/scripts/plot_results.py" "${dirs[0]}" --compare "${dirs[@]:1}" \
  --labels "${labels[@]}" --out "$out/plots"
/usr/bin/python3 "$root/scripts/plot_results.py" "$out/mass_conserving" --compare "$out/starved" "$out/hd" \
  --labels "flooded" "starved (3 um layer)" "flooded, Reynolds condition" --out "$out/plots_oil_supply"
/usr/bin/python3 "$root/scripts/plot_wear.py" "$out/starved" --log 3 --out "$out/plots_oil_supply"
echo "== HD with the ring pack on the 3 um liner oil layer (starved rings)"
"$flexehd" run "$root/examples/engine86/starved_rings.yaml"
/usr/bin/python3 "$root/scripts/plot_results.py" "$out/starved_rings" --compare "$out/hd_rings" "$out/starved" \
  --labels "rings on the 3 um layer" "rings, flooded" "skirt alone on the layer" --out "$out/plots_rings_starved"
if [[ "${FLEXEHD_EXAMPLE_STARVED_EHD:-0}" == 1 ]]; then
  echo "== EHD with the mass-conserving film on the 3 um liner oil layer (flexible piston, starved)"
  "$flexehd" run "$root/examples/engine86/starved_ehd.yaml"
  /usr/bin/python3 "$root/scripts/plot_results.py" "$out/starved_ehd" --compare "$out/ehd" "$out/starved" \
    --labels "EHD starved (3 um layer)" "EHD flooded, Reynolds condition" "HD starved (3 um layer)" \
    --out "$out/plots_starved_ehd"
  /usr/bin/python3 "$root/scripts/plot_wear.py" "$out/starved_ehd" --log 3 --out "$out/plots_starved_ehd"
  echo "EHD on the starved layer: $out/starved_ehd/, plots against the flooded EHD and the starved HD runs in"
  echo "$out/plots_starved_ehd/."
fi
if [[ "${FLEXEHD_EXAMPLE_NOISE:-0}" == 1 ]]; then
  echo "== slap noise: the liner in its block, the block's outer walls radiating"
  # Grey iron for liner and block, bonded; the block's base held (docs/meshes.md).
  "$flexehd" reduce --mesh "$root/meshes/liner_block.geo" --size 0.009 --E 1.1e11 --nu 0.26 --rho 7200 \
    --interface base:rbe2 --modes 30 --static-correction bore --axial-hats 17 --out "$out/liner_block.h5" | tail -n 2
  "$flexehd" run "$root/examples/engine86/ehd_block.yaml"
  /usr/bin/python3 "$root/scripts/plot_acoustics.py" "$out/ehd_block"
  "$flexehd" sweep "$root/examples/engine86/study_slap_noise.yaml"
  /usr/bin/python3 "$root/scripts/rank_slap_noise.py" "$out/study_slap_noise"
  echo "Slap noise: $out/ehd_block/acoustics.json and plots_acoustics/; the pin-offset ranking in"
  echo "$out/study_slap_noise/erp_ranking.png."
fi
echo
echo "Results: $out/{hd,hd_rings,ehd,ehd_rings,thermal_hd,mass_conserving,starved,starved_rings}/history.csv and summary.json; plots in"
echo "$out/plots/ and, flooded against starved (friction, minimum film, lateral motion, oil) with the starved run's"
echo "wear maps, $out/plots_oil_supply/; the ring pack's friction and films in $out/plots_rings/ (HD) and"
echo "$out/plots_rings_ehd/ (EHD), on the starved layer in $out/plots_rings_starved/;"
echo "temperatures and thermal expansion in $out/thermal/ (piston.vtu, liner.vtu)."
echo "ParaView: open $out/ehd/film.pvd (film grid: pressure, film thickness, contact, shear) and"
echo "$out/ehd/piston.pvd (Warp By Vector: 'displacement_m' with a scale of about 20, 'elastic_displacement_m' 100-200)."
