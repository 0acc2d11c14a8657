#!/bin/bash
# Issue 10's 128² goal with the 8 x 8 sub-grid (--refine 6 --refine-grid 8, --capture auto) on the 48
# scenes of the goals, against the 2048² shadow map of --capture auto (back on closed meshes, front
# on open ones; docs/results/sharp-reference) and against the 2048² front-capture map with its slope
# bias; then frame times of both sub-grids and the maps on six scenes (`shadowvol bench`, 15 frames).
# Fetch first what docs/results/sharp-reference/run.sh says; run docs/results/open-rims/run.sh first
# (the 4 x 4 sub-grid's figures at this commit). About 12 minutes on a 2-core machine.
set -e
out=${OUT:-out/grid8}
mkdir -p "$out"
scenes="data/scenes/{armadillo,bunny,default,fandisk,hemisphere-grazing,lion-head,plate,plate-rotated,tree}.json"
scenes=$(eval echo $scenes)" "$(echo data/scenes/unseen/*.json docs/results/subgrid-bias/probe-scenes/*.json)
python3 scripts/refine_eval.py --exe build/apps/shadowvol --refine-grid 8 --methods "refined auto 128" \
    --out "$out/s8" $scenes > "$out/s8.md"
python3 scripts/refine_eval.py --exe build/apps/shadowvol --methods "shadowmap front 2048" \
    --out "$out/map-front" $scenes > "$out/map-front.md"
python3 - "$out" "${S4:-out/open-rims/results.jsonl}" <<'PY'
import json, sys
load = lambda p: [json.loads(l) for l in open(p)]
out, s4path = sys.argv[1], sys.argv[2]
auto = {d["scene"]: d["error"] for d in load("docs/results/sharp-reference/results.jsonl")
        if d["method"] == "shadowmap auto 2048"}
front = {d["scene"]: d["error"] for d in load(out + "/map-front/results.jsonl")}
s4 = {d["scene"]: d["error"] for d in load(s4path) if d["method"] == "refined auto 128"}
s8 = {d["scene"]: d for d in load(out + "/s8/results.jsonl")}
print("| scene | 2048² map, auto | 2048² map, front | refined 128 S=4 | refined 128 S=8 |\n|---|---:|---:|---:|---:|")
for sc in sorted(s8):
    print(f"| {sc} | {100 * auto[sc]:.4f} | {100 * front[sc]:.4f} | {100 * s4[sc]:.4f} | {100 * s8[sc]['error']:.4f} |")
for name, e in (("S=4", s4), ("S=8", {k: v["error"] for k, v in s8.items()})):
    for label, ref in (("the auto map", auto), ("the better of the two maps", {k: min(auto[k], front[k]) for k in auto})):
        miss = [k for k in sorted(s8) if e[k] > ref[k]]
        print(f"\nrefined 128 {name} at most {label}: {len(s8) - len(miss)} of {len(s8)}; missed: {', '.join(miss) or 'none'}")
low = [k for k, d in s8.items() if d["agree"] is not None and d["agree"] < 0.9999]
print(f"\nS=8 stencil vs counts below 99.99 %: {len(low)}")
PY
bench=(build/apps/shadowvol bench --repeat 15 --scenes data/scenes/{default,bunny,armadillo,fandisk}.json
       docs/results/subgrid-bias/probe-scenes/elephantholes.json data/scenes/unseen/coupling-directional-down.json)
"${bench[@]}" --resolutions 128,256 --out "$out/bench" --methods hybrid-refined-grid-entry/explicit,\
hybrid-refined-grid8-entry/explicit,hybrid-refined-grid-front/explicit,hybrid-refined-grid8-front/explicit,shadowmap,shadowmap-front
"${bench[@]}" --resolutions 2048 --out "$out/bench-map" --methods shadowmap,shadowmap-front
