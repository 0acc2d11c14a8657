#!/usr/bin/env bash
# Fetches real meshes nobody here wrote from Debian's libcgal-demo package into data/meshes/
# (git-ignored), for the shipped scenes and the tests. Safe to run again.
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
exec bash "$top/scripts/fetch_debian_meshes.sh" fetch_meshes "$top/data/meshes" \
  cgal:bunny00.off:bunny.off cgal:armadillo.off:armadillo.off cgal:fandisk.off:fandisk.off \
  cgal:elephant.off:elephant.off cgal:lion-head.off:lion-head.off
