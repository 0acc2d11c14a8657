#!/usr/bin/env bash
# Broken files in Assimp's formats, made from assimp-testmodels (apt-get download, no install):
# each of five models cut at 0, 1, 10, 37, 50, 90 and 99 % of its size, 5,000 random bytes with
# its extension, and an empty .glb; each put in a scene and built with `shadowvol build`. Prints
# one line per file: exit code, seconds, the error. Expected: exit 0 or 1, never a crash.
#   bash scripts/assimp_broken_files.sh [SHADOWVOL]      (default build/apps/shadowvol)
set -euo pipefail
exe=$(realpath "${1:-build/apps/shadowvol}")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
apt-get download assimp-testmodels >/dev/null 2>&1
dpkg -x assimp-testmodels_*.deb x
m=x/usr/share/assimp/models
sources=("$m/glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb" "$m/FBX/box.fbx" "$m/Collada/COLLADA.dae"
         "$m/3DS/RotatingCube.3DS" "$m/BLEND/4Cubes4Mats_248.blend")
mkdir bad
i=0
for f in "${sources[@]}"; do
  ext=${f##*.}
  size=$(stat -c %s "$f")
  for pct in 0 1 10 37 50 90 99; do i=$((i + 1)); head -c $((size * pct / 100)) "$f" > "bad/cut$i-$pct.$ext"; done
  head -c 5000 /dev/urandom > "bad/random$i.$ext"
done
: > bad/empty.glb
for b in bad/*; do
  cat > s.json <<JSON
{"objects": [{"type": "plane", "name": "ground", "size": 10}, {"type": "mesh", "name": "m", "file": "$PWD/$b"}],
 "light": {"type": "spot", "position": [2.5, 6, 2], "target": [0, 0.5, 0], "fov": 50},
 "camera": {"eye": [0, 2.5, 5], "target": [0, 0.7, 0], "fov": 45, "width": 320, "height": 240}}
JSON
  start=$(date +%s.%N)
  set +e
  out=$(timeout 120 "$exe" build --scene s.json --resolution 32 --out "$PWD/o.ply" 2>&1)
  rc=$?
  set -e
  end=$(date +%s.%N)
  printf '%-22s exit %-3s %5.2f s  %s\n' "${b#bad/}" "$rc" "$(echo "$end - $start" | bc)" \
    "$(echo "$out" | grep 'error' | sed 's|.*: /[^:]*: ||' | cut -c1-110)"
done
