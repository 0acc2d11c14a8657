#!/bin/bash
# A complete report folder from run 1; run 2 into the same folder killed with SIGKILL part-way:
# the old report is gone and the folder holds a partial new set (PNGs/overlay.svg without report.json).
cd /work/main; SV=${SV:-/tmp/probe22/sv}; V=$(mktemp -d)/rep
$SV -q validate --resolution 512 --size 1600x1200 --report $V >/dev/null 2>&1; echo "run1 rc=$? $(ls $V | tr '\n' ' ')"
for t in 1.0 1.6 2.0 2.2 2.4 2.6 2.8; do
  $SV -q validate --resolution 512 --size 1600x1200 --scene data/scenes/plate.json --report $V >/dev/null 2>&1 & p=$!
  sleep $t; kill -9 $p; wait $p 2>/dev/null; echo "killed at $t s: $(ls -A $V | tr '\n' ' ')"
done
