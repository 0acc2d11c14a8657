#!/bin/bash
# usage: killval.sh SIG FILE_TO_WAIT_FOR  -- start validate into kv/rep (after a complete earlier run), kill when FILE appears
# SV: the shadowvol binary (an absolute path; default: this repository's build)
sv=${SV:-$(cd "$(dirname "$0")/../../../.." && pwd)/build/apps/shadowvol}
sig=$1; waitfor=$2
mkdir -p kv; cd kv; rm -rf rep
"$sv" -q validate --resolution 64 --size 320x240 --report rep >/dev/null 2>&1   # an earlier complete run
echo "before: $(ls rep | tr '\n' ' ')"
"$sv" validate --resolution 128 --size 2000x1500 --report rep > log 2>&1 &
pid=$!
sleep 1
while [ ! -e rep/$waitfor ] || [ rep/$waitfor -ot rep/stencil.png.old ] ; do sleep 0.005; kill -0 $pid 2>/dev/null || break; done
kill -$sig $pid; wait $pid; echo "sig=$sig rc=$?"
echo "after: $(ls -la --time-style=+%T rep | awk 'NR>1{print $6, $7}' | tr '\n' ' ')"
tail -1 log
