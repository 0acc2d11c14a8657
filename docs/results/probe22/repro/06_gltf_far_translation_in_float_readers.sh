#!/bin/bash
# glTF node translation -123456789012.34567 is read by Assimp 5.2.5 (Debian) as -123456790528 (1516 units off)
cd /work/main; SV=${SV:-/tmp/probe22/sv}; D=$(mktemp -d)
$SV -q build --scene /tmp/probe22/repro/stl_header_origin_truncated.json --resolution 64 --out $D/v.glb
LD_LIBRARY_PATH=/tmp/probe22/root/usr/lib/x86_64-linux-gnu /tmp/probe22/root/usr/bin/assimp info $D/v.glb -v | grep -A2 'Node hierarchy'
