#!/usr/bin/env bash
# Copies meshes out of Debian's libcgal-demo and assimp-testmodels packages (apt-get download, no
# install) into a git-ignored folder. The one implementation behind fetch_meshes.sh and
# fetch_unseen_meshes.sh. Safe to run again: it does nothing when every mesh is there.
#   fetch_debian_meshes.sh NAME DEST ENTRY...
# NAME: what to call itself in messages; DEST: the folder; ENTRY: package:path:file, package
# "cgal" (a path under libcgal-demo's data/meshes/) or "assimp" (a path under assimp-testmodels'
# models/), file the name in DEST. Every file is written as file.part and renamed when complete.
set -euo pipefail
name=$1 dest=$2
shift 2
wanted=("$@")
have_all=1
for w in "${wanted[@]}"; do [ -f "$dest/${w##*:}" ] || have_all=0; done
if [ $have_all -eq 1 ]; then echo "$name: $dest is complete"; exit 0; fi

packages=()
for w in "${wanted[@]}"; do
  case "${w%%:*}" in
    cgal) [[ " ${packages[*]-} " == *" libcgal-demo "* ]] || packages+=(libcgal-demo) ;;
    assimp) [[ " ${packages[*]-} " == *" assimp-testmodels "* ]] || packages+=(assimp-testmodels) ;;
    *) echo "$name: unknown package in '$w' (cgal or assimp)" >&2; exit 2 ;;
  esac
done
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
if ! ls /var/lib/apt/lists/*_main_binary-* >/dev/null 2>&1; then apt-get update -qq; fi
for p in "${packages[@]}"; do
  # apt-get download as root warns that _apt cannot write here; the download itself works.
  apt-get download "$p" 2>&1 | grep -v "^W: Download is performed unsandboxed" || true
  dpkg-deb -x "$(ls "${p}"_*.deb)" pkg
done
if [[ " ${packages[*]} " == *" libcgal-demo "* ]]; then
  mkdir -p cgal
  tar xzf pkg/usr/share/doc/libcgal-dev/data.tar.gz -C cgal data/meshes
fi
mkdir -p "$dest"
for w in "${wanted[@]}"; do
  IFS=: read -r pkg path file <<<"$w"
  if [ "$pkg" = cgal ]; then src="cgal/data/meshes/$path"; else src="pkg/usr/share/assimp/models/$path"; fi
  cp "$src" "$dest/$file.part"
  mv "$dest/$file.part" "$dest/$file"
done
echo "$name: wrote ${#wanted[@]} meshes to $dest (from ${packages[*]})"
