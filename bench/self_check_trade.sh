#!/usr/bin/env bash
# The self-check's trade, measured: for each level of tsf gen's self-check
# (none: --no-verify; default; full: --verify-full) the whole process's wall
# time and peak memory on the N x N wave field of
# self_check_whole_process.sh, and which planted defects each level catches.
#   bench/self_check_trade.sh [-r RUNS] TSF [SIZES...]
# Prints two Markdown tables (docs/verifier.md, "What each level costs and
# catches"). The defects are planted in the binary STL of a 60 x 60 model
# and checked by tsf verify with the scene sidecar: --quick is what the
# default level keeps above 3 million triangles, no flag what it runs
# below (and --verify-full at every size). The models are written with
# --keep-unprintable: cells of 0.15 mm (1000 x 1000 on a 150 mm bed) have
# walls thinner than a nozzle, which the full check refuses.
set -euo pipefail
runs=1
while getopts "r:" opt; do
  case $opt in
    r) runs=$OPTARG ;;
    *) exit 2 ;;
  esac
done
shift $((OPTIND - 1))
[ $# -ge 1 ] || { echo "usage: $0 [-r RUNS] TSF [SIZES...]" >&2; exit 2; }
tsf="$1"
shift
sizes=("${@:-100 300}")
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

wave() {  # wave N FILE
  python3 - "$1" "$2" <<'PY'
import math, sys
n = int(sys.argv[1])
with open(sys.argv[2], "w") as f:
    for r in range(n):
        f.write(",".join("%.4f" % (math.sin(c * 0.05) * math.cos(r * 0.03) + 1) for c in range(n)) + "\n")
PY
}

echo "| grid | triangles | level | wall s | peak MB | checks run (of the self-check's) |"
echo "|---|---|---|---|---|---|"
for n in ${sizes[@]}; do
  wave "$n" "$work/f$n.csv"
  for level in none default full; do
    case $level in
      none) flag="--no-verify" ;;
      default) flag="" ;;
      full) flag="--verify-full" ;;
    esac
    for ((i = 0; i < runs; i++)); do
      /usr/bin/time -f "%e %M" -o "$work/time" "$tsf" gen "$work/f$n.csv" --bins "$n" --cull none $flag --keep-unprintable \
          -o "$work/m.stl" --no-key --json > "$work/out.json" 2> /dev/null
      read -r wall kb < "$work/time"
      python3 - "$work/out.json" "$n" "$level" "$wall" "$kb" <<'PY'
import json, sys
d = json.load(open(sys.argv[1]))
n, level, wall, kb = sys.argv[2], sys.argv[3], float(sys.argv[4]), int(sys.argv[5])
checks = (d.get("verify") or {}).get("checks", [])
ran = [c["id"] for c in checks if c["status"] != "skipped"]
left = [c["id"] for c in checks if c["status"] == "skipped" and c["id"] != "fits_bed"]
what = f"{len(ran)}" + (f", not: {', '.join(left)}" if left else "")
print(f"| {n} x {n} | {d['mesh']['triangles']} | {level} | {wall:.2f} | {kb // 1024} | {what if checks else 'none'} |")
PY
    done
  done
done

# Planted defects in a 60 x 60 model (3 mm cells), each checked at the two
# verifying levels. The sidecar's record of the model file is dropped so
# that tsf verify takes the edited file.
wave 60 "$work/d.csv"
"$tsf" gen "$work/d.csv" --bins 60 --cull none --cell 3 -o "$work/d.stl" --no-key > /dev/null 2>&1
python3 - "$work" "$tsf" <<'PY'
import json, os, struct, subprocess, sys
work, tsf = sys.argv[1], sys.argv[2]
scene = json.load(open(f"{work}/d.stl.scene.json"))
scene.pop("model", None)
json.dump(scene, open(f"{work}/d.json", "w"))
data = open(f"{work}/d.stl", "rb").read()
count = struct.unpack("<I", data[80:84])[0]
tris = [list(struct.unpack("<12f", data[84 + 50 * t:84 + 50 * t + 48])) for t in range(count)]

