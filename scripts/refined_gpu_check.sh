#!/bin/bash
# The refined GPU volume's consistency on every shipped scene (docs/gpu.md "The refined GPU volume"):
# shadowvol validate --volume gpu --refine 4 (the GPU's rays, the default since 2026-12-04; the walk
# before) at 128^2 and 256^2, back and front capture, with and
# without blur. One line per frame: stencil vs crossing counts, boundary edges the CPU rule found
# that the GPU did not, the GPU volume's own mesh check, the error against exact shadows, the verdict
# (consistent: the checks above; accurate: validate's error limits, which blur with front capture can miss).
# Usage: bash scripts/refined_gpu_check.sh [build dir] > out.txt   (about 10 minutes on 2 cores)
set -u
B=$(realpath "${1:-build}")  # given from the caller's folder
V=$B/apps/shadowvol
root=$(cd "$(dirname "$0")/.." && pwd)  # the repository: the scenes are read from it
cd "$root"
missing=0
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
for f in data/scenes/{default,armadillo,bunny,fandisk,plate,plate-rotated,tree,hemisphere-grazing,lion-head,bunny-wide-ground,tree-wide-ground}.json data/scenes/unseen/*.json; do
  s=$(basename "$f" .json)
  for res in 128 256; do for cap in back front; do for blur in "" "--blur"; do
    j=$("$V" validate --json --scene "$f" --volume gpu --refine 4 --resolution "$res" --capture "$cap" $blur \
        --report "$out/r" 2>/dev/null)
    if [ -z "$j" ]; then echo "$s $res $cap ${blur:-plain}: no report (scene meshes missing? scripts/fetch_meshes.sh)"; missing=$((missing + 1)); continue; fi
    echo "$j" | python3 -c "
import json,sys
j=json.load(sys.stdin); a=j['stencilVsCount']; g=j.get('gpuVolumeMeshChecks',{}); e=j['againstExact']['method']
v=j['verdict']
print('$s $res $cap ${blur:-plain}: stencil vs counts %.4f%%, CPU edges not the GPU\'s %d of %d, GPU mesh %s, error %.3f%%, %s, %s' % (
  100*a['fraction'], j['volume']['crossingFallbacks'], j['volume']['boundaryEdges'],
  'valid' if g.get('valid') else 'INVALID', 100*e['errorFraction'],
  'consistent' if v['consistent'] else 'INCONSISTENT', 'accurate' if v['accurate'] else 'not accurate (--max-error)'))"
  done; done; done
done
[ "$missing" -eq 0 ] || { echo "$missing runs gave no report" >&2; exit 1; }
