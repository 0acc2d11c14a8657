#!/usr/bin/env python3
# Generates hostile / heavy scenes and mesh files for probe14/A. Run in /tmp/probe14/A.
import json, os, struct
os.makedirs('s', exist_ok=True)
def scene(name, objs, light=None, camera=None):
    d = {"objects": objs,
         "light": light or {"type": "spot", "position": [3, 9, 2], "target": [0, 0, 0], "fov": 55},
         "camera": camera or {"eye": [0, 6, 11], "target": [0, 1, 0], "fov": 45, "width": 320, "height": 240}}
    json.dump(d, open(f's/{name}.json', 'w'), indent=1)
G = {"type": "plane", "name": "ground", "size": 20}
scene('plane_sub4096', [{"type": "plane", "size": 20, "subdivisions": 4096}])
scene('plane_sub5000', [{"type": "plane", "size": 20, "subdivisions": 5000}])
scene('plane_sub100000', [{"type": "plane", "size": 20, "subdivisions": 100000}])
scene('sphere_detail8', [G, {"type": "sphere", "detail": 8, "transform": {"translate": [0, 2, 0]}}])
scene('sphere_uv_huge', [G, {"type": "sphere", "tessellation": "uv", "segments": 100000, "rings": 100000, "transform": {"translate": [0, 2, 0]}}])
scene('sphere_uv_big', [G, {"type": "sphere", "tessellation": "uv", "segments": 5000, "rings": 5000, "transform": {"translate": [0, 2, 0]}}])
scene('hemi_huge', [G, {"type": "hemisphere", "segments": 1000000, "rings": 1000000}])
scene('cyl_huge', [G, {"type": "cylinder", "segments": 2000000000, "transform": {"translate": [0, 1, 0]}}])
scene('cyl_big', [G, {"type": "cylinder", "segments": 20000000, "transform": {"translate": [0, 1, 0]}}])
scene('tree_detail8', [G, {"type": "tree", "detail": 8}])
scene('tree_detail7', [G, {"type": "tree", "detail": 7}])
scene('many_detail7', [G] + [{"type": "sphere", "detail": 7, "transform": {"translate": [i*2.5-5, 2, 0]}} for i in range(5)])
scene('many_sub4096', [{"type": "plane", "size": 20, "subdivisions": 4096, "transform": {"translate": [0, i*0.01, 0]}} for i in range(3)])
# odd scenes for JSON / verdict checks
scene('empty_objs', [])
scene('only_ground', [G])
scene('behind_light', [G, {"type": "sphere", "transform": {"translate": [6, 13, 4]}}])  # beyond the light, away from target
scene('light_inside', [G, {"type": "box", "size": 30, "transform": {"translate": [0, 5, 0]}}])
scene('camera_inside', [G, {"type": "sphere", "radius": 3, "transform": {"translate": [0, 6, 11]}}])
scene('all_shadow', [G, {"type": "plane", "size": 40, "transform": {"translate": [0, 5, 0], "rotate": [180, 0, 0]}}, {"type": "plane", "size": 40, "transform": {"translate": [0, 5, 0]}}])
scene('nothing_shadow', [G])
scene('tiny_obj', [G, {"type": "sphere", "radius": 0.001, "transform": {"translate": [0, 2, 0]}}])
scene('light_in_room', [{"type": "plane", "size": 8}, {"type": "box", "size": 2, "transform": {"translate": [0, 1, 0]}},
      {"type": "mesh", "file": "room_in.obj"}],
      light={"type": "spot", "position": [3, 9, 2], "target": [0, 0, 0], "fov": 55},
      camera={"eye": [0, 6, 11], "target": [0, 1, 0], "fov": 45, "width": 320, "height": 240})
# 300 stacked thin boxes over the ground: the silhouette method's stencil count under them is 300 (> 255, an 8-bit stencil)
scene('stack300', [G] + [{"type": "box", "size": [2, 0.01, 2], "transform": {"translate": [0, 1 + 0.02*i, 0]}} for i in range(300)])
scene('stack256', [G] + [{"type": "box", "size": [2, 0.01, 2], "transform": {"translate": [0, 1 + 0.02*i, 0]}} for i in range(256)])
scene('stack255', [G] + [{"type": "box", "size": [2, 0.01, 2], "transform": {"translate": [0, 1 + 0.02*i, 0]}} for i in range(255)])
