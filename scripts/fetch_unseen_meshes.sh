#!/usr/bin/env bash
# Fetches the meshes of the evaluation scenes in data/scenes/unseen/ (meshes the method was not
# developed on) from Debian's libcgal-demo and assimp-testmodels packages into the git-ignored
# data/meshes/unseen/. Safe to run again. Not needed by the tests; used by scripts/refine_eval.py.
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
exec bash "$top/scripts/fetch_debian_meshes.sh" fetch_unseen_meshes "$top/data/meshes/unseen" \
  cgal:cow.off:cow.off cgal:knot1.off:knot.off cgal:couplingdown.off:coupling.off cgal:pinion.off:pinion.off \
  cgal:turbine.off:turbine.off cgal:ellipe0.003.off:ellipsoid.off cgal:diplodocus.off:diplodocus.off \
  cgal:homer.off:homer.off cgal:triceratops.off:triceratops.off cgal:dino.off:dino.off cgal:bones.off:bones.off \
  cgal:ChineseDragon-10kv.off:dragon.off cgal:mushroom.off:mushroom.off cgal:lion-head.off:lionhead.off \
  cgal:mannequin-devil.off:devilmask.off cgal:head.off:head.off cgal:plane.off:cloth.off \
  cgal:blobby-shuffled.off:blobbyshuffled.off \
  assimp:STL/Wuson.stl:wuson.stl assimp:STL/Spider_binary.stl:spider.stl assimp:STL/3DSMaxExport.STL:maxexport.stl \
  assimp:PLY/Wuson.ply:wusonsoup.ply
