#!/usr/bin/env bash
# Whole-process time and peak memory of `tsf gen` on synthetic N x N grid CSVs.
#   bench/gen_whole_process.sh [build/tsf] [sizes...]
# Prints one Markdown table row per size and mode.
set -euo pipefail
tsf="${1:-build/tsf}"
shift || true
sizes=("${@:-100 300 1000}")
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
echo "| grid | bottom | hexagons | triangles | wall s | user s | peak MB | STL MB |"
echo "|---|---|---|---|---|---|---|---|"
for n in ${sizes[@]}; do
  python3 - "$n" "$work/f$n.csv" <<'PY'
import math, sys
n = int(sys.argv[1])
with open(sys.argv[2], "w") as f:
    for r in range(n):
        f.write(",".join("%.4f" % (math.sin(c * 0.05) * math.cos(r * 0.03) + 1) for c in range(n)) + "\n")
PY
  for mode in flat mirror; do
    extra=""; [ "$mode" = mirror ] && extra="--mirror"
    /usr/bin/time -f "%e %U %M" -o "$work/time" "$tsf" gen "$work/f$n.csv" --bins "$n" --cull none $extra \
        -o "$work/m.stl" --json --no-verify > "$work/out.json"
    read -r wall user kb < "$work/time"
    python3 - "$n" "$mode" "$wall" "$user" "$kb" "$work/out.json" "$work/m.stl" <<'PY'
import json, os, sys
n, mode, wall, user, kb, out, stl = sys.argv[1:]
j = json.load(open(out))
cells = j["scene"]["cells"]["kept"]
print(f"| {n}x{n} | {mode} | {cells} | {j['mesh']['triangles']} | {float(wall):.2f} | {float(user):.2f} | "
      f"{int(kb)/1024:.0f} | {os.path.getsize(stl)/1e6:.0f} |")
PY
  done
done
