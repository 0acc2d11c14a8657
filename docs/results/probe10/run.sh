#!/bin/bash
# The tenth probe (README.md here): issue 10's accuracy goals on 19 scenes of meshes no other scene
# uses. Run from the repository root after building and fetching the meshes to /tmp/probe9 (README.md
# here says how). About 6 minutes on a 2-core machine. Writes $OUT (default out/probe10): s4/ (the
# 4 x 4 sub-grid, the maps and silhouette volumes), s8/ (the 8 x 8 sub-grid at 128²) and prints the goals.
set -e
out=${OUT:-out/probe10}
mkdir -p "$out"
scenes=$(ls docs/results/probe10/scenes/*.json)
python3 scripts/refine_eval.py --exe build/apps/shadowvol --refine-grid 4 \
    --methods "shadowmap auto 2048,shadowmap front 2048,refined auto 128,refined auto 256,silhouette" \
    --out "$out/s4" $scenes > "$out/s4.md"
python3 scripts/refine_eval.py --exe build/apps/shadowvol --refine-grid 8 --methods "refined auto 128" \
    --out "$out/s8" $scenes > "$out/s8.md"
# Closed meshes: the scenes whose silhouette volume applies (every mesh closed: --capture auto takes entry).
closed=$(python3 - "$out/s4/results.jsonl" <<'PY'
import json, sys
print(",".join(sorted({d["scene"] for d in map(json.loads, open(sys.argv[1]))
                       if d["method"] == "silhouette" and d.get("error") is not None and d["error"] < 0.01})))
PY
)
python3 scripts/refine_goals.py "$out/s4/results.jsonl" --closed "$closed"
python3 - "$out" <<'PY'
import json, sys
out = sys.argv[1]
rows = [json.loads(l) for l in open(out + "/s4/results.jsonl")] + [json.loads(l) for l in open(out + "/s8/results.jsonl")]
cell = {}
for d in rows:
    key = d["method"] + (" S=8" if d.get("refineGrid") == 8 else "")
    cell.setdefault(d["scene"], {})[key] = d["error"]
for m in ("refined auto 128", "refined auto 128 S=8"):
    for label, ref in (("the auto map", lambda c: c["shadowmap auto 2048"]),
                       ("the better of the auto and front maps", lambda c: min(c["shadowmap auto 2048"], c["shadowmap front 2048"]))):
        miss = sorted(s for s, c in cell.items() if c[m] > ref(c))
        print("%s at most %s: %d of %d; missed: %s" % (m, label, len(cell) - len(miss), len(cell), ", ".join(miss) or "none"))
PY
