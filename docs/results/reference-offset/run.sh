#!/bin/bash
# The table of README.md here: each scene x offset scale x method, validate's figures as JSON lines.
# Run from the repository root after building: bash docs/results/reference-offset/run.sh > results.jsonl
cd "$(dirname "$0")/../../.."  # the repository root: scenes, build and out/ are read from it
for s in armadillo bunny unseen/bones-multicomponent-spot unseen/cow-spot unseen/coupling-directional-down default; do
  for k in ${SCALES:-1 0.1 0.01 0}; do
    for m in "silhouette|--method silhouette" "entry256|--volume explicit --refine 6 --refine-grid 4 --capture entry --resolution 256" "auto256|--volume explicit --refine 6 --refine-grid 4 --capture auto --resolution 256" "map2048|--method shadowmap --resolution 2048 --capture back"; do
      name=${m%%|*}; args=${m#*|}
      build/apps/shadowvol validate --scene data/scenes/$s.json $args --exact-offset-scale $k --report out/reference-offset --json 2>/dev/null | python3 -c "
import json,sys;d=json.load(sys.stdin);m=d['againstExact']['method'];print(json.dumps({'scene':'$s'.split('/')[-1],'scale':$k,'method':'$name','error':m['errorFraction'],'missed':m['missedShadow'],'false':m['falseShadow'],'exactShadowed':d['pixels']['exactShadowed']}))"
    done
  done
done
