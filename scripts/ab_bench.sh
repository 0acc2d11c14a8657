#!/bin/bash
# Interleaved A/B frame times of one bench method with two shadowvol binaries (README "Sub-grid
# bias"): ROUNDS rounds, each running A then B on every scene at each resolution; prints the median
# over rounds of each binary's frame_ms and build_ms per scene and resolution, and B's frame over A's.
# Usage: bash scripts/ab_bench.sh EXE_A EXE_B METHOD ROUNDS "RES..." SCENE.json...
set -euo pipefail
a=$1 b=$2 method=$3 rounds=$4 res=$5
shift 5
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
for r in $(seq 1 "$rounds"); do
  for tag in A B; do
    exe=$a; [ "$tag" = B ] && exe=$b
    "$exe" bench --scenes "$@" --methods "$method" --resolutions $res --repeat 20 --warmup 3 \
      --out "$out/$tag-$r" > /dev/null 2>&1
  done
done
/usr/bin/env python3 - "$out" "$rounds" <<'PY'
import csv, statistics, sys
out, rounds = sys.argv[1], int(sys.argv[2])
rows = {}
for tag in "AB":
    for r in range(1, rounds + 1):
        for row in csv.DictReader(open(f"{out}/{tag}-{r}/results.csv")):
            k = (row["scene"], int(row["resolution"]))
            rows.setdefault(k, {}).setdefault(tag, []).append((float(row["frame_ms"]), float(row["build_ms"] or 0)))
print("| scene | N | A frame ms | B frame ms | B / A | A build ms | B build ms |")
print("|---|---:|---:|---:|---:|---:|---:|")
for (scene, n), v in sorted(rows.items()):
    fa = statistics.median(x[0] for x in v["A"]); fb = statistics.median(x[0] for x in v["B"])
    ba = statistics.median(x[1] for x in v["A"]); bb = statistics.median(x[1] for x in v["B"])
    print(f"| {scene} | {n} | {fa:.2f} | {fb:.2f} | {fb / fa:.2f} | {ba:.2f} | {bb:.2f} |")
PY
