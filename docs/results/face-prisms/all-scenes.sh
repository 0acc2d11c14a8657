#!/bin/bash
# validate --refine 6 --refine-grid 4 at 128² with and without --face-prisms on every scene of
# data/scenes, data/scenes/unseen and the probes' folders (closed, open and non-manifold meshes):
# one line per scene and variant: name, resolution, variant, exit code, passed, missed, false,
# stencil-vs-count disagreements, texels handed over to the prisms. Fetch the meshes first
# (docs/results/light-fit/run.sh says how), build, run from the repository root (about 10 minutes
# on 2 cores). EXE as run.sh's. all-scenes.txt is the output at 4f1ea0e.
exe=${EXE:-build/apps/shadowvol}
tmp=$(mktemp -d)
for s in data/scenes/*.json data/scenes/unseen/*.json docs/results/subgrid-bias/probe-scenes/*.json \
    docs/results/probe10/scenes/*.json docs/results/probe16/scenes/*.json; do
  n=$(basename "$s" .json)
  for fp in "" "--face-prisms"; do
    timeout 300 "$exe" validate --scene "$s" --volume explicit --refine 6 --refine-grid 4 --resolution 128 $fp \
      --report "$tmp/r" --json > "$tmp/r.json" 2> "$tmp/r.err"
    rc=$?
    python3 - "$n" "$fp" "$rc" "$tmp" <<'PY'
import json, sys
n, fp, rc, tmp = sys.argv[1:]
try:
    j = json.load(open(f"{tmp}/r.json")); m = j["againstExact"]["method"]
    print(n, 128, fp or "plain", rc, j["passed"], m["missedShadow"], m["falseShadow"],
          j["stencilVsCount"]["disagree"], j["volume"].get("prismColumnTexels"))
except (OSError, ValueError, KeyError):
    print(n, 128, fp or "plain", rc, "ERR", open(f"{tmp}/r.err").read()[:200].replace("\n", " "))
PY
  done
done
rm -rf "$tmp"
