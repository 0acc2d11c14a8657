#!/bin/bash
# --no-flatten: the volume holds coincident vertex pairs joined by a duplicated edge that build does not count as
# split vertices (prints "0 split vertices") and does not warn about for STL/glTF; read welded, the file is non-manifold.
cd /work/main; SV=${SV:-/tmp/probe22/sv}; D=$(mktemp -d)
$SV build --scene data/scenes/unseen/knot-grazing.json --resolution 80 --no-flatten --out $D/k.ply | grep 'split vertices'
$SV -q build --scene data/scenes/unseen/knot-grazing.json --resolution 80 --no-flatten --out $D/k.stl; echo "stl rc=$?"
$SV -q build --scene data/scenes/unseen/knot-grazing.json --resolution 80 --no-flatten --out $D/k.glb
$SV -q build --scene data/scenes/armadillo.json --resolution 64 --no-flatten --out $D/a.stl
/tmp/probe22/repro/meshcheck.py $D/k.ply $D/k.stl | cut -c1-120
for f in $D/k.ply $D/k.stl $D/k.glb $D/a.stl; do echo "$f: $($SV check $f | tail -1)"; done