def normal_z(t):
    (ax, ay, az), (bx, by, bz), (cx, cy, cz) = t[3:6], t[6:9], t[9:12]
    return (bx - ax) * (cy - ay) - (by - ay) * (cx - ax)

def top_z():
    return max(max(t[5], t[8], t[11]) for t in tris)

def write(name, ts):
    with open(f"{work}/{name}.stl", "wb") as f:
        f.write(b"\0" * 80 + struct.pack("<I", len(ts)))
        for t in ts:
            f.write(struct.pack("<12f", *t) + b"\0\0")

def move_vertex(ts, p, q):
    """Every corner at p (x, y, z) moved to q: the mesh stays closed."""
    out = []
    for t in ts:
        t = list(t)
        for k in (3, 6, 9):
            if tuple(t[k:k + 3]) == p:
                t[k:k + 3] = q
        out.append(t)
    return out

# A top corner near the middle of the model, and a bottom corner.
mid_x = sum(t[3] for t in tris) / len(tris)
mid_y = sum(t[4] for t in tris) / len(tris)
tops = [tuple(t[k:k + 3]) for t in tris if normal_z(t) > 0 for k in (3, 6, 9)]
top = min(tops, key=lambda p: (p[0] - mid_x) ** 2 + (p[1] - mid_y) ** 2)
bottoms = [tuple(t[k:k + 3]) for t in tris if normal_z(t) < 0 for k in (3, 6, 9)]
bottom = min(bottoms, key=lambda p: (p[0] - mid_x) ** 2 + (p[1] - mid_y) ** 2 + p[2])
defects = {
    "a top corner pushed down 1 mm": move_vertex(tris, top, (top[0], top[1], top[2] - 1.0)),
    "a bottom corner pushed up through the top": move_vertex(tris, bottom, (bottom[0], bottom[1], top_z() + 2.0)),
    "a top corner moved 0.05 mm sideways": move_vertex(tris, top, (top[0] + 0.05, top[1], top[2])),
    "one triangle left out": tris[:len(tris) // 2] + tris[len(tris) // 2 + 1:],
    "one triangle turned over": tris[:7] + [tris[7][:3] + tris[7][3:6] + tris[7][9:12] + tris[7][6:9]] + tris[8:],
    "the whole model 0.01 mm higher": [t[:3] + [v + (0.01 if k % 3 == 2 else 0) for k, v in enumerate(t[3:])] for t in tris],
    "a small closed box inside a pillar": tris,  # filled in below
}
# A 0.2 mm tetrahedron inside the solid under the top corner: a second piece.
x, y, z = top[0] + 0.3, top[1] - 0.3, 1.0
a, b, c, d = (x, y, z), (x + 0.2, y, z), (x, y + 0.2, z), (x, y, z + 0.2)
for p, q, r in ((a, c, b), (a, b, d), (b, c, d), (c, a, d)):
    defects["a small closed box inside a pillar"] = defects["a small closed box inside a pillar"] + [[0, 0, 0, *p, *q, *r]]

print()
print("| planted defect | default below 3 M triangles, and --verify-full | default above 3 M triangles (tsf verify --quick) |")
print("|---|---|---|")
for k, (what, ts) in enumerate(defects.items()):
    write(f"p{k}", ts)
    cells = []
    for flags in ([], ["--quick"]):
        r = subprocess.run([tsf, "verify", f"{work}/p{k}.stl", "--scene", f"{work}/d.json", "--json", *flags],
                           capture_output=True, text=True)
        try:
            rep = json.loads(r.stdout)
            failed = [c["id"] for c in rep["checks"] if c["status"] == "fail"]
        except ValueError:
            failed = ["refused: " + (r.stderr.strip().splitlines() or ["?"])[-1]]
        cells.append("caught: " + ", ".join(failed) if failed else "**missed**")
    print(f"| {what} | {cells[0]} | {cells[1]} |")
PY
