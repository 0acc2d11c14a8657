#!/bin/bash
# How much of a one-pixel difference is the frame's sampling (README.md here): issue 10's 48
# closed-mesh goal scenes at 256², each rendered in five frames with the camera moved by a fraction
# of a pixel (jitter.py: the light, its depth map and the volume stay as they are), the silhouette
# volume and the refined volume (the 4 x 4 sub-grid with --face-prisms, as docs/results/face-prisms)
# validated against the sharp exact reference in every frame. Fetch the meshes first
# (docs/results/light-fit/run.sh says how), build, run from the repository root: about 6 minutes on
# 2 cores. EXE (default build/apps/shadowvol), OUT (default out/tie-noise), FLAGS (the refined
# volume's options). A rerun with the same OUT reuses the reports already there.
set -e
exe=${EXE:-build/apps/shadowvol}
out=${OUT:-out/tie-noise}
flags=${FLAGS:---volume explicit --refine 6 --refine-grid 4 --resolution 256 --face-prisms}
scenes="$(ls data/scenes/{armadillo,bunny,default,fandisk,hemisphere-grazing,lion-head,plate,plate-rotated,tree}.json \
  data/scenes/unseen/*.json docs/results/subgrid-bias/probe-scenes/*.json docs/results/probe10/scenes/*.json \
  docs/results/probe16/scenes/*.json)"
python3 "$(dirname "$0")/frames.py" "$exe" "$out" "$flags" $scenes
