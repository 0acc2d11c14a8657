#!/bin/bash
# validate determinism: same command 3 times (third pinned to core 0); compare report.json (minus timing fields) and PNGs
# SV: the shadowvol binary (default: this repository's build), copied to /tmp/probe15/sv
sv=${SV:-$(cd "$(dirname "$0")/../../../.." && pwd)/build/apps/shadowvol}
mkdir -p /tmp/probe15 && cp "$sv" /tmp/probe15/sv
cd /tmp/probe15
tag=$1; S=$2; shift 2
for i in 1 2 3; do
  pre=""; [ $i = 3 ] && pre="taskset -c 0"
  $pre ./sv validate --scene $S --size 320x240 --report det/val/$tag.$i --json "$@" > det/val/$tag.$i.out 2> det/val/$tag.$i.err; echo -n "rc=$? "
done
/usr/bin/python3 - det/val/$tag <<'PY'
import json, sys, hashlib, os
b = sys.argv[1]
def strip(x):
    if isinstance(x, dict): return {k: strip(v) for k, v in x.items() if k not in ("ms", "seconds", "timings", "time", "elapsedMs")}
    if isinstance(x, list): return [strip(v) for v in x]
    return x
def flat(x, p=""):
    if isinstance(x, dict):
        for k, v in x.items(): yield from flat(v, p + "/" + k)
    elif isinstance(x, list):
        for i, v in enumerate(x): yield from flat(v, p + f"/{i}")
    else: yield p, x
reps = [dict(flat(strip(json.load(open(f"{b}.{i}/report.json"))))) for i in (1, 2, 3)]
diffs = [k for k in reps[0] if not (reps[0].get(k) == reps[1].get(k) == reps[2].get(k))]
print(os.path.basename(b), "report fields differing:", len(diffs))
for k in diffs[:30]: print("   ", k, [r.get(k) for r in reps])
for root, _, files in os.walk(b + ".1"):
    for f in files:
        if f.endswith(".json"): continue
        rel = os.path.relpath(os.path.join(root, f), b + ".1")
        hs = set()
        for i in (1, 2, 3):
            try: hs.add(hashlib.md5(open(f"{b}.{i}/{rel}", "rb").read()).hexdigest())
            except FileNotFoundError: hs.add("missing")
        if len(hs) > 1: print("    file differs:", rel, len(hs))
PY
