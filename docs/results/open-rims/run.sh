#!/bin/bash
# The sub-grid's search for open rims (docs/volume.md "Hidden surfaces", "Open rims"): the refined
# volume (K = 6, 4 x 4 sub-grid, --capture auto) at 128² and 256² on the 48 scenes of the goals
# (docs/results/sharp-reference/run.sh says what to fetch first), compared with the same run before
# the rims (docs/results/sharp-reference/results.jsonl, 2026-12-06); then the search's cost.
# About 8 minutes on a 2-core machine.
set -e
out=${OUT:-out/open-rims}
mkdir -p "$out"
python3 scripts/refine_eval.py --exe build/apps/shadowvol --refine-grid 4 \
    --methods "refined auto 128,refined auto 256" --out "$out" \
    data/scenes/{armadillo,bunny,default,fandisk,hemisphere-grazing,lion-head,plate,plate-rotated,tree}.json \
    data/scenes/unseen/*.json docs/results/subgrid-bias/probe-scenes/*.json > "$out.md"
python3 - "$out/results.jsonl" <<'PY'
import json, sys
load = lambda p: {(d["scene"], d["method"]): d for d in map(json.loads, open(p))}
before, after = load("docs/results/sharp-reference/results.jsonl"), load(sys.argv[1])
print("| scene | method | before % | with rims % |\n|---|---|---:|---:|")
changed = [k for k in sorted(after) if abs(before[k]["error"] - after[k]["error"]) > 1e-12]
for k in changed:
    print(f"| {k[0]} | {k[1]} | {100 * before[k]['error']:.4f} | {100 * after[k]['error']:.4f} |")
low = [k for k in after if after[k]["agree"] is not None and after[k]["agree"] < 0.9999]
print(f"\n{len(changed)} of {len(after)} runs changed; stencil vs counts below 99.99 %: {len(low)}")
PY
/usr/bin/python3 scripts/hidden_search_cost.py
