#!/bin/bash
# Experiments on issue 10's 256² goal that did not land (README.md here). Each patch is applied to
# the working tree, built, compared with and without its environment variable, and reverted. Run
# from the repository root with a clean tree, after building and fetching what
# docs/results/sharp-reference/run.sh and docs/results/probe10/run.sh need.
#   bash docs/results/resolution-bound/run.sh [smooth|cap|corner|grazing|grid8] ...   (default: all; about 15 minutes)
# The patches were made on bbcaa78; two of them (entry-exit-cap, entry-grazing-threshold) do not
# apply to later trees (a seventeenth probe's finding): run this in a checkout of bbcaa78.
set -e
here=docs/results/resolution-bound
exe=build/apps/shadowvol
out=${OUT:-out/resolution-bound}
mkdir -p "$out"
main="data/scenes/armadillo.json data/scenes/bunny.json data/scenes/default.json data/scenes/fandisk.json
      data/scenes/hemisphere-grazing.json data/scenes/lion-head.json data/scenes/plate.json
      data/scenes/plate-rotated.json data/scenes/tree.json $(ls data/scenes/unseen/*.json docs/results/subgrid-bias/probe-scenes/*.json)"
closed22="armadillo bunny default fandisk hemisphere-grazing plate plate-rotated tree"
for s in blobby-shuffled-orientation-spot bones-multicomponent-spot coupling-directional-down cow-spot \
         dino-directional diplodocus-grazing duo-ellipsoid-over-cow-spot ellipsoid-float-directional-down \
         homer-spot knot-grazing pinion-spot-steep triceratops-spot-low trio-directional turbine-spot; do
  closed22="$closed22 unseen/$s"
done

# row NAME RES LABEL ARGS...: one validate run (RES "-": no --resolution, for silhouette volumes),
# printed as "scene res label capture missed false error% capture-cause", the last the pixels
# report.json's errorCauses puts under `capture` ("-" for silhouette volumes).
row() {
  local name=$1 res=$2 label=$3; shift 3
  local r=(--resolution "$res")
  [ "$res" = - ] && r=()
  "$exe" validate "${r[@]}" --report "$out/report" --json "$@" > "$out/run.json" 2>/dev/null || true
  python3 -c "
import json; d = json.load(open('$out/run.json')); m = d['againstExact']['method']
c = d.get('errorCauses'); c = c if isinstance(c, dict) else {}
print('%-36s %4s %-10s %-6s %5d %5d %.4f %s' % ('$name', '$res', '$label', d['options'].get('capture') or '-', m['missedShadow'],
      m['falseShadow'], 100 * m['errorFraction'], c.get('capture', '-')))"
}

# with_patch PATCH COMMAND...: applies the patch, builds, runs the command, reverts.
with_patch() {
  local patch=$1; shift
  if ! git apply --check "$here/$patch" 2> /dev/null; then
    echo "$patch does not apply to this tree: run this script in a checkout of bbcaa78" >&2
    exit 2
  fi
  git apply "$here/$patch"
  trap "git apply -R '$here/$patch'; cmake --build build --target shadowvol > /dev/null" EXIT
  cmake --build build --target shadowvol > /dev/null
  "$@"
  git apply -R "$here/$patch"
  trap - EXIT
  cmake --build build --target shadowvol > /dev/null
}

smooth() {  # texel centres of plain quads keep only the bias their chords show (smooth-bias.patch)
  for s in $main; do for r in 128 256; do
    row "$(basename "$s" .json)" $r base --scene "$s" --volume explicit --refine 6 --refine-grid 4
    SV_SMOOTH_BIAS=1 row "$(basename "$s" .json)" $r smooth --scene "$s" --volume explicit --refine 6 --refine-grid 4
  done; done
}

cap() {  # entry capture records min(entry, exit - B): the sheet no deeper than the first back face (entry-exit-cap.patch)
  for s in armadillo bunny unseen/bones-multicomponent-spot unseen/cow-spot; do
    local a=(--scene "data/scenes/$s.json" --volume explicit --depth-from rays --refine 6 --refine-grid 4)
    row "$(basename "$s")" 256 base "${a[@]}"
    local b=$(python3 -c "import json; print(json.load(open('$out/run.json'))['options']['bias'])")
    SV_ENTRY_CAP=$b row "$(basename "$s")" 256 exit-cap "${a[@]}"
  done
}

corner() {  # texel centres inside the sub-grid keep only the bias their sub-cells need (corner-bias.patch)
  for s in docs/results/probe10/scenes/chinesedragon-10kv-spot.json data/scenes/armadillo.json \
           data/scenes/unseen/bones-multicomponent-spot.json docs/results/subgrid-bias/probe-scenes/elephantholes.json; do
    row "$(basename "$s" .json)" 128 base --scene "$s" --volume explicit --refine 6 --refine-grid 4
    SV_CORNER_BIAS=1 row "$(basename "$s" .json)" 128 corner --scene "$s" --volume explicit --refine 6 --refine-grid 4
  done
}

grazing() {  # entry capture passes over faces lit below N.L = 1/64 or 1/32 instead of 1/256 (entry-grazing-threshold.patch)
  for s in $main docs/results/probe10/scenes/*.json; do for r in 128 256; do
    local a=(--scene "$s" --volume explicit --depth-from rays --refine 6 --refine-grid 4 --capture auto)
    row "$(basename "$s" .json)" $r 1/256 "${a[@]}"
    SV_GRAZE=0.015625 row "$(basename "$s" .json)" $r 1/64 "${a[@]}"
    SV_GRAZE=0.03125 row "$(basename "$s" .json)" $r 1/32 "${a[@]}"
  done; done
}

grid8() {  # the 8 x 8 sub-grid on every refined quad (no patch): the 22 closed-mesh scenes at 256²
  for s in $closed22; do
    row "$(basename "$s")" 256 S=4 --scene "data/scenes/$s.json" --volume explicit --refine 6 --refine-grid 4
    row "$(basename "$s")" 256 S=8-every --scene "data/scenes/$s.json" --volume explicit --refine 6 --refine-grid 8 --refine-grid-everywhere
    row "$(basename "$s")" - silhouette --scene "data/scenes/$s.json" --method silhouette
  done
}

for part in ${@:-smooth cap corner grazing grid8}; do
  case $part in
    smooth) with_patch smooth-bias.patch smooth | tee "$out/smooth.txt" ;;
    cap) with_patch entry-exit-cap.patch cap | tee "$out/cap.txt" ;;
    corner) with_patch corner-bias.patch corner | tee "$out/corner.txt" ;;
    grazing) with_patch entry-grazing-threshold.patch grazing | tee "$out/grazing.txt" ;;
    grid8) grid8 | tee "$out/grid8.txt" ;;
    *) echo "unknown part: $part" >&2; exit 2 ;;
  esac
done
