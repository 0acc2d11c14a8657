#!/bin/bash
# sphere r=0.01 just under a 178.99-degree spot: at 256^2 it covers no texel centre; only "the volume is empty" is printed,
# not the README's per-object warning naming it and the resolution that would catch it (1024^2 captures it).
cd /work/main; SV=${SV:-/tmp/probe22/sv}; D=$(mktemp -d)
for r in 256 1024; do $SV build --scene /tmp/probe22/repro/tiny_object_wide_spot.json --resolution $r --out $D/w.ply 2>&1 | grep -E 'vertices,|warning|note'; done
