#!/bin/bash
# The leak criterion (lib/include/shadowvol/validate/shadow_leaks.h) over many scenes: one line per
# scene (per light) with its deep missed pixels, missed pixels, the exact shadow and the verdict.
# usage: bash scripts/leak_scan.sh "VALIDATE OPTIONS" SCENE.json...   (run from the repository root)
#   e.g. bash scripts/leak_scan.sh "--method shadowmap --resolution 64" data/scenes/*.json data/scenes/*/*.json
# SV: the binary (default build/apps/shadowvol). Reports go to a temporary folder, removed at the end.
set -u
sv=${SV:-build/apps/shadowvol}
opts=$1
shift
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
for f in "$@"; do
  name=$(basename "$f" .json)
  # shellcheck disable=SC2086  # the options are words
  timeout 300 "$sv" validate --scene "$f" $opts --json --report "$tmp/r" > "$tmp/out.json" 2> /dev/null
  rc=$?
  python3 - "$tmp/out.json" "$name" "$rc" <<'PY'
import json, sys
path, name, rc = sys.argv[1:]
try:
    j = json.load(open(path))
except Exception:
    print(f"{name:40s} rc={rc} no report")
    sys.exit()
for s in j.get("lights", [j]):
    leaks, m = s.get("leaks"), s["againstExact"]["method"]
    deep = leaks["deep"] if isinstance(leaks, dict) else "-"
    print(f"{name:40s} rc={rc} deep={deep} missed={m['missedShadow']} of {s['pixels']['exactShadowed']} "
          f"passed={s['passed']}")
PY
done
