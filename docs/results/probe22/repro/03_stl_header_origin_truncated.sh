#!/bin/bash
# origin with two tiny non-zero components: the 80-byte STL header cuts the last number's exponent.
cd /work/main; SV=${SV:-/tmp/probe22/sv}; D=$(mktemp -d)
$SV -q build --scene /tmp/probe22/repro/stl_header_origin_truncated.json --resolution 64 --out $D/v.stl
$SV -q build --scene /tmp/probe22/repro/stl_header_origin_truncated.json --resolution 64 --out $D/v.ply
echo "STL header: $(head -c 80 $D/v.stl | tr '\0' '.')"; grep -a 'origin' $D/v.ply
