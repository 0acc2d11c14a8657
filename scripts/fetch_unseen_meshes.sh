#!/usr/bin/env bash
# Fetches the meshes of the evaluation scenes in data/scenes/unseen/ (meshes the method was not
# developed on) from Debian's libcgal-demo and assimp-testmodels packages (apt-get download, no
# install) into the git-ignored data/meshes/unseen/. Safe to run again: it does nothing when the
# meshes are there. Not needed by the tests; used by scripts/refine_eval.py.
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
dest="$top/data/meshes/unseen"
# package:path inside it:name here
wanted=(
  cgal:cow.off:cow.off cgal:knot1.off:knot.off cgal:couplingdown.off:coupling.off cgal:pinion.off:pinion.off
  cgal:turbine.off:turbine.off cgal:ellipe0.003.off:ellipsoid.off cgal:diplodocus.off:diplodocus.off
  cgal:homer.off:homer.off cgal:triceratops.off:triceratops.off cgal:dino.off:dino.off cgal:bones.off:bones.off
  cgal:ChineseDragon-10kv.off:dragon.off cgal:mushroom.off:mushroom.off cgal:lion-head.off:lionhead.off
  cgal:mannequin-devil.off:devilmask.off cgal:head.off:head.off cgal:plane.off:cloth.off
  cgal:blobby-shuffled.off:blobbyshuffled.off
  assimp:STL/Wuson.stl:wuson.stl assimp:STL/Spider_binary.stl:spider.stl assimp:STL/3DSMaxExport.STL:maxexport.stl
  assimp:PLY/Wuson.ply:wusonsoup.ply
)
have_all=1
for w in "${wanted[@]}"; do [ -f "$dest/${w##*:}" ] || have_all=0; done
if [ $have_all -eq 1 ]; then echo "fetch_unseen_meshes: data/meshes/unseen is complete"; exit 0; fi

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
if ! ls /var/lib/apt/lists/*_main_binary-* >/dev/null 2>&1; then apt-get update -qq; fi
for p in libcgal-demo assimp-testmodels; do
  apt-get download "$p" 2>&1 | grep -v "^W: Download is performed unsandboxed" || true
  dpkg-deb -x "$(ls ${p}_*.deb)" pkg
done
mkdir -p cgal "$dest"
tar xzf pkg/usr/share/doc/libcgal-dev/data.tar.gz -C cgal data/meshes
for w in "${wanted[@]}"; do
  IFS=: read -r pkg path name <<<"$w"
  if [ "$pkg" = cgal ]; then src="cgal/data/meshes/$path"; else src="pkg/usr/share/assimp/models/$path"; fi
  cp "$src" "$dest/$name.part"
  mv "$dest/$name.part" "$dest/$name"
done
# blobby-shuffled.off has '#' comment lines and blank lines around its OFF header, which the
# OpenMesh reader refuses; the copy here drops them (the geometry is unchanged).
sed -i '/^#/d; /^[[:space:]]*$/d' "$dest/blobbyshuffled.off"
echo "fetch_unseen_meshes: wrote ${#wanted[@]} meshes to data/meshes/unseen"
