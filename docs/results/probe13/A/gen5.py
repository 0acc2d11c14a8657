#!/usr/bin/env python3
"""UTF-8 byte-order mark before each text format (gen5/): README says it is skipped."""
import os
OUT = "/tmp/probe13/A/gen5"; os.makedirs(OUT, exist_ok=True)
G = "/tmp/probe13/A/gen/"
for f in ("cube.obj", "cube.off", "cube_ascii.ply", "cube_ascii.stl"):
    open(OUT + "/bom_" + f, "wb").write(b"\xef\xbb\xbf" + open(G + f, "rb").read())
print("gen5 written")

# a PLY holding its triangles as a tristrips element (no face element), and a text file that is no OBJ
open(OUT + "/tristrip.ply", "w").write(
    "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
    "element tristrips 1\nproperty list int int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n4 0 1 2 3\n")
open(OUT + "/hello.obj", "w").write("hello world\n")
print("gen5 tristrip/hello written")
