#!/bin/bash
# Issue 10's accuracy goals against the sharp exact reference (README "Silhouette refinement").
# Run from the repository root after building, scripts/fetch_unseen_meshes.sh, and fetching the
# ninth probe's meshes to /tmp/probe9 (docs/results/subgrid-bias/README.md says how); about 10
# minutes on a 2-core machine. Writes out/sharp-reference.md (refine_eval's table) and prints the goals.
set -e
out=${OUT:-out/sharp-reference}
mkdir -p "$out"
python3 scripts/refine_eval.py --exe build/apps/shadowvol --refine-grid 4 \
    --methods "shadowmap auto 2048,shadowmap entry 2048,refined auto 128,refined auto 256,refined entry 128,refined entry 256,silhouette" \
    --out "$out" \
    data/scenes/{armadillo,bunny,default,fandisk,hemisphere-grazing,lion-head,plate,plate-rotated,tree}.json \
    data/scenes/unseen/*.json docs/results/subgrid-bias/probe-scenes/*.json > "$out.md"
closed=armadillo,blobby-shuffled-orientation-spot,bones-multicomponent-spot,bunny,coupling-directional-down
closed=$closed,cow-spot,default,dino-directional,diplodocus-grazing,duo-ellipsoid-over-cow-spot
closed=$closed,ellipsoid-float-directional-down,fandisk,hemisphere-grazing,homer-spot,knot-grazing
closed=$closed,pinion-spot-steep,plate,plate-rotated,tree,triceratops-spot-low,trio-directional,turbine-spot
python3 scripts/refine_goals.py "$out/results.jsonl" --closed $closed
