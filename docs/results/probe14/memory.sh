#!/bin/bash
# Peak memory of `shadowvol build --depth` on 1000² maps of different islands of hit texels
# (README, the resolution limits): isolated texels, 2 x 2 and 3 x 3 blocks, stripes, a checkerboard,
# one square, and the default scene's own map. Needs the Python module (build/python) and numpy.
# Run from the repository root after building; prints one line per map: name, seconds, peak KB.
set -euo pipefail
SV=${SV:-$PWD/build/apps/shadowvol}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
PYTHONPATH=$PWD/build/python /usr/bin/python3 - "$out" <<'PY'
import sys, numpy as np, shadowvol as sv
out = sys.argv[1]
d = sv.capture_depth(sv.default_scene(), 64, 64)
n, hit = 1000, d.far * 0.8
def save(name, mask):
    a = np.where(mask, np.float32(hit), np.float32(np.inf)).astype(np.float32)
    sv.DepthMap.from_array(a, d.light_view, d.light_projection, d.near, d.far, light=d.light).save(f'{out}/{name}.pfm')
j, i = np.mgrid[0:n, 0:n]
save('isolated', (i % 2 == 0) & (j % 2 == 0))
save('blocks2', (i % 3 < 2) & (j % 3 < 2))
save('blocks3', (i % 4 < 3) & (j % 4 < 3))
save('stripes', j % 2 == 0)
save('checkerboard', (i + j) % 2 == 0)
save('square', (i >= n // 4) & (i < 3 * n // 4) & (j >= n // 4) & (j < 3 * n // 4))
PY
for m in isolated blocks2 blocks3 stripes checkerboard square; do
  /usr/bin/time -f "$m %e s %M KB" "$SV" build --depth "$out/$m.pfm" --out "$out/v.ply" 2>&1 >/dev/null | tail -1
done
/usr/bin/time -f "default-scene %e s %M KB" "$SV" build --resolution 1000 --out "$out/v.ply" 2>&1 >/dev/null | tail -1
