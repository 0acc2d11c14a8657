#!/bin/bash
# The sheet held no deeper than halfway through the first solid, or than its back face
# (entry-cap.patch, an experiment that did not land; README.md here). Applies the patch, builds the
# command line, runs `validate` on the 48 closed-mesh scenes of run.sh at 256² with the 4 x 4
# sub-grid and the map ray-cast (the patch is in the Embree capture), without the patch's variables
# (base), with SV_ENTRY_MIDCAP=B (mid) and with SV_ENTRY_CAP=B (exit), B the scene's default bias;
# then reverts and rebuilds. Run from the repository root with a clean tree, after run.sh (it reads
# the closed list from its OUT). Prints "scene label missed false missedSelf resolution capture"
# and the sums (about 10 minutes on 2 cores).
set -e
here=docs/results/error-places
exe=build/apps/shadowvol
eout=${OUT:-out/error-places}
out=${CAP_OUT:-out/error-places-cap}
mkdir -p "$out"
git apply --check "$here/entry-cap.patch"
git apply "$here/entry-cap.patch"
trap "git apply -R '$here/entry-cap.patch'; cmake --build build --target shadowvol > /dev/null" EXIT
cmake --build build --target shadowvol > /dev/null
scenes="$(ls data/scenes/{armadillo,bunny,default,fandisk,hemisphere-grazing,lion-head,plate,plate-rotated,tree}.json \
  data/scenes/unseen/*.json docs/results/subgrid-bias/probe-scenes/*.json docs/results/probe10/scenes/*.json \
  docs/results/probe16/scenes/*.json)"
closed=$(python3 scripts/closed_scenes.py "$exe" "$eout/silhouette.jsonl" $scenes)
: > "$out/rows.txt"
row() {  # LABEL NAME VALIDATE-ARGS...
  local label=$1 name=$2; shift 2
  "$exe" validate "$@" --report "$out/r" --json > "$out/run.json" 2>/dev/null || true
  python3 -c "
import json; d = json.load(open('$out/run.json')); m = d['againstExact']['method']; c = d['errorCauses']
print('$name', '$label', m['missedShadow'], m['falseShadow'], d['shadowsByOccluder']['missedSelf'], c['resolution'],
      c['capture'], d['options']['bias'])" | tee -a "$out/rows.txt"
}
for s in $scenes; do
  n=$(basename "$s" .json)
  case ",$closed," in *",$n,"*) ;; *) continue ;; esac
  a=(--scene "$s" --volume explicit --depth-from rays --refine 6 --refine-grid 4 --resolution 256)
  row base "$n" "${a[@]}"
  b=$(tail -1 "$out/rows.txt" | awk '{print $8}')
  SV_ENTRY_MIDCAP=$b row mid "$n" "${a[@]}"
  SV_ENTRY_CAP=$b row exit "$n" "${a[@]}"
done
python3 - "$out/rows.txt" <<'PY'
import collections, sys
tot = collections.defaultdict(lambda: [0] * 5)
for line in open(sys.argv[1]):
    f = line.split()
    tot[f[1]] = [a + int(b) for a, b in zip(tot[f[1]], f[2:7])]
for label, t in tot.items():
    print("sum %-5s missed %d false %d missedSelf %d resolution %d capture %d" % (label, *t))
PY
