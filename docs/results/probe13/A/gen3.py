#!/usr/bin/env python3
"""Follow-ups: the pinched two cubes against the same cubes unpinched, and the upper cube alone (gen3/)."""
import json, os
OUT = "/tmp/probe13/A/gen3"; os.makedirs(OUT, exist_ok=True)
CUBE_V = [(-.5, 0, -.5), (.5, 0, -.5), (.5, 0, .5), (-.5, 0, .5), (-.5, 1, -.5), (.5, 1, -.5), (.5, 1, .5), (-.5, 1, .5)]
CUBE_Q = [(0, 1, 2, 3), (4, 7, 6, 5), (0, 4, 5, 1), (1, 5, 6, 2), (2, 6, 7, 3), (3, 7, 4, 0)]
def objtext(V, F):
    return "".join("v %r %r %r\n" % v for v in V) + "".join("f %s\n" % " ".join(str(i + 1) for i in f) for f in F)
def two(gap):
    V = CUBE_V + [(x + 1 + gap, y + 1 + gap, z + 1 + gap) for x, y, z in CUBE_V]
    return objtext(V, CUBE_Q + [tuple(i + 8 for i in q) for q in CUBE_Q])
open(OUT + "/two_apart.obj", "w").write(two(0.0))        # touching at a vertex, not welded (two parts)
open(OUT + "/two_gap.obj", "w").write(two(0.05))
open(OUT + "/upper_only.obj", "w").write(objtext([(x + 1, y + 1, z + 1) for x, y, z in CUBE_V], CUBE_Q))
SPOT = {"type": "spot", "position": [2.5, 7, 1.5], "target": [0, 0, 0], "fov": 60}
CAM = {"eye": [0, 5, 9], "target": [0, 0.5, 0], "width": 320, "height": 240}
for f in ("two_apart.obj", "two_gap.obj", "upper_only.obj"):
    json.dump({"objects": [{"type": "plane", "name": "ground", "size": 8},
                           {"type": "mesh", "file": f, "transform": {"translate": [0, 0.3, 0]}}],
               "light": SPOT, "camera": CAM}, open(OUT + "/h_" + f.replace(".", "_") + ".json", "w"), indent=1)
print("gen3 written")

# ASCII PLY whose vertex 3 line lacks z and vertex 4 line has one value too many: every line is
# malformed for a line-per-element format, yet the token counts add up
s = "ply\nformat ascii 1.0\nelement vertex 8\nproperty float x\nproperty float y\nproperty float z\n" \
    "element face 6\nproperty list uchar int vertex_indices\nend_header\n"
lines = []
for k, v in enumerate(CUBE_V):
    if k == 3:
        lines.append("%r %r" % v[:2])
    elif k == 4:
        lines.append("%r %r %r 9.0" % v)
    else:
        lines.append("%r %r %r" % v)
open(OUT + "/cube_shifted.ply", "w").write(s + "\n".join(lines) + "\n" + "".join("4 %d %d %d %d\n" % q for q in CUBE_Q))
# the same cube as an OFF whose vertex count says 7 and whose face count says 7 (a vertex line read as a face?)
print("gen3 shifted written")
