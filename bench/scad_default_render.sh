#!/usr/bin/env bash
# Render time and peak memory of the default generated .scad (the orientation
# tab joined into the terrain's one polyhedron) against the same field with
# --marks-on data (the pillars and the marks in the data, no tab) and
# against the tab as it was written before (the closed tab unioned with the
# terrain polyhedron: the CSG strategy's file with its terrain call made
# tsf_terrain_polyhedron(), which is that file to the letter), on
# OpenSCAD 2021.01 (the desktop `openscad`, run directly, as a user would)
# and the 2025 WebAssembly engine (`tsf render --engine wasm`), and whether
# each render is the direct mesh (`tsf verify --reference`).
#   bench/scad_default_render.sh [build/tsf] [cases...]
# cases: 100 (a 100 x 100 grid CSV, the default cell) and 300 (300 x 300 at
# --cell 0.5: one pillar per value); default both. Prints one Markdown table
# row per case, file and engine. Wall clock and peak resident memory are
# /usr/bin/time -v's (for the wasm engine: tsf render and the node process).
# SKIP_WASM=1 renders on OpenSCAD 2021 only. A render that is killed or runs
# out of memory shows as "render failed".
set -euo pipefail
tsf="$(realpath "${1:-build/tsf}")"
shift || true
cases=("${@:-100 300}")
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
echo "| field | file | engine | wall s | user s | peak MB | triangles | tsf verify --reference |"
echo "|---|---|---|---|---|---|---|---|"
for n in ${cases[@]}; do
  python3 - "$n" "$work/f$n.csv" <<'PY'
import math, sys
n = int(sys.argv[1])
with open(sys.argv[2], "w") as f:
    for r in range(n):
        f.write(",".join("%.4f" % (50 + 20 * math.sin(c * 0.07) * math.cos(r * 0.05) + 3 * math.sin(c * r * 0.001))
                         for c in range(n)) + "\n")
PY
  cell=(); [ "$n" = 300 ] && cell=(--cell 0.5)
  "$tsf" gen "$work/f$n.csv" "${cell[@]}" -o "$work/default.stl" --scad "$work/default.scad" --no-verify --json > "$work/gen.json"
  hexagons=$(python3 -c "import json,sys; print(json.load(open(sys.argv[1]))['scene']['cells']['kept'])" "$work/gen.json")
  "$tsf" gen "$work/f$n.csv" "${cell[@]}" --marks-on data -o "$work/data.stl" --scad "$work/data.scad" --no-verify > /dev/null
  "$tsf" gen "$work/f$n.csv" "${cell[@]}" --scad-strategy csg --scad "$work/union.scad" --no-verify -o "$work/union.stl" > /dev/null
  sed -i 's/^tsf_with_tab(orientation_tab, show_orientation_tab) tsf_terrain_csg(model);$/tsf_with_tab(orientation_tab, show_orientation_tab) tsf_terrain_polyhedron(model);/' "$work/union.scad"
  grep -q '^tsf_with_tab(.*tsf_terrain_polyhedron(model);$' "$work/union.scad"
  # The union at 300 x 300 ran out of 14 GB after 5 minutes on OpenSCAD 2021: not run by default.
  files=(default data union); [ "$n" = 300 ] && [ "${UNION_300:-}" != 1 ] && files=(default data)
  for file in "${files[@]}"; do
    engines=(openscad wasm); [ "${SKIP_WASM:-}" = 1 ] && engines=(openscad)
    for engine in "${engines[@]}"; do
      out="$work/$file.$engine.stl"
      if [ "$engine" = openscad ]; then
        cmd=(openscad -o "$out" --export-format binstl "$work/$file.scad")
      else
        cmd=("$tsf" render --engine wasm --no-check -q "$work/$file.scad" -o "$out")
      fi
      if /usr/bin/time -v -o "$work/time" "${cmd[@]}" > "$work/log" 2>&1; then
        verdict=$("$tsf" verify "$out" --reference "$work/$file.stl" --no-printability > "$work/verify" 2>&1 && echo pass || echo FAIL)
        tris=$(python3 -c "import struct,sys; d=open(sys.argv[1],'rb').read(84); print(struct.unpack('<I', d[80:84])[0])" "$out")
      else
        verdict="render failed"; tris="-"
      fi
      python3 - "$n" "$file" "$engine" "$work/time" "$tris" "$verdict" "$hexagons" <<'PY'
import re, sys
n, file, engine, tfile, tris, verdict, hexagons = sys.argv[1:]
t = open(tfile).read()
wall = re.search(r"Elapsed \(wall clock\) time.*: (?:(\d+):)?(\d+):([\d.]+)", t)
secs = (int(wall.group(1) or 0) * 3600 + int(wall.group(2)) * 60 + float(wall.group(3))) if wall else float("nan")
kb = int(re.search(r"Maximum resident set size \(kbytes\): (\d+)", t).group(1))
user = float(re.search(r"User time \(seconds\): ([\d.]+)", t).group(1))
size = ("100 x 100" if n == "100" else "300 x 300, --cell 0.5") + f" ({int(hexagons):,} hexagons)".replace(",", " ")
what = {"default": "default: tab joined", "data": "--marks-on data (no tab)", "union": "tab unioned (before)"}[file]
print(f"| {size} | {what} | {engine} | {secs:.2f} | {user:.2f} | {kb / 1024:.0f} | {tris} | {verdict} |")
PY
    done
  done
done
