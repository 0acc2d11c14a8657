#!/usr/bin/env python3
"""Second batch of odd mesh files and scenes, into /tmp/probe13/A/gen2/ (run: python3 gen2.py)."""
import json, os, struct, sys
sys.path.insert(0, "/tmp/probe13/A")
OUT = "/tmp/probe13/A/gen2"
os.makedirs(OUT, exist_ok=True)

CUBE_V = [(-.5, 0, -.5), (.5, 0, -.5), (.5, 0, .5), (-.5, 0, .5),
          (-.5, 1, -.5), (.5, 1, -.5), (.5, 1, .5), (-.5, 1, .5)]
CUBE_Q = [(0, 1, 2, 3), (4, 7, 6, 5), (0, 4, 5, 1), (1, 5, 6, 2), (2, 6, 7, 3), (3, 7, 4, 0)]


def w(name, data):
    with open(os.path.join(OUT, name), "wb" if isinstance(data, bytes) else "w") as f:
        f.write(data)


def objtext(V, F):
    return "".join("v %r %r %r\n" % v for v in V) + "".join("f %s\n" % " ".join(str(i + 1) for i in f) for f in F)


# a closed cube whose quads each repeat a corner (as some exporters write): "f 1 2 3 3 4"
w("cube_repeat_corner.obj", objtext(CUBE_V, [(q[0], q[1], q[2], q[2], q[3]) for q in CUBE_Q]))
# the same cube written with quads and an extra zero-area sliver triangle on an edge midpoint (T-junction fixed)
# ASCII PLY with one value too many on each vertex line (header declares x y z)
s = "ply\nformat ascii 1.0\nelement vertex 8\nproperty float x\nproperty float y\nproperty float z\n" \
    "element face 6\nproperty list uchar int vertex_indices\nend_header\n"
w("cube_extra_col.ply", s + "".join("%r %r %r 1\n" % v for v in CUBE_V) +
  "".join("4 %d %d %d %d\n" % q for q in CUBE_Q))
# ASCII PLY, a vertex line missing its z (the next line's x is taken)
w("cube_missing_z.ply", s + "".join(("%r %r\n" % v[:2]) if k == 3 else ("%r %r %r\n" % v) for k, v in enumerate(CUBE_V)) +
  "".join("4 %d %d %d %d\n" % q for q in CUBE_Q) + "0\n")
# binary PLY with a CRLF header
hdr = ("ply\r\nformat binary_little_endian 1.0\r\nelement vertex 8\r\nproperty float x\r\nproperty float y\r\n"
       "property float z\r\nelement face 6\r\nproperty list uchar int vertex_indices\r\nend_header\r\n").encode()
body = b"".join(struct.pack("<3f", *v) for v in CUBE_V) + b"".join(struct.pack("<B4i", 4, *q) for q in CUBE_Q)
w("cube_crlf_bin.ply", hdr + body)
# binary PLY whose first body byte is a newline character (x of vertex 0 = float with low byte 0x0a)
V0 = list(CUBE_V)
x0 = struct.unpack("<f", b"\x0a" + struct.pack("<f", -0.5)[1:])[0]
V0[0] = (x0, 0.0, -0.5)
hdr2 = ("ply\nformat binary_little_endian 1.0\nelement vertex 8\nproperty float x\nproperty float y\n"
        "property float z\nelement face 6\nproperty list uchar int vertex_indices\nend_header\n").encode()
w("cube_body_starts_lf.ply", hdr2 + b"".join(struct.pack("<3f", *v) for v in V0) +
  b"".join(struct.pack("<B4i", 4, *q) for q in CUBE_Q))
# the same, header ending in CR LF and first body byte CR? (0x0d)
x1 = struct.unpack("<f", b"\x0d" + struct.pack("<f", -0.5)[1:])[0]
V1 = list(CUBE_V); V1[0] = (x1, 0.0, -0.5)
w("cube_body_starts_cr.ply", hdr2 + b"".join(struct.pack("<3f", *v) for v in V1) +
  b"".join(struct.pack("<B4i", 4, *q) for q in CUBE_Q))
# "ply" magic line with trailing space
w("cube_magic_space.ply", "ply \n" + s.split("\n", 1)[1] + "".join("%r %r %r\n" % v for v in CUBE_V) +
  "".join("4 %d %d %d %d\n" % q for q in CUBE_Q))
