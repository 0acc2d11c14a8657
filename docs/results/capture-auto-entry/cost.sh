#!/bin/bash
# Frame time of the default render (the GPU volume, no refinement) with back and with entry capture,
# interleaved: ROUNDS rounds of `render --frames 30` per scene, resolution and capture; prints the
# median over rounds of frameMs (each run's median frame) and entry over back.
# Usage: bash docs/results/capture-auto-entry/cost.sh ROUNDS "RES..." SCENE.json...
set -euo pipefail
rounds=$1 res=$2
sv=$(cd "$(dirname "$0")/../../.." && pwd)/build/apps/shadowvol  # the scenes stay paths from the caller's folder
shift 2
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
for r in $(seq 1 "$rounds"); do
  for s in "$@"; do
    for n in $res; do
      for c in back entry; do
        "$sv" render --scene "$s" --resolution "$n" --capture "$c" --frames 30 --json \
          --out "$out/x.png" 2>/dev/null | python3 -c "
import json,sys; d=json.load(sys.stdin); print('$s', $n, '$c', d['frameMs'])" >> "$out/times.txt"
      done
    done
  done
done
python3 - "$out/times.txt" <<'PY'
import statistics, sys, os
rows = {}
for line in open(sys.argv[1]):
    s, n, c, ms = line.split()
    rows.setdefault((os.path.basename(s)[:-5], int(n)), {}).setdefault(c, []).append(float(ms))
print("| scene | N | back frame ms | entry frame ms | entry / back |")
print("|---|---:|---:|---:|---:|")
for (s, n), v in sorted(rows.items()):
    b, e = statistics.median(v["back"]), statistics.median(v["entry"])
    print("| %s | %d | %.2f | %.2f | %.2fx |" % (s, n, b, e, e / b))
PY
