#!/usr/bin/env bash
# Whole-process time, peak memory and the verifier's stages of `tsf gen` with
# its self-check, on the synthetic N x N wave CSV of gen_whole_process.sh.
#   bench/self_check_whole_process.sh [-r RUNS] [-f] TSF [TSF...] -- SIZES...
# Each size is run RUNS times (default 3) with every binary in turn, so that
# binaries compared share the machine's state; -f adds --verify-full (every
# check at any size). Prints one Markdown table row per run.
set -euo pipefail
runs=3
full=""
while getopts "r:f" opt; do
  case $opt in
    r) runs=$OPTARG ;;
    f) full="--verify-full" ;;
    *) exit 2 ;;
  esac
done
shift $((OPTIND - 1))
binaries=()
while [ $# -gt 0 ] && [ "$1" != "--" ]; do binaries+=("$1"); shift; done
[ $# -gt 0 ] && shift
sizes=("${@:-100}")
[ ${#binaries[@]} -gt 0 ] || { echo "usage: $0 [-r RUNS] [-f] TSF [TSF...] -- SIZES..." >&2; exit 2; }
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
echo "| binary | grid | triangles | wall s | user s | sys s | peak MB | verify stages (ms) |"
echo "|---|---|---|---|---|---|---|---|"
for n in "${sizes[@]}"; do
  python3 - "$n" "$work/f$n.csv" <<'PY'
import math, sys
n = int(sys.argv[1])
with open(sys.argv[2], "w") as f:
    for r in range(n):
        f.write(",".join("%.4f" % (math.sin(c * 0.05) * math.cos(r * 0.03) + 1) for c in range(n)) + "\n")
PY
  for ((i = 0; i < runs; i++)); do
    for tsf in "${binaries[@]}"; do
      /usr/bin/time -f "%e %U %S %M" -o "$work/time" "$tsf" gen "$work/f$n.csv" --bins "$n" --cull none $full \
          -o "$work/m.stl" --json > "$work/out.json" 2> /dev/null
      read -r wall user sys kb < "$work/time"
      python3 - "$tsf" "$n" "$wall" "$user" "$sys" "$kb" "$work/out.json" <<'PY'
import json, sys
tsf, n, wall, user, sys_s, kb, out = sys.argv[1:]
j = json.load(open(out))
stages = ", ".join(f"{s['name']} {s['time_ms']:.0f}" for s in j["verify"]["stages"])
print(f"| {tsf} | {n}x{n} | {j['mesh']['triangles']} | {float(wall):.2f} | {float(user):.2f} | {float(sys_s):.2f} | "
      f"{int(kb) / 1024:.0f} | {stages} |")
PY
    done
  done
done
