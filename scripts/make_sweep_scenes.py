#!/usr/bin/env python3
"""Writes data/scenes/sweep-*.json: the polygon-sweep family (the thesis's Table 1 series).

Same layout at every size: the default scene's ground, light and camera, with a UV sphere whose
tessellation sets the triangle count: 2 (ground) + 2 * segments * (rings - 1), segments = 2 (rings - 1).
"""
import json
import math
import pathlib

TARGETS = [500, 2000, 8000, 32000, 128000, 200000, 800000]
out = pathlib.Path(__file__).resolve().parent.parent / "data" / "scenes"

for target in TARGETS:
    k = max(2, round(math.sqrt((target - 2) / 4)))  # rings - 1
    rings, segments = k + 1, 2 * k
    total = 2 + 2 * segments * (rings - 1)
    scene = {
        "description": f"polygon sweep: nominal {target} triangles, actual {total}",
        "objects": [
            {"type": "plane", "name": "ground", "size": 20},
            {"type": "sphere", "name": "sphere", "tessellation": "uv", "segments": segments, "rings": rings,
             "transform": {"translate": [0, 2, 0]}},
        ],
        "light": {"type": "spot", "position": [3, 9, 2], "target": [-0.3, 0, -0.2], "fov": 55},
        "camera": {"eye": [0, 6, 11], "target": [0, 1, 0], "fov": 45, "width": 640, "height": 480},
    }
    path = out / f"sweep-{target:06d}.json"
    path.write_text(json.dumps(scene, indent=2) + "\n")
    print(f"{path.name}: {total} triangles")
