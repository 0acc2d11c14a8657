#!/bin/bash
# Where the refined volume's wrong pixels lie at 256² on the closed-mesh goal scenes of issue 10
# (docs/results/light-fit: every mesh object a closed 2-manifold, where silhouette volumes apply),
# with the 4 x 4 and the 8 x 8 sub-grid, against the silhouette volume: `validate`'s report.json
# (againstExact, errorCauses, shadowsByOccluder's missedSelf and missedOnOthers). Fetch the meshes
# first (docs/results/light-fit/run.sh says how), build, then run from the repository root (about
# 5 minutes on a 2-core machine). EXE (default build/apps/shadowvol), OUT (default
# out/error-places), FLAGS (more options for the refined volume's runs, such as --face-prisms). Prints one line per scene and variant, then the sums. A rerun with the same OUT
# reuses the reports already there (delete OUT for a new binary).
set -e
exe=${EXE:-build/apps/shadowvol}
out=${OUT:-out/error-places}
mkdir -p "$out"
scenes="$(ls data/scenes/{armadillo,bunny,default,fandisk,hemisphere-grazing,lion-head,plate,plate-rotated,tree}.json \
  data/scenes/unseen/*.json docs/results/subgrid-bias/probe-scenes/*.json docs/results/probe10/scenes/*.json \
  docs/results/probe16/scenes/*.json)"
# closed_scenes.py reads each scene's silhouette error (a scene of generated objects counts as
# closed when its silhouette volume was exact); the silhouette runs below give them.
for s in $scenes; do
  n=$(basename "$s" .json)
  [ -f "$out/$n-silhouette.json" ] || "$exe" validate --scene "$s" --method silhouette --report "$out/r" --json \
      > "$out/$n-silhouette.json" 2>/dev/null || true
done
python3 - "$out" $scenes > "$out/silhouette.jsonl" <<'PY'
import json, os, sys
out = sys.argv[1]
for path in sys.argv[2:]:
    n = os.path.basename(path)[:-len(".json")]
    try:
        e = json.load(open(f"{out}/{n}-silhouette.json"))["againstExact"]["method"]["errorFraction"]
    except (OSError, ValueError, KeyError):
        continue
    print(json.dumps({"scene": n, "method": "silhouette", "error": e}))
PY
closed=$(python3 scripts/closed_scenes.py "$exe" "$out/silhouette.jsonl" $scenes)
for s in $scenes; do
  n=$(basename "$s" .json)
  case ",$closed," in *",$n,"*) ;; *) continue ;; esac
  for g in 4 8; do
    [ -f "$out/$n-s$g.json" ] || "$exe" validate --scene "$s" --volume explicit --refine 6 --refine-grid $g \
        --resolution 256 $FLAGS --report "$out/r" --json > "$out/$n-s$g.json" 2>/dev/null || true
  done
done
python3 - "$out" "$closed" <<'PY'
import json, sys
out, closed = sys.argv[1], sys.argv[2].split(",")
print("| scene | silhouette | S | missed | on itself | on others | false | resolution | capture | within 1.5x |")
print("|---|---:|---:|---:|---:|---:|---:|---:|---:|---|")
tot = {4: [0] * 6, 8: [0] * 6}
for n in closed:
    sil = json.load(open(f"{out}/{n}-silhouette.json"))["againstExact"]["method"]
    sw = sil["missedShadow"] + sil["falseShadow"]
    for g in (4, 8):
        r = json.load(open(f"{out}/{n}-s{g}.json"))
        m, c, o = r["againstExact"]["method"], r["errorCauses"], r["shadowsByOccluder"]
        ok = m["errorFraction"] <= 1.5 * sil["errorFraction"]
        row = [m["missedShadow"], o["missedSelf"], o["missedOnOthers"], m["falseShadow"], c["resolution"], c["capture"]]
        tot[g] = [a + b for a, b in zip(tot[g], row)] + [tot[g][6] + ok if len(tot[g]) > 6 else ok]
        print(f"| {n} | {sw} | {g} | " + " | ".join(map(str, row)) + f" | {'yes' if ok else 'no'} |")
for g in (4, 8):
    t = tot[g]
    print(f"| **sum, S = {g}** ({len(closed)} scenes) | | {g} | " + " | ".join(map(str, t[:6])) + f" | {t[6]} of {len(closed)} |")
PY
