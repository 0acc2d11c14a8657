#!/bin/bash
# a Latin-1 byte in a path: exit 4 ("runtime failure") with a raw nlohmann message; build --json leaves its mesh and prints nothing
cd /work/main; SV=${SV:-/tmp/probe22/sv}; D=$(mktemp -d)
$SV -q build --resolution 16 --out $D/$'caf\xe9.gltf'; echo "gltf rc=$?"
cp data/scenes/default.json $D/$'sc\xe9ne.json'
$SV -q validate --scene $D/$'sc\xe9ne.json' --resolution 32 --size 80x60 --report $D/rep; echo "validate rc=$?"; ls -a $D/rep
$SV -q build --scene $D/$'sc\xe9ne.json' --resolution 32 --json --out $D/j.ply > $D/j.json; echo "build --json rc=$? stdout bytes=$(stat -c %s $D/j.json)"; ls $D
