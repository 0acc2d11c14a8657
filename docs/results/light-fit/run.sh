#!/bin/bash
# Issue 10's accuracy goals on every goal scene (the 67 of README "Silhouette refinement": the 9
# shipped, 25 unseen, the ninth probe's 14 and the tenth's 19) and the sixteenth probe's 16, with
# the light planes fitted to the objects' boxes (README "Scene files"). Fetch the meshes first
# (docs/results/probe10/README.md and docs/results/probe16/README.md say how), build, then run from
# the repository root (about 16 minutes on a 2-core machine). EXE (default build/apps/shadowvol),
# OUT (default out/light-fit). Writes $OUT/s4 (2048² maps auto and front, refined 128² and 256²
# with the 4 x 4 sub-grid, silhouette), $OUT/s8 (refined 128² with the 8 x 8 sub-grid) and prints
# the goals; a rerun with the same OUT skips the runs already there.
set -e
exe=${EXE:-build/apps/shadowvol}
out=${OUT:-out/light-fit}
mkdir -p "$out"
scenes="$(ls data/scenes/{armadillo,bunny,default,fandisk,hemisphere-grazing,lion-head,plate,plate-rotated,tree}.json \
  data/scenes/unseen/*.json docs/results/subgrid-bias/probe-scenes/*.json docs/results/probe10/scenes/*.json \
  docs/results/probe16/scenes/*.json)"
python3 scripts/refine_eval.py --exe "$exe" --refine-grid 4 \
    --methods "shadowmap auto 2048,shadowmap front 2048,refined auto 128,refined auto 256,silhouette" \
    --out "$out/s4" $scenes > "$out/s4.md"
python3 scripts/refine_eval.py --exe "$exe" --refine-grid 8 --methods "refined auto 128" --out "$out/s8" $scenes > "$out/s8.md"
closed=$(python3 scripts/closed_scenes.py "$exe" "$out/s4/results.jsonl" $scenes)
echo "closed (silhouette volumes apply): $closed"
python3 scripts/refine_goals.py "$out/s4/results.jsonl" --closed "$closed" --grid8 "$out/s8/results.jsonl"
