#!/usr/bin/env python3
"""Writes scenes into /tmp/probe13/A/gen/ for the meshes gen.py wrote (run after gen.py)."""
import json, os, sys

OUT = "/tmp/probe13/A/gen"
DATA = "/tmp/probe9/d/data/meshes"
AS = "/tmp/probe9/x/usr/share/assimp/models"

SPOT = {"type": "spot", "position": [2.5, 7, 1.5], "target": [0, 0, 0], "fov": 60}
DOWN = {"type": "directional", "direction": [0, -1, 0]}
GRAZE = {"type": "directional", "direction": [-1, -0.2, -0.3]}
POINT = {"type": "point", "position": [1.2, 4, 0.8]}
CAM = {"eye": [0, 5, 9], "target": [0, 0.5, 0], "width": 320, "height": 240}


def scene(name, objs, light=SPOT, cam=CAM, ground=8):
    o = ([{"type": "plane", "name": "ground", "size": ground}] if ground else []) + objs
    with open(os.path.join(OUT, name + ".json"), "w") as f:
        json.dump({"objects": o, "light": light, "camera": cam}, f, indent=1)


def mesh(file, name=None, **tr):
    d = {"type": "mesh", "file": file}
    if name:
        d["name"] = name
    if tr:
        d["transform"] = tr
    return d


# one scene per cube variant, same light and camera: all should load the same 14 triangles
for f in sorted(os.listdir(OUT)):
    if f.startswith("cube") and not f.endswith(".json") and "1e" not in f and "tiny" not in f:
        scene("v_" + f.replace(".", "_"), [mesh(f, translate=[0, 0.3, 0])])

# L prism, fanned by the reader vs triangulated correctly, lit straight down
for f in ("L_fan.obj", "L_fan.off", "L_fan.ply", "L_tri.obj"):
    scene("L_" + f.replace(".", "_"), [mesh(f, translate=[0, 2.0, 0])], light=DOWN,
          cam={"eye": [6, 3, 6], "target": [0.5, 0, 0.5], "width": 320, "height": 240})

# real meshes in odd formats, 2-3 per scene, with spot / straight down / grazing / point lights
combos = {
    "c_nested_glb_spot": ([mesh("nested.gltf", translate=[0, 0.6, 0])], SPOT),
    "c_nodes_down": ([mesh("cubes_nodes.gltf", scale=0.6, translate=[0, 0.5, 0])], DOWN),
    "c_nodes_graze": ([mesh("cubes_nodes.gltf", scale=0.6, translate=[0, 0.2, 0])], GRAZE),
    "c_cgal_trio_point": ([mesh(DATA + "/cube_poly.off", scale=0.5, translate=[-1.5, 1, 0]),
                           mesh(DATA + "/corner_poly.off", scale=0.5, translate=[1.5, 1, 0]),
                           mesh(DATA + "/blobby_3cc.off", scale=0.5, translate=[0, 1.5, 1])], POINT),
    "c_cgal_trio_graze": ([mesh(DATA + "/cube_poly.off", scale=0.5, translate=[-1.5, 1, 0]),
                           mesh(DATA + "/corner_poly.off", scale=0.5, translate=[1.5, 1, 0]),
                           mesh(DATA + "/blobby_3cc.off", scale=0.5, translate=[0, 1.5, 1])], GRAZE),
    "c_colored_tetra_b9_spot": ([mesh(DATA + "/colored_tetra.ply", translate=[-1, 1, 0]),
                                 mesh(DATA + "/b9_mesh.off", scale=0.02, translate=[1, 1, 0])], SPOT),
    "c_fbx_dae_down": ([mesh(AS + "/FBX/cubes_with_names.fbx", scale=0.01, translate=[-1.5, 1, 0]),
                        mesh(AS + "/Collada/teapot_instancenodes.DAE", scale=0.02, translate=[1.5, 0.5, 0])], DOWN),
    "c_x_3ds_spot": ([mesh(AS + "/X/test_cube_binary.x", scale=0.3, translate=[-1.5, 1, 0]),
                      mesh(AS + "/3DS/RotatingCube.3DS", scale=0.02, translate=[1.5, 1, 0])], SPOT),
    "c_far_ply_1e6": ([mesh("cube_at_1e6.ply", translate=[-1e6, 0.3, -1e6])], SPOT),
    "c_far_ply_1e6_d": ([mesh("cube_at_1e6_d.ply", translate=[-1e6, 0.3, -1e6])], SPOT),
    "c_far_obj_1e7": ([mesh("cube_at_1e7.obj", translate=[-1e7, -5e6 + 0.3, 1e7])], SPOT),
    "c_tiny": ([mesh("cube_tiny.obj", scale=1e5, translate=[0, 0.3, 0])], SPOT),
    "c_tiny_far": ([mesh("cube_tiny_far.obj", scale=1e5, translate=[-3e5, 0.3, 0])], SPOT),
    "c_gltf_node_1e7": ([mesh("cube_node_1e7.gltf", translate=[-1e7, 0.3, -1e7])], SPOT),
    "c_gltf_stored_1e7": ([mesh("cube_stored_1e7_node_back.gltf", translate=[0, 0.3, 0])], SPOT),
    "c_mirror_matrix_graze": ([mesh("cube_mirror_matrix.gltf", translate=[0, 0.3, 0]),
                               mesh("cube_inside_out.obj", translate=[2, 0.3, 0]),
                               mesh("cube_junk.obj", translate=[-2, 0.3, 0])], GRAZE),
}
for k, (objs, light) in combos.items():
    scene(k, objs, light)
print("scenes written")

# stray vertex far away: same scene as the plain cube, straight-down light
scene("s_stray_down", [mesh("cube_stray.obj", translate=[0, 0.3, 0])], DOWN)
scene("s_plain_down", [mesh("cube.obj", translate=[0, 0.3, 0])], DOWN)
scene("s_stray_spot", [mesh("cube_stray.obj", translate=[0, 0.3, 0])], SPOT)
scene("s_plain_spot", [mesh("cube.obj", translate=[0, 0.3, 0])], SPOT)
print("stray scenes written")
