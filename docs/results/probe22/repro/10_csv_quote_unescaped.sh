#!/bin/bash
# a scene named with a double quote: results.csv writes it unquoted (RFC 4180 asks for "a&b<c""e")
cd /work/main; SV=${SV:-/tmp/probe22/sv}; D=$(mktemp -d); cp data/scenes/default.json "$D/a&b<c\"e.json"
$SV -q bench --scenes "$D/a&b<c\"e.json" --methods shadowmap --resolutions 32 --size 80x60 --repeat 1 --warmup 0 --out $D/bench
sed -n 2p $D/bench/results.csv | cut -c1-40
