#!/bin/bash
# Issue 15's cost goal on the default scene at 128^2: the refined GPU frame over the unrefined GPU
# frame, measured in N alternating pairs of `shadowvol render --frames 51` (the median frame of
# each), because one bench cell on a shared machine varies by 20-30 %. Prints both medians, the
# median ratio and every pair's ratio.
# Usage: bash scripts/refined_gpu_ratio.sh [N pairs, default 15] [build dir, or the shadowvol executable]
#            [the refined frame's options, default "--refine 6" (the GPU's rays, the sweep's K); the walk:
#             "--refine 4 --crossings gpu-walk", as measured before 2026-12-04 with "--refine 4"]
set -eu
N=${1:-15}
B=$(realpath "${2:-build}")  # given from the caller's folder
REFINED=${3:---refine 6}
SV=$B/apps/shadowvol
[ -f "$B" ] && SV=$B
root=$(cd "$(dirname "$0")/.." && pwd)  # the repository: the scenes are read from it
cd "$root"
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
frame() { "$SV" render --scene data/scenes/default.json --resolution 128 --frames 51 "$@" \
            --out "$out/r.png" 2>&1 | grep -o 'frame [0-9.]* ms' | grep -o '[0-9.]*'; }
for k in $(seq 1 "$N"); do
  # shellcheck disable=SC2086  # the options split into words
  echo "$(frame) $(frame $REFINED)"
done | python3 -c "
import sys, statistics
p = [tuple(map(float, l.split())) for l in sys.stdin if l.strip()]
print('%d pairs: unrefined median %.2f ms, refined median %.2f ms, ratio median %.2f; ratios %s' % (
  len(p), statistics.median(a for a, b in p), statistics.median(b for a, b in p),
  statistics.median(b / a for a, b in p), ' '.join('%.2f' % (b / a) for a, b in p)))"
