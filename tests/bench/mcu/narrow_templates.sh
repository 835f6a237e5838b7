# SPDX-License-Identifier: BSD-3-Clause
# Sourced by tests/bench/mcu/results.sh (its trees, scratch directory, sequence and helpers): the
# markdown section of docs/results/mcu.md on a narrow template set, the detector's share of a
# firmware: the templates of one known view (an axis, a cone, one distance band) as constant data
# for the Cortex-M3, the detector's code in the command line firmware's link map, and the guest
# instructions and heap of one `edgetrack detect` with those templates on the board and on the PXA270.

narrow_cone=20  # degrees about the known axis: the axis' nearest directions at 2 subdivisions (16 degrees apart)
narrow_band=0.10  # the distance band: the first pose's distance, 10 % either side (3 distances 1.1 apart)
narrow_in_plane=18  # rotations about the optical axis, 20 degrees apart (the default range's)

# first_view POS: "X,Y,Z DISTANCE" of a .pos pose (tx ty tz tux tuy tuz, camera from model): the unit
# direction from the model's origin (the cube's centre) towards the camera, in the model frame, and the
# camera's distance to it in metres. The camera sits at -R^T t.
first_view() {
  tr '\n' ' ' <"$1" | awk '{
    tx = $1; ty = $2; tz = $3; ux = $4; uy = $5; uz = $6
    th = sqrt(ux * ux + uy * uy + uz * uz); c = cos(th); s = sin(th); v = 1 - c
    if (th > 0) { ux /= th; uy /= th; uz /= th }
    r11 = c + ux * ux * v;      r12 = ux * uy * v - uz * s; r13 = ux * uz * v + uy * s
    r21 = uy * ux * v + uz * s; r22 = c + uy * uy * v;      r23 = uy * uz * v - ux * s
    r31 = uz * ux * v - uy * s; r32 = uz * uy * v + ux * s; r33 = c + uz * uz * v
    px = -(r11 * tx + r21 * ty + r31 * tz); py = -(r12 * tx + r22 * ty + r32 * tz); pz = -(r13 * tx + r23 * ty + r33 * tz)
    d = sqrt(px * px + py * py + pz * pz)
    printf "%.6f,%.6f,%.6f %.6f\n", px / d, py / d, pz / d, d }'
}
# translation_distance_mm POS_A POS_B: the distance between the model's origins in the camera frame of two .pos
# poses, mm (the cube's symmetric poses put the camera elsewhere in the model frame, the model at the same place).
translation_distance_mm() {
  paste <(head -n 3 "$1") <(head -n 3 "$2") | awk '{ s += ($1 - $2) ^ 2 } END { printf "%.2f", 1000 * sqrt(s) }'
}
# detector_code MAP: the flash of the detector's objects (tracker/src/detector) in a link map, bytes.
detector_code() {
  local objects
  objects=$(cd "$top/tracker/src/detector" && ls ./*.cpp | sed 's|^\./||; s|$|.obj|' | tr '\n' ' ')
  awk -v by=object -f "$here/flash_and_ram.awk" "$1" |
    awk -v list=" $objects" 'index(list, " " $1 " ") { n += $2 } END { print n + 0 }'
}

narrow_templates_section() {
  local view axis distance low high made count features image=seq/frames/frame0000.pgm
  view=$(first_view seq/first.pos)
  axis=${view% *} distance=${view#* }
  low=$(awk -v d="$distance" -v b="$narrow_band" 'BEGIN { printf "%.4f", d * (1 - b) }')
  high=$(awk -v d="$distance" -v b="$narrow_band" 'BEGIN { printf "%.4f", d * (1 + b) }')
  local range=(--axis "$axis" --cone "$narrow_cone" --distance "$low:$high" --in-plane "$narrow_in_plane")
  made=$("$host_dir/app/edgetrack" templates --model "$model" --camera seq/camera.xml "${range[@]}" \
         --out narrow.templates --cxx narrow.cpp)
  count=$(sed -n 's/^templates: \([0-9]*\) templates.*/\1/p' <<<"$made")
  features=$(sed -n 's/.*distances, \([0-9]*\) features.*/\1/p' <<<"$made")
  arm-none-eabi-g++ -std=c++17 -O2 -mcpu=cortex-m3 -mthumb -mfloat-abi=soft -fno-exceptions -fno-rtti -D_GNU_SOURCE \
    -Wno-psabi -I"$top/tracker/include" -I"$top/ports/real/include" -I"$mcu_dir/ports/real/include" \
    -c narrow.cpp -o narrow.o
  local template_bytes per_template code remaining fit
  template_bytes=$(section narrow.o .rodata)
  per_template=$((template_bytes / count))
  code=$(detector_code "$mcu_dir/app/edgetrack.map")
  remaining=$((262144 - t_flash - code))
  fit=$(( remaining > 0 ? remaining / per_template : 0 ))

  local detect=(detect --model "$model" --camera seq/camera.xml --image "$image" --templates narrow.templates --out)
  EDGETRACK_BOARD_REPORT=1 EDGETRACK_MCU_FIRMWARE=$firmware "$top/toolchains/mcu/edgetrack-mcu.sh" "${detect[@]}" \
    narrow-m3.pos >narrow-m3.txt 2>narrow-m3.board || true
  EDGETRACK_COUNT_TRIPLE=arm-none-eabi "$top/toolchains/qemu/count-insns.sh" --out narrow-m3.count \
    --windows narrow-m3.windows "$firmware" "${detect[@]}" narrow-m3-counted.pos >/dev/null 2>&1 || true
  "$top/toolchains/qemu/count-insns.sh" --out narrow-arm.count --windows narrow-arm.windows \
    "$arm_dir/app/edgetrack" "${detect[@]}" narrow-arm.pos >narrow-arm.txt 2>&1 || true
  local found error insns_m3 insns_arm heap
  found=$(grep -q 'found=1' narrow-m3.txt && echo yes || echo no)
  error="no pose"
  [ -s narrow-m3.pos ] && error="$(translation_distance_mm narrow-m3.pos seq/first.pos) mm"
  insns_m3=$(awk '{ sub("insns=", "", $3); print $3 }' narrow-m3.windows 2>/dev/null | head -n 1)
  insns_arm=$(awk '{ sub("insns=", "", $3); print $3 }' narrow-arm.windows 2>/dev/null | head -n 1)
  heap=$(board_value "heap high-water" narrow-m3.board)
  local directions distances
  distances=$(sed -n 's/.* over \([0-9]*\) distances,.*/\1/p' <<<"$made")
  directions=$((count / narrow_in_plane / distances))
  echo
  echo "### A narrow template set: the detector on the microcontroller"
  echo
  echo "One known view instead of the whole sphere: the direction from the cube towards the camera of the first"
  echo "generated frame (as a board mounted at a known side of the object would know it), a ${narrow_cone}-degree cone"
  echo "about it and one distance band (the first pose's $(awk -v d="$distance" 'BEGIN { printf "%.0f", d * 1000 }') mm, $(awk -v b="$narrow_band" 'BEGIN { printf "%.0f", b * 100 }') % either side), every rotation"
  echo "about the optical axis: \`edgetrack templates ${range[*]} --cxx\`. The source compiled for the Cortex-M3"
  echo "as above; the detector's code is its objects (tracker/src/detector) in the command line firmware's link map;"
  echo "\`edgetrack detect --templates\` on the first generated frame, by the command line firmware on the board"
  echo "(qemu-system-arm) and on the PXA270 (qemu-arm), the detection counted by its markers."
  echo
  echo "| what | measured | budget |"
  echo "|---|---:|---:|"
  echo "| the range: directions, rotations about the optical axis, distances | $directions, $narrow_in_plane, $distances ($low to $high m) | |"
  echo "| templates, features | $count, $features | |"
  echo "| their constant data (\`.rodata\` of the compiled source) | $(kb "$template_bytes") KB: $per_template bytes per template | |"
  echo "| the detector's code in the command line firmware | $(kb "$code") KB | |"
  echo "| found on the first frame (Cortex-M3), its translation against the truth | $found, $error | |"
  echo "| guest instructions of \`Detector::detect\`, Cortex-M3 | ${insns_m3:-not measured} | |"
  echo "| guest instructions of \`Detector::detect\`, PXA270 | ${insns_arm:-not measured} | |"
  echo "| heap high-water of \`detect\` on the board (the templates read into RAM from their file, the model, the frame, the detector's maps) | $(kb "$heap") KB | 192 KB: $(met "$heap" 192) |"
  echo
  echo "What remains of the 256 KB flash budget beside the tracker firmware ($(kb "$t_flash") KB) and the detector's code:"
  if [ "$remaining" -gt 0 ]; then
    echo "$(kb "$remaining") KB, room for $fit templates at $per_template bytes each (this set has $count)."
  else
    echo "nothing: the two are over it by $(kb $((-remaining))) KB, so no template fits until the tracker firmware shrinks."
  fi
  echo "Each KB of flash holds $((1024 / per_template)) templates: this set's views ($directions directions within $narrow_cone degrees of"
  echo "the axis, $distances distances from $low to $high m, $narrow_in_plane rotations each) take $(kb "$template_bytes") KB."
}
narrow_templates_section
