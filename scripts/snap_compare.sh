#!/bin/bash
# Refinement's snap (docs/volume.md "Snap") against bisection alone: validate's misclassified
# fraction of the explicit refined volume, with and without --no-snap, scene by scene.
# Usage: bash scripts/snap_compare.sh RESOLUTION [more validate options, e.g. --refine-grid 4] -- SCENE.json...
# Prints: scene, error % without the snap, error % with it, crossings snapped (one line per scene).
set -eu
res=$1; shift
opts=()
while [ "$#" -gt 0 ] && [ "$1" != "--" ]; do opts+=("$1"); shift; done
[ "${1:-}" = "--" ] && shift
# Back capture unless the options name one (the command line's default is --capture auto since
# 2026-12-05; the figures in README were measured with back capture).
case " ${opts[*]-} " in *" --capture "*) ;; *) opts+=(--capture back) ;; esac
# The binary: SV, or this repository's build (the scenes are paths from the caller's folder).
SV=${SV:-$(cd "$(dirname "$0")/.." && pwd)/build/apps/shadowvol}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
error() {
  "$SV" validate --volume explicit --resolution "$res" --refine 6 "${opts[@]}" "$@" --json --report "$out/v" 2>/dev/null |
    python3 -c "import json, sys; r = json.load(sys.stdin); print('%.4f %s' % (100 * r['againstExact']['method']['errorFraction'], r['volume']['snappedCrossings']))"
}
printf '%-36s %10s %10s %9s\n' scene no-snap snap snapped
for f in "$@"; do
  read -r a _ < <(error --scene "$f" --no-snap)
  read -r b n < <(error --scene "$f")
  printf '%-36s %10s %10s %9s\n' "$(basename "$f" .json)" "$a" "$b" "$n"
done
