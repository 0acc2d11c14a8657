#!/bin/bash
# Entry against back capture for refined volumes (--refine 6 --refine-grid 4, explicit volume,
# 640x480 against the sharp exact reference) on spot lights of growing far / near (README
# "--capture auto"). Makes the fourteenth probe's wide-spot scenes first (B/gen.py, into
# /tmp/probe14/B; the meshes from /tmp/probe9, docs/results/subgrid-bias says how to fetch them).
# Run from the repository root after building; prints one line per run.
set -euo pipefail
export SV=$(realpath "${SV:-build/apps/shadowvol}")  # absolute: gen.py runs in /tmp/probe14/B
mkdir -p /tmp/probe14/B && cp docs/results/probe14/B/*.py /tmp/probe14/B/
(cd /tmp/probe14/B && python3 gen.py wide2 insh > /dev/null)
for s in data/scenes/bunny-wide-ground.json /tmp/probe14/B/scenes/wide2_fov90.json \
         /tmp/probe14/B/scenes/wide2_fov160.json data/scenes/tree.json \
         data/scenes/unseen/triceratops-spot-low.json data/scenes/unseen/turbine-spot.json \
         docs/results/probe10/scenes/helmet-spotlow.json /tmp/probe14/B/scenes/wide_id.json; do
  ratio=$("$SV" scene --scene "$s" --json 2>/dev/null |
          python3 -c "import json,sys; l=json.load(sys.stdin)['light']; print('%.3g' % (l['far']/l['near']))")
  for r in 128 256; do for c in entry back; do
    out=$("$SV" validate --scene "$s" --resolution $r --volume explicit --refine 6 --refine-grid 4 --capture $c \
          --report /tmp/probe14/deep-spot-rep 2>&1 | grep "against exact" || true)
    echo "$(basename "$s") far/near $ratio $r $c $out"
  done; done
done
