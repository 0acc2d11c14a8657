#!/bin/bash
# The sub-grid's adaptive choice with the back faces behind its samples (exit-choice.patch, not
# landed; README.md here). Builds the patched shadowvol beside the current one (the patch is applied,
# built and reverted), then compares both: refine_eval on the 48 scenes of
# docs/results/sharp-reference/run.sh at 128² and 256² with --refine-grid 4 and --capture auto
# (compare.py: wrong pixels per run that changed, totals, the 128² goal), the 1.5x goal at 256²
# (scripts/refine_goals.py), and the cost (scripts/ab_bench.sh with entry capture, then the frame
# against hybrid-perfect/explicit on the default scene). Run from the repository root with a clean
# tree, after building and fetching what docs/results/sharp-reference/run.sh needs; about 20 minutes.
# The patch was made on bb5275d and does not apply to later trees (a seventeenth probe's finding):
# run this in a checkout of it (git worktree add /tmp/exit-choice bb5275d, build there).
set -e
here=docs/results/exit-choice
out=${OUT:-out/exit-choice}
if ! git apply --check "$here/exit-choice.patch" 2> /dev/null; then
  echo "exit-choice.patch does not apply to this tree: run this script in a checkout of bb5275d" >&2
  exit 2
fi
mkdir -p "$out"
cmake --build build --target shadowvol > /dev/null
cp build/apps/shadowvol "$out/shadowvol-base"
git apply "$here/exit-choice.patch"
trap "git apply -R '$here/exit-choice.patch'; cmake --build build --target shadowvol > /dev/null" EXIT
cmake --build build --target shadowvol > /dev/null
cp build/apps/shadowvol "$out/shadowvol-exits"
git apply -R "$here/exit-choice.patch"
trap - EXIT
cmake --build build --target shadowvol > /dev/null

scenes="data/scenes/armadillo.json data/scenes/bunny.json data/scenes/default.json data/scenes/fandisk.json
        data/scenes/hemisphere-grazing.json data/scenes/lion-head.json data/scenes/plate.json
        data/scenes/plate-rotated.json data/scenes/tree.json $(ls data/scenes/unseen/*.json docs/results/subgrid-bias/probe-scenes/*.json)"
for v in base exits; do
  python3 scripts/refine_eval.py --exe "$out/shadowvol-$v" --refine-grid 4 \
      --methods "refined auto 128,refined auto 256" --out "$out/$v" $scenes > "$out/$v.md"
done
echo "## Wrong pixels (missed/false) where they changed, base -> exits"
python3 "$here/compare.py" "$out/base/results.jsonl" "$out/exits/results.jsonl"

closed=armadillo,blobby-shuffled-orientation-spot,bones-multicomponent-spot,bunny,coupling-directional-down
closed=$closed,cow-spot,default,dino-directional,diplodocus-grazing,duo-ellipsoid-over-cow-spot
closed=$closed,ellipsoid-float-directional-down,fandisk,hemisphere-grazing,homer-spot,knot-grazing
closed=$closed,pinion-spot-steep,plate,plate-rotated,tree,triceratops-spot-low,trio-directional,turbine-spot
for v in base exits; do
  echo "## Goals, $v"
  grep -E '"(silhouette|shadowmap auto 2048)"' docs/results/sharp-reference/results.jsonl > "$out/$v-goals.jsonl"
  cat "$out/$v/results.jsonl" >> "$out/$v-goals.jsonl"
  python3 scripts/refine_goals.py "$out/$v-goals.jsonl" --closed "$closed" | tail -3
done

echo "## Cost, entry capture on the 4 x 4 sub-grid (B = exits)"
bash scripts/ab_bench.sh "$out/shadowvol-base" "$out/shadowvol-exits" hybrid-refined-grid-entry/explicit 5 "128 256" \
    data/scenes/default.json data/scenes/bunny.json data/scenes/armadillo.json
echo "## Frame over hybrid-perfect/explicit's, default scene, 256², five rounds"
for r in 1 2 3 4 5; do
  for v in base exits; do
    rm -rf "$out/ratio"
    "$out/shadowvol-$v" bench --scenes data/scenes/default.json --methods hybrid-perfect/explicit \
        hybrid-refined/explicit hybrid-refined-grid-entry/explicit --resolutions 256 --repeat 20 --warmup 3 \
        --out "$out/ratio" > /dev/null 2>&1
    python3 -c "
import csv; f = {r['method']: float(r['frame_ms']) for r in csv.DictReader(open('$out/ratio/results.csv'))}
b = f['hybrid-perfect/explicit']
print('$v', 'plain refinement %.2f' % (f['hybrid-refined/explicit'] / b), 'sub-grid entry %.2f' % (f['hybrid-refined-grid-entry/explicit'] / b))"
  done
done
