#!/usr/bin/env python3
"""The sixteenth probe's scenes (docs/results/probe16/README.md): 13 meshes from libcgal-demo 5.5.1-2
and assimp-testmodels 5.2.5~ds0-1 that no other scene here uses, each scaled to 2.5 units (1.6 to
2.0 in the scenes with two or three) and set on a ground plane, under the tenth probe's four
lights: a spot light from above at 50 degrees (`spot`), a directional light 14 degrees above the
horizon (`grazing`), one straight down (`down`) and a low spot light (`spotlow`); and three scenes
under a point light (`point`, written to a second folder: the sub-grid is refused for a point
light, so they are run without it). Writes SCENE.json files into the folders given (default:
scenes/ and scenes-point/ beside this file). The meshes are read from /tmp/probe9 (README.md here
says how to fetch them); their bounds (after the rotation, and after Assimp's node transforms for
the formats it reads) come from `shadowvol scene --json`, so the binary is needed (--exe).

  python3 docs/results/probe16/make_scenes.py [--exe /tmp/sv16] [OUT_DIR [POINT_OUT_DIR]]
"""
import json
import os
import subprocess
import sys
import tempfile

CGAL = "/tmp/probe9/d/data/meshes/"
ASSIMP = "/tmp/probe9/x/usr/share/assimp/models/"
LIGHTS = {
    "spot": {"type": "spot", "fov": 50, "position": [6.161, 6.749, 5.17], "target": [0, 0.341, 0]},
    "grazing": {"type": "directional", "direction": [0.9703, -0.2419, 0.0]},
    "down": {"type": "directional", "direction": [0, -1, 0]},
    "spotlow": {"type": "spot", "fov": 60, "position": [-5.0, 2.2, 1.5], "target": [0, 0.5, 0]},
    "point": {"type": "point", "position": [2.0, 4.0, 2.5]},
}
# name -> (file, rotate [x, y, z] degrees that stands it up: z-up files are turned to y-up)
MESHES = {
    "handle": (CGAL + "handle.off", [0, 0, 0]),
    "blade": (CGAL + "blade.off", [0, 0, 0]),
    "holes": (CGAL + "holes.off", [0, 0, 0]),
    "relief": (CGAL + "polygon_mesh.off", [-90, 0, 0]),
    "doubletorus": (CGAL + "double-torus-example.off", [0, 0, 0]),
    "thething": (ASSIMP + "Ogre/TheThing/Mesh.mesh.xml", [0, 0, 0]),
    "human": (ASSIMP + "Collada/human.zae", [0, 0, 0]),
    "mrfixit": (ASSIMP + "IQM/mrfixit.iqm", [-90, 0, 0]),
    "yxa": (ASSIMP + "BLEND/yxa_1.blend", [-90, 0, 0]),
    "subdiv": (ASSIMP + "AC/sample_subdiv.ac", [0, 0, 0]),
    "torus": (ASSIMP + "BLEND/TorusLightsCams_250_compressed.blend", [0, 0, 0]),
    "animtest": (ASSIMP + "X/anim_test.x", [0, 0, 0]),
    "molecule": (ASSIMP + "COB/molecule.cob", [0, 0, 0]),
}
SINGLES = [("handle", "spot"), ("blade", "grazing"), ("holes", "down"), ("relief", "grazing"),
           ("thething", "spotlow"), ("human", "spot"), ("mrfixit", "down"), ("yxa", "spot"),
           ("subdiv", "spotlow"), ("torus", "grazing"), ("animtest", "down"), ("molecule", "spot"),
           ("doubletorus", "spotlow")]
GROUPS = [("duo-handle-thething-grazing", [("handle", 2.0, -1.5), ("thething", 2.0, 1.5)], "grazing"),
          ("trio-torus-molecule-mrfixit-spot", [("torus", 1.6, -2.0), ("molecule", 1.6, 0.0), ("mrfixit", 1.6, 2.0)], "spot"),
          ("duo-human-yxa-down", [("human", 1.8, -1.2), ("yxa", 1.8, 1.2)], "down")]
