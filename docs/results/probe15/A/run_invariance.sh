#!/bin/bash
# validate every scene variant not yet validated; one process at a time
# SV: the shadowvol binary (default: this repository's build), copied to /tmp/probe15/sv
sv=${SV:-$(cd "$(dirname "$0")/../../../.." && pwd)/build/apps/shadowvol}
mkdir -p /tmp/probe15 && cp "$sv" /tmp/probe15/sv
cd /tmp/probe15
for f in scenes/*.json; do n=$(basename $f .json)
  [ -f rep/$n.out ] && continue
  /usr/bin/time -f "%e s" -o rep/$n.time ./sv validate --scene $f --volume explicit --refine 6 --resolution 128 --size 320x240 --report rep/$n --json > rep/$n.out 2> rep/$n.err
  echo "$n rc=$?" >> rep/rcs.txt
done
