#!/bin/bash
# Issue 10's 128² goal (at most the 2048² shadow map's error) with the face prisms: the refined
# volume at 128² with --face-prisms and the 4 x 4 and the 8 x 8 sub-grid on the 83 goal scenes,
# against the 2048² maps of docs/results/light-fit/s4.jsonl (refine_goals.py reads each run as
# its --grid8 column, so its lines say "S=8" for both). Fetch the meshes first
# (docs/results/light-fit/run.sh says how), build, run from the repository root (about 8 minutes
# on 2 cores). EXE, OUT (default out/face-prisms-128). goal128-s4.jsonl and goal128-s8.jsonl here
# are the two runs' results with the binary of 4f1ea0e.
set -e
exe=${EXE:-build/apps/shadowvol}
out=${OUT:-out/face-prisms-128}
mkdir -p "$out"
scenes="$(ls data/scenes/{armadillo,bunny,default,fandisk,hemisphere-grazing,lion-head,plate,plate-rotated,tree}.json \
  data/scenes/unseen/*.json docs/results/subgrid-bias/probe-scenes/*.json docs/results/probe10/scenes/*.json \
  docs/results/probe16/scenes/*.json)"
for g in 4 8; do
  python3 scripts/refine_eval.py --exe "$exe" --refine-grid $g --methods "refined auto 128" \
      --validate-args=--face-prisms --out "$out/s$g" $scenes > "$out-s$g.md"
done
closed=$(python3 scripts/closed_scenes.py "$exe" docs/results/light-fit/s4.jsonl $scenes)
for g in 4 8; do
  echo "--refine-grid $g --face-prisms:"
  python3 scripts/refine_goals.py docs/results/light-fit/s4.jsonl --closed "$closed" --grid8 "$out/s$g/results.jsonl" |
    grep "S=8"
done