POINTS = [("thething", "point"), ("human", "point"), ("duo-handle-doubletorus-point",
                                                       [("handle", 2.0, -1.5), ("doubletorus", 2.0, 1.5)])]


def bounds(exe, path, rotate):
    """min, max and triangle count of the mesh after `rotate`, as shadowvol loads it."""
    s = {"objects": [{"type": "mesh", "file": path, "transform": {"rotate": rotate}}],
         "light": {"type": "directional", "direction": [0, -1, 0]}, "camera": {"eye": [0, 5, 5], "target": [0, 0, 0]}}
    with tempfile.NamedTemporaryFile("w", suffix=".json", delete=False) as f:
        json.dump(s, f)
    try:
        d = json.loads(subprocess.run([exe, "scene", "--scene", f.name, "--json"], check=True,
                                      capture_output=True, text=True).stdout)
    finally:
        os.unlink(f.name)
    return d["bounds"]["min"], d["bounds"]["max"], d["triangles"]


def placed(exe, name, size, x):
    """The transform that scales the mesh's largest extent to `size` and stands it on y = 0 at (x, 0)."""
    path, rotate = MESHES[name]
    lo, hi, tris = bounds(exe, path, rotate)
    s = size / max(hi[k] - lo[k] for k in range(3))
    t = [x - s * (lo[0] + hi[0]) / 2, -s * lo[1], -s * (lo[2] + hi[2]) / 2]
    return {"scale": round(s, 8), "translate": [round(c, 5) for c in t], "rotate": rotate}, tris


def scene(exe, parts, light):
    objects = [{"type": "plane", "name": "ground", "size": 15 if light == "grazing" else 10}]
    described = []
    for name, size, x in parts:
        transform, tris = placed(exe, name, size, x)
        objects.append({"type": "mesh", "name": name, "file": MESHES[name][0], "transform": transform})
        described.append("%s (%d triangles)" % (MESHES[name][0].split("/tmp/probe9/")[1], tris))
    camera = {"eye": [2.161, 4.558, 7.203], "target": [0, 0.596, 0], "fov": 45, "width": 640, "height": 480}
    if light == "grazing":
        camera = {"eye": [-4.0, 7.5, 8.0], "target": [1.5, 0.6, 0], "fov": 45, "width": 640, "height": 480}
    return {"description": "sixteenth probe (libcgal-demo 5.5.1-2, assimp-testmodels 5.2.5~ds0-1): " +
            ", ".join(described) + "; light " + light, "objects": objects, "light": LIGHTS[light], "camera": camera}


def write(folder, scenes):
    os.makedirs(folder, exist_ok=True)
    for name, s in scenes.items():
        with open(os.path.join(folder, name + ".json"), "w") as f:
            json.dump(s, f, indent=1)
            f.write("\n")
    print("%d scenes in %s" % (len(scenes), folder))


def main():
    args = sys.argv[1:]
    exe = "/tmp/sv16"
    if args[:1] == ["--exe"]:
        exe, args = args[1], args[2:]
    here = os.path.dirname(os.path.abspath(__file__))
    out = args[0] if args else os.path.join(here, "scenes")
    out_point = args[1] if len(args) > 1 else os.path.join(here, "scenes-point")
    scenes = {}
    for name, light in SINGLES:
        scenes[name + "-" + light] = scene(exe, [(name, 2.5, 0.0)], light)
    for name, parts, light in GROUPS:
        scenes[name] = scene(exe, parts, light)
    write(out, scenes)
    points = {}
    for entry in POINTS:
        if isinstance(entry[1], list):
            points[entry[0]] = scene(exe, entry[1], "point")
        else:
            points[entry[0] + "-point"] = scene(exe, [(entry[0], 2.5, 0.0)], "point")
    write(out_point, points)


if __name__ == "__main__":
    main()
