#!/bin/sh
# C++ API: buildVolume on a DepthMap whose matrices a caller filled (NaN / singular) returns an
# all-NaN mesh without an error; far <= near, NaN far, or a wrong depth.size() abort the process
# (SV_CHECK -> std::abort) instead of throwing InputError.
B=/work/main/build; cd /tmp/probe21/repro
g++ -std=c++20 -O1 -I/work/main/lib/include -I$B/generated cpp_unchecked_depthmap.cpp -o /tmp/probe21/cpp/unchecked \
  $B/lib/src/embree/libshadowvol_embree.a $B/lib/src/core/libshadowvol_core.a \
  /usr/lib/x86_64-linux-gnu/libOpenMeshCore.so.9.0 /usr/lib/x86_64-linux-gnu/libgmpxx.so /usr/lib/x86_64-linux-gnu/libmpfr.so \
  /usr/lib/x86_64-linux-gnu/libgmp.so /usr/lib/x86_64-linux-gnu/libstb.so /usr/lib/x86_64-linux-gnu/libassimp.so \
  /usr/lib/x86_64-linux-gnu/libtbb.so.12.8 /usr/lib/x86_64-linux-gnu/libembree3.so.3.13.5 2>&1 | grep -i error
for w in nanview singularproj scaledview pointtype nanfar farltnear sizemismatch; do
  /tmp/probe21/cpp/unchecked $w; echo "  [$w: exit $?]"
done
