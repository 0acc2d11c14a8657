#!/bin/bash
# Whether two shadowvol binaries build byte-identical volumes (for a change meant to keep behaviour,
# README "Sub-grid", Cost): 8 scenes x 128²/256² x back/front/entry capture x 4 x 4 and 8 x 8
# sub-grid, and the unseen scenes at 128² with the 4 x 4 sub-grid, all with --refine 6; prints each
# volume that differs (or fails), then the count compared.
# Usage: bash scripts/volume_identity.sh EXE_A EXE_B
set -uo pipefail
a=$1 b=$2
cd "$(dirname "$0")/.."
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
n=0 diff=0
one() {  # name, then the build options
  local name=$1; shift
  "$a" build "$@" --out "$out/a-$name.ply" > /dev/null 2>&1 || { echo "FAIL A $name"; diff=$((diff + 1)); }
  "$b" build "$@" --out "$out/b-$name.ply" > /dev/null 2>&1 || { echo "FAIL B $name"; diff=$((diff + 1)); }
  cmp -s "$out/a-$name.ply" "$out/b-$name.ply" || { echo "DIFF $name"; diff=$((diff + 1)); }
  n=$((n + 1))
}
for s in default bunny armadillo hemisphere-grazing lion-head tree fandisk plate-rotated; do
  scene=(); [ "$s" = default ] || scene=(--scene "data/scenes/$s.json")
  for r in 128 256; do for c in back front entry; do for g in 4 8; do
    one "$s-$r-$c-$g" "${scene[@]}" --resolution $r --capture $c --refine 6 --refine-grid $g
  done; done; done
done
for f in data/scenes/unseen/*.json; do
  one "u-$(basename "$f" .json)" --scene "$f" --resolution 128 --refine 6 --refine-grid 4
done
echo "$n volumes compared, $diff differ or fail"
[ "$diff" -eq 0 ]
