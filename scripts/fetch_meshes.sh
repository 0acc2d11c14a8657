#!/usr/bin/env bash
# Fetches real meshes nobody here wrote from Debian's libcgal-demo package (its data.tar.gz)
# into data/meshes/ (git-ignored). Safe to run again: it does nothing when the meshes are there.
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
dest="$top/data/meshes"
wanted=(bunny00.off:bunny.off armadillo.off:armadillo.off fandisk.off:fandisk.off elephant.off:elephant.off
        lion-head.off:lion-head.off)

have_all=1
for w in "${wanted[@]}"; do [ -f "$dest/${w#*:}" ] || have_all=0; done
if [ $have_all -eq 1 ]; then echo "fetch_meshes: data/meshes is complete"; exit 0; fi

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
if ! ls /var/lib/apt/lists/*_main_binary-* >/dev/null 2>&1; then apt-get update -qq; fi
# apt-get download as root warns that _apt cannot write here; the download itself works.
apt-get download libcgal-demo 2>&1 | grep -v "^W: Download is performed unsandboxed" || true
deb=$(ls libcgal-demo_*.deb)
dpkg-deb -x "$deb" pkg
data=pkg/usr/share/doc/libcgal-dev/data.tar.gz
members=()
for w in "${wanted[@]}"; do members+=("data/meshes/${w%%:*}"); done
tar xzf "$data" "${members[@]}"
mkdir -p "$dest"
for w in "${wanted[@]}"; do
  cp "data/meshes/${w%%:*}" "$dest/${w#*:}.part"
  mv "$dest/${w#*:}.part" "$dest/${w#*:}"
done
echo "fetch_meshes: wrote ${#wanted[@]} meshes to data/meshes (from $deb)"
