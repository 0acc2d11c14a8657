#!/usr/bin/env python3
# Writes chk/chkN.pfm (+ .json): an N x N depth map of the default scene's light where every other texel of every
# other row holds a hit (isolated one-texel occluders: worst case for the volume's size). Usage: gen_checker.py N [N...]
import shadowvol as sv, numpy as np, sys, os
os.makedirs('chk', exist_ok=True)
d = sv.capture_depth(sv.default_scene(), 64, 64)
for n in map(int, sys.argv[1:]):
    a = np.full((n, n), np.inf, np.float32); a[::2, ::2] = d.far * 0.8
    sv.DepthMap.from_array(a, d.light_view, d.light_projection, d.near, d.far, light=d.light).save(f'chk/chk{n}.pfm')
