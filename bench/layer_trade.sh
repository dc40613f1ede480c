#!/usr/bin/env bash
# The layer trade (docs/printing.md): for each layer height, what a print
# costs (PrusaSlicer's time and filament, through `tsf print-check`) against
# what it can show (how many value levels the heights can take, how many the
# data keeps apart, and how far a printed height is from its value).
#
#   bench/layer_trade.sh [build/tsf] [layer heights, mm...]
#
# Default: the bundled airports example as the README's first command makes it
# (40 columns, flat), layers 0.1 0.15 0.2 0.25 0.3. Prints one Markdown table
# row per layer height. Needs python3 (JSON) and prusa-slicer.
#
# The read-back error is the snapping of heights to whole layers: each
# pillar's height above the floor is compared with the same model made at a
# 0.001 mm height grid (exact to within 0.0005 mm), in mm and in value units. The verifier reads
# the printed model back against its own (snapped) Scene, so that difference
# is zero by construction and not what a reader loses.
set -euo pipefail
tsf="${1:-build/tsf}"
shift || true
layers=("${@:-0.1 0.15 0.2 0.25 0.3}")
input=examples/airports-europe.csv
gen_args=(--points x=lon,y=lat --bins 40 --no-verify)
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

"$tsf" gen "$input" "${gen_args[@]}" --snap 0.001 -o "$work/exact.stl" > /dev/null

echo "| layer mm | layers | print time | filament cm3 | filament g | levels in the height range | data levels printed / exact | read-back error max (mean), mm | max error, value units |"
echo "|---|---|---|---|---|---|---|---|---|"
for layer in ${layers[@]}; do
  "$tsf" gen "$input" "${gen_args[@]}" --layer "$layer" -o "$work/l.stl" > /dev/null
  "$tsf" print-check "$work/l.stl" --layer "$layer" --json > "$work/check.json"
  python3 - "$layer" "$work/exact.stl.scene.json" "$work/l.stl.scene.json" "$work/check.json" <<'PY'
import json, sys
layer = float(sys.argv[1])
exact, snapped, check = (json.load(open(p)) for p in sys.argv[2:5])

def data_tops(scene):
    """Height (mm) above the floor of every cell that shows a value, by (row, col):
    what the value maps to (the floor snaps with the tops, so it is taken out)."""
    unit = scene["z_snap_mm"]
    return {(c["row"], c["col"]): (c["top"] - scene["floor_units"]) * unit
            for c in scene["cells"]
            if c.get("value") is not None and not c.get("shape", {}).get("structural", False)}

e, s = data_tops(exact), data_tops(snapped)
errors = [abs(s[k] - e[k]) for k in e]
m = snapped["mapping"]
value_per_mm = (m["value_max"] - m["baseline"]) / m["max_height_mm"]
levels = int(m["max_height_mm"] / layer + 1e-9) + 1
distinct = lambda tops: len({round(t, 6) for t in tops.values()})
hours, rest = divmod(int(check["print_time_s"]), 3600)
print(f"| {layer:g} | {check['layers']} | {hours} h {rest // 60:02d} min | {check['filament_cm3']:.1f} "
      f"| {check['filament_g']:.1f} | {levels} | {distinct(s)} / {distinct(e)} "
      f"| {max(errors):.3f} ({sum(errors) / len(errors):.3f}) | {max(errors) * value_per_mm:.3f} |")
PY
done
