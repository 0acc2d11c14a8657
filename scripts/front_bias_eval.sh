#!/bin/bash
# Front capture's bias against its error: the refined sub-grid volume (--refine 6 --refine-grid 4,
# --capture front) of each unseen scene with an open or non-manifold mesh, at 128^2 and 256^2, with
# the default bias F (volume.bias of validate's JSON: a texel's footprint at the far plane plus 4
# float ulps, README 'Volume mesh') and with F/2 and F/4. Prints one line per scene and size: F
# and the misclassified % (againstExact.method) at F, F/2, F/4. About 5 minutes on 2 cores.
# Usage: bash scripts/front_bias_eval.sh [build dir, or the shadowvol executable]
set -eu
B=$(realpath "${1:-build}")  # given from the caller's folder
SV=$B/apps/shadowvol
[ -f "$B" ] && SV=$B
root=$(cd "$(dirname "$0")/.." && pwd)  # the repository: the scenes are read from it
cd "$root"
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
PY=/usr/bin/python3
[ -x "$PY" ] || PY=python3
field() { "$PY" -c "import json,sys; d=json.load(sys.stdin); print($1)"; }
run() {  # scene file, resolution, extra options...; prints validate's JSON
  local f=$1 r=$2
  shift 2
  "$SV" validate --scene "$f" --volume explicit --refine 6 --refine-grid 4 --resolution "$r" --capture front \
    "$@" --report "$out/r" --json 2>/dev/null
}
for s in biped-nonmanifold-grazing cloth-open-directional-down devilmask-open-grazing dragon-nearlyclosed-spot \
         duo-cloth-over-dino-directional head-open-spot mushroom-open-directional spider-nonmanifold-spot \
         wuson-open-spot wusonsoup-soup-directional; do
  f=data/scenes/unseen/$s.json
  for r in 128 256; do
    read -r F e < <(run "$f" "$r" | field "d['volume']['bias'], 100 * d['againstExact']['method']['errorFraction']")
    line="$s $r F=$F e(F)=$e"
    for k in 2 4; do
      b=$("$PY" -c "print($F / $k)")
      e=$(run "$f" "$r" --bias "$b" | field "100 * d['againstExact']['method']['errorFraction']")
      line="$line e(F/$k)=$e"
    done
    echo "$line"
  done
done
