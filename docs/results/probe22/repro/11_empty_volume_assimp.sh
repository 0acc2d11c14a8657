#!/bin/bash
# empty volume (documented, warned): every format is refused by Assimp 5.2.5
cd /work/main; SV=${SV:-/tmp/probe22/sv}; D=$(mktemp -d)
for e in ply obj off stl gltf glb; do $SV -q build --scene /tmp/probe22/repro/empty_ground_only.json --resolution 32 --out $D/e.$e 2>/dev/null
  echo "$e: $(LD_LIBRARY_PATH=/tmp/probe22/root/usr/lib/x86_64-linux-gnu /tmp/probe22/root/usr/bin/assimp info $D/e.$e 2>&1 | grep -m1 ERROR)"; done
