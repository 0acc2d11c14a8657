#!/bin/bash
# Scene origin stays 0 (big ground centred at origin, camera looks at origin), the shadowed detail sits at x=1e6
# with a fine directional window (extent 11, 1024^2 -> ~0.02 texel). Default (float) exports hold zero-area triangles.
cd /work/main; SV=${SV:-/tmp/probe22/sv}; D=$(mktemp -d)
$SV build --scene /tmp/probe22/repro/far_detail_origin0.json --resolution 1024 --out $D/v.ply; echo "build rc=$?"
$SV build --scene /tmp/probe22/repro/far_detail_origin0.json --resolution 1024 --out $D/v.glb >/dev/null
$SV build --scene /tmp/probe22/repro/far_detail_origin0.json --resolution 1024 --world-coords --out $D/v-wc.ply >/dev/null
/tmp/probe22/repro/meshcheck.py $D/v.ply $D/v.glb $D/v-wc.ply | cut -c1-160
$SV check $D/v.ply | tail -1; $SV check $D/v-wc.ply | tail -1
