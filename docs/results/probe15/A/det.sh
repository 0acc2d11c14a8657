#!/bin/bash
# determinism: run each build config 3 times (2 normal, 1 pinned to core 0), compare md5s
# usage: det.sh TAG SCENE EXT -- build options...
# SV: the shadowvol binary (default: this repository's build), copied to /tmp/probe15/sv
sv=${SV:-$(cd "$(dirname "$0")/../../../.." && pwd)/build/apps/shadowvol}
mkdir -p /tmp/probe15 && cp "$sv" /tmp/probe15/sv
cd /tmp/probe15
tag=$1; scene=$2; ext=$3; shift 4
for i in 1 2; do ./sv build --scene $scene --out det/$tag.$i.$ext "$@" > det/$tag.$i.log 2>&1; echo $? > det/$tag.$i.rc; done
taskset -c 0 ./sv build --scene $scene --out det/$tag.p.$ext "$@" > det/$tag.p.log 2>&1; echo $? > det/$tag.p.rc
h=$(md5sum det/$tag.{1,2,p}.$ext 2>/dev/null | awk '{print $1}' | sort -u | wc -l)
echo "$tag: rc=$(cat det/$tag.{1,2,p}.rc | tr '\n' ,) distinct=$h $(grep -o '[0-9,]* triangles' det/$tag.1.log | head -1)" | tee -a det/summary.txt
