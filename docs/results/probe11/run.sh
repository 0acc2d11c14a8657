#!/bin/bash
# The eleventh probe (docs/results/probe11/README.md): 39 assimp-testmodels meshes, 221 runs, about
# 5 minutes on 2 cores. Needs the meshes unpacked under /tmp/probe9 (README) or PROBE_MODELS; the
# scenes were made once by make_scenes.py and are kept here.
set -euo pipefail
cd "$(dirname "$0")/../../.."
export OUT=${OUT:-out/probe11}
rm -f "$OUT/runs.jsonl"
python3 docs/results/probe11/run.py > /dev/null
python3 docs/results/probe11/analyse.py
