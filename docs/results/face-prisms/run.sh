#!/bin/bash
# The face prisms (--face-prisms, docs/volume.md "Face prisms") on issue 10's 48 closed-mesh goal
# scenes at 256², 4 x 4 and 8 x 8 sub-grid, against the sharp exact reference: error-places' run
# with the flag (results.md), then its cost beside the same volume without it and silhouette
# volumes on three scenes (bench.csv). Fetch the meshes first (docs/results/light-fit/run.sh says
# how), build, run from the repository root: about 10 minutes on 2 cores. EXE, OUT as run.sh's.
# The bias experiment (bias2.md, bias4.md): apply bias-scale.patch, build, run this script's first
# command with SV_BIAS_SCALE=2 (or 4) and another OUT, revert the patch.
set -e
exe=${EXE:-build/apps/shadowvol}
out=${OUT:-out/face-prisms}
EXE=$exe FLAGS=--face-prisms OUT=$out bash docs/results/error-places/run.sh
"$exe" bench --scenes default data/scenes/armadillo.json data/scenes/bunny.json \
  --methods hybrid-refined-grid-entry/explicit,hybrid-refined-grid-prisms-entry/explicit,hybrid-refined-grid8-entry/explicit,hybrid-refined-grid8-prisms-entry/explicit,silhouette \
  --resolutions 256 --repeat 7 --out "$out-bench" > /dev/null
cut -d, -f1,3,11,20,23,27,29 "$out-bench/results.csv"
