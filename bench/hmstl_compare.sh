#!/usr/bin/env bash
# tsf against hmstl (github.com/anoved/hmstl, a heightmap image -> STL
# converter on github.com/anoved/libtrix) on the same N x N 8-bit PNG, run
# alternately, whole process: wall time, peak memory, triangles written, and
# the time per cell and per triangle.
#   bench/hmstl_compare.sh [-r RUNS] [-n SIZE] TSF HMSTL_SRC LIBTRIX_SRC
# HMSTL_SRC and LIBTRIX_SRC are folders holding the two projects' sources
# (clones of the public repositories; neither is packaged for Debian). They
# are built here into a temporary folder with the system's cc, -O2; nothing
# of theirs is written into tsf's tree. Without them:
#   git clone https://github.com/anoved/hmstl && git clone https://github.com/anoved/libtrix
# tsf runs as the issue measures it: --cell 0.15 --cull none --no-verify
# --no-key (one pillar per pixel, no self-check, the sidecar and the fsyncs
# kept); a second tsf row keeps the default self-check; a second hmstl row
# syncs its file and folder (coreutils sync) inside the timed command, as
# tsf syncs its outputs. Prints a Markdown table (docs/benchmarks.md, "tsf
# and hmstl").
set -euo pipefail
runs=5
size=1000
while getopts "r:n:" opt; do
  case $opt in
    r) runs=$OPTARG ;;
    n) size=$OPTARG ;;
    *) exit 2 ;;
  esac
done
shift $((OPTIND - 1))
[ $# -eq 3 ] || { echo "usage: $0 [-r RUNS] [-n SIZE] TSF HMSTL_SRC LIBTRIX_SRC" >&2; exit 2; }
tsf="$(realpath "$1")"
hmstl_src="$(realpath "$2")"
libtrix_src="$(realpath "$3")"
for f in "$hmstl_src/hmstl.c" "$hmstl_src/heightmap.c" "$hmstl_src/stb_image.c" "$libtrix_src/libtrix.c"; do
  [ -f "$f" ] || { echo "$0: $f not found" >&2; exit 2; }
done
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

# Build the peer: libtrix as an object, hmstl linked against it.
cc -O2 -w -c "$libtrix_src/libtrix.c" -I "$libtrix_src" -o "$work/libtrix.o"
cc -O2 -w -I "$libtrix_src" -I "$hmstl_src" "$hmstl_src/hmstl.c" "$hmstl_src/heightmap.c" "$hmstl_src/stb_image.c" \
   "$work/libtrix.o" -lm -o "$work/hmstl"

# An N x N 8-bit grey PNG of rolling terrain (zlib, no image library needed).
python3 - "$size" "$work/f.png" <<'PY'
import math, struct, sys, zlib
n, path = int(sys.argv[1]), sys.argv[2]
rows = b"".join(b"\0" + bytes(int(127.5 + 127 * math.sin(c * 0.05) * math.cos(r * 0.03)) for c in range(n))
                for r in range(n))
def chunk(kind, data):
    return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF)
png = b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", n, n, 8, 0, 0, 0, 0))
png += chunk(b"IDAT", zlib.compress(rows, 6)) + chunk(b"IEND", b"")
open(path, "wb").write(png)
PY

measure() {  # measure NAME COMMAND...: appends "name wall kb" to $work/runs
  local name=$1
  shift
  sync
  /usr/bin/time -f "%e %M" -o "$work/time" "$@" > /dev/null 2>&1
  echo "$name $(cat "$work/time")" >> "$work/runs"
}
: > "$work/runs"
for ((i = 0; i < runs; i++)); do
  measure hmstl "$work/hmstl" -i "$work/f.png" -o "$work/h.stl" -z 0.1
  # hmstl writes and never syncs; tsf syncs its files and their folder
  # before renaming them. Synced the same way, in the timed command:
  measure hmstl_synced sh -c '"$1" -i "$2" -o "$3" -z 0.1 && sync "$3" "$(dirname "$3")"' sh \
      "$work/hmstl" "$work/f.png" "$work/hs.stl"
  measure tsf "$tsf" gen "$work/f.png" --cell 0.15 --cull none --no-verify --keep-unprintable --no-key -o "$work/t.stl"
  measure tsf_checked "$tsf" gen "$work/f.png" --cell 0.15 --cull none --keep-unprintable --no-key -o "$work/c.stl"
done

python3 - "$work" "$size" "$runs" <<'PY'
import os, statistics, struct, sys
work, n, runs = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])
rows = {}
for line in open(f"{work}/runs"):
    name, wall, kb = line.split()
    rows.setdefault(name, []).append((float(wall), int(kb)))
def triangles(path):
    with open(path, "rb") as f:
        f.seek(80)
        return struct.unpack("<I", f.read(4))[0]
files = {"hmstl": "h.stl", "hmstl_synced": "hs.stl", "tsf": "t.stl", "tsf_checked": "c.stl"}
what = {"hmstl": "hmstl -z 0.1", "hmstl_synced": "hmstl -z 0.1, then its file and folder synced (as tsf does)",
        "tsf": "tsf gen --cell 0.15 --cull none --no-verify",
        "tsf_checked": "tsf gen --cell 0.15 --cull none (default self-check)"}
cells = n * n
base = None
print(f"| {n} x {n} PNG | triangles | wall s (median of {runs}, range) | peak MB | ns per cell | ns per triangle | per triangle vs hmstl | vs hmstl synced |")
print("|---|---|---|---|---|---|---|---|")
base_synced = None
for name in ("hmstl", "hmstl_synced", "tsf", "tsf_checked"):
    walls = sorted(w for w, _ in rows[name])
    med = statistics.median(walls)
    peak = max(k for _, k in rows[name]) / 1024
    tri = triangles(f"{work}/{files[name]}")
    per_tri = med / tri * 1e9
    if base is None:
        base = per_tri
    if name == "hmstl_synced":
        base_synced = per_tri
    synced = f"{per_tri / base_synced:.2f}x" if base_synced else ""
    print(f"| {what[name]} | {tri} | {med:.2f} ({walls[0]:.2f}-{walls[-1]:.2f}) | {peak:.0f} | "
          f"{med / cells * 1e9:.0f} | {per_tri:.0f} | {per_tri / base:.2f}x | {synced} |")
PY
