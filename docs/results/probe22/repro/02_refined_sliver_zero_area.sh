#!/bin/bash
# bunny, 1024^2, --refine 16 --refine-grid 8: the default float PLY holds one exactly collinear triangle;
# shadowvol's own check rejects both the float file and the --world-coords (double) file; build exits 0, no warning.
cd /work/main; SV=${SV:-/tmp/probe22/sv}; D=$(mktemp -d)
$SV -q build --scene data/scenes/bunny.json --resolution 1024 --refine 16 --refine-grid 8 --out $D/b.ply; echo "build rc=$?"
$SV -q build --scene data/scenes/bunny.json --resolution 1024 --refine 16 --refine-grid 8 --world-coords --out $D/b-wc.ply
/tmp/probe22/repro/meshcheck.py $D/b.ply $D/b-wc.ply | cut -c1-120
/usr/bin/python3 /tmp/probe22/repro/degen.py $D/b.ply | head -4
$SV check $D/b.ply | tail -1; $SV check $D/b-wc.ply | tail -1
