#!/bin/bash
# usage: killtest.sh SIG DIR CMD...   start CMD in DIR, wait for a temp file (.*tmp*) to appear, send SIG, list what is left
sig=$1; dir=$2; shift 2
mkdir -p $dir; cd $dir; rm -rf -- * .[!.]* 2>/dev/null
"$@" > log 2>&1 &
pid=$!
for i in $(seq 1 12000); do
  if ls -a | grep -q tmp; then break; fi
  if ! kill -0 $pid 2>/dev/null; then echo "ended before a temp file appeared"; break; fi
  sleep 0.01
done
sleep ${DELAY:-0}
kill -$sig $pid 2>/dev/null
wait $pid; rc=$?
echo "sig=$sig rc=$rc left: $(ls -aR | tr '\n' ' ')"
tail -2 log
