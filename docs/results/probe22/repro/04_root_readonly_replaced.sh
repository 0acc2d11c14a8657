#!/bin/bash
# run as root: a 0444 output file is replaced (exit 0); README: "a read-only file is refused"
cd /work/main; SV=${SV:-/tmp/probe22/sv}; D=$(mktemp -d); echo old > $D/ro.ply; chmod 444 $D/ro.ply
$SV -q build --resolution 32 --out $D/ro.ply; echo "rc=$? (id -u=$(id -u))"; ls -l $D/ro.ply; head -c 3 $D/ro.ply; echo