# OFF with 9 declared vertices but 8 given (the first face line read as a vertex)
w("cube_off_count.off", "OFF\n9 6 0\n" + "".join("%r %r %r\n" % v for v in CUBE_V) +
  "".join("4 %d %d %d %d\n" % q for q in CUBE_Q))
# OBJ in UTF-16 LE with BOM
w("cube_utf16le.obj", ("\ufeff" + objtext(CUBE_V, CUBE_Q)).encode("utf-16-le"))
# OBJ with upper-case file extension
w("cube_upper_ext.OBJ", objtext(CUBE_V, CUBE_Q))
# OBJ whose faces use a polygon with a vertex index repeated non-adjacent (bow tie) - self-touching
# two cubes sharing one vertex (pinched, non-manifold vertex) in one file
V2 = CUBE_V + [(x + 1, y + 1, z + 1) for x, y, z in CUBE_V[1:]]
# second cube: vertex 0 of it is shared: CUBE_V[6] == (0.5, 1, 0.5) equals (x+1,y+1,z+1) of CUBE_V[0]
V2 = CUBE_V + [(x + 1, y + 1, z + 1) for x, y, z in CUBE_V]
Q2 = CUBE_Q + [tuple(i + 8 for i in q) for q in CUBE_Q]
# weld the coincident vertex (index 8 == (0.5, 1, 0.5) == index 6)
Q2 = [tuple(6 if i == 8 else i for i in q) for q in Q2]
w("two_cubes_pinched.obj", objtext(V2, Q2))
# a cube with a cube-shaped cavity, the cavity wound outward too (wrong: should face inward)
VI = [(x * 0.4, y * 0.4 + 0.3, z * 0.4) for x, y, z in CUBE_V]
w("hollow_cube_bad_cavity.obj", objtext(CUBE_V + VI, CUBE_Q + [tuple(i + 8 for i in q) for q in CUBE_Q]))
# three nested cubes (solid, cavity, island), all wound outward in the file
V3 = CUBE_V + VI + [(x * 0.15, y * 0.15 + 0.425, z * 0.15) for x, y, z in CUBE_V]
w("nested3.obj", objtext(V3, CUBE_Q + [tuple(i + 8 for i in q) for q in CUBE_Q] + [tuple(i + 16 for i in q) for q in CUBE_Q]))

SPOT = {"type": "spot", "position": [2.5, 7, 1.5], "target": [0, 0, 0], "fov": 60}
DOWN = {"type": "directional", "direction": [0, -1, 0]}
GRAZE = {"type": "directional", "direction": [-1, -0.2, -0.3]}
POINT = {"type": "point", "position": [1.2, 4, 0.8]}
CAM = {"eye": [0, 5, 9], "target": [0, 0.5, 0], "width": 320, "height": 240}


def scene(name, objs, light=SPOT, cam=CAM):
    with open(os.path.join(OUT, name + ".json"), "w") as f:
        json.dump({"objects": [{"type": "plane", "name": "ground", "size": 8}] + objs, "light": light, "camera": cam}, f,
                  indent=1)


def mesh(file, **tr):
    return {"type": "mesh", "file": file, "transform": tr} if tr else {"type": "mesh", "file": file}


for f in sorted(os.listdir(OUT)):
    if not f.endswith(".json"):
        scene("g_" + f.replace(".", "_"), [mesh(f, translate=[0, 0.3, 0])])
D = "/tmp/probe9/d/data/meshes/"
scene("r_shuffled_spot", [mesh(D + "tet-shuffled.off", translate=[-1.5, 0.5, 0]),
                          mesh(D + "cube4-shuffled.off", scale=0.5, translate=[1.5, 0.5, 0]),
                          mesh(D + "negative.off", scale=0.5, translate=[0, 1.5, 1])])
scene("r_spheres3_down", [mesh(D + "sphere.off", translate=[-1.5, 1, 0]), mesh(D + "sphere.ply", translate=[0, 1, 0]),
                          mesh(D + "sphere.stl", translate=[1.5, 1, 0])], DOWN)
scene("r_cheese_point", [mesh(D + "cheese.off", scale=20, translate=[0, 0.2, 0]),
                         mesh(D + "degtri_sliding.off", scale=0.5, translate=[1.5, 1, 0])], POINT)
scene("r_nested3_graze", [mesh("nested3.obj", translate=[0, 0.3, 0]), mesh("hollow_cube_bad_cavity.obj", translate=[2, 0.3, 0]),
                          mesh("two_cubes_pinched.obj", translate=[-2, 0.3, 0])], GRAZE)
print("gen2 written")
