#!/usr/bin/env python3
"""The tenth probe's scenes (docs/results/probe10/README.md): meshes from libcgal-demo 5.5.1-2 that no
other scene here uses, each scaled to 2.5 units (1.6 to 2.0 in the scenes with two or three) and
set on a ground plane, under four lights: a spot light from above at 50 degrees (`spot`), a
directional light 14 degrees above the horizon (`grazing`), one straight down (`down`) and a low
spot light (`spotlow`). Writes SCENE.json files into the folder given (default: scenes/ beside
this file); the meshes are read from /tmp/probe9 (README.md says how to fetch them). Stdlib only.

  python3 docs/results/probe10/make_scenes.py [OUT_DIR]
"""
import json
import math
import os
import sys

MESHES = "/tmp/probe9/d/data/meshes/"
LIGHTS = {
    "spot": {"type": "spot", "fov": 50, "position": [6.161, 6.749, 5.17], "target": [0, 0.341, 0]},
    "grazing": {"type": "directional", "direction": [0.9703, -0.2419, 0.0]},
    "down": {"type": "directional", "direction": [0, -1, 0]},
    "spotlow": {"type": "spot", "fov": 60, "position": [-5.0, 2.2, 1.5], "target": [0, 0.5, 0]},
}
SINGLES = [("camel.off", "spot"), ("elk.off", "grazing"), ("man.off", "spotlow"), ("bear.off", "down"),
           ("rotor.off", "spot"), ("anchor.off", "grazing"), ("femur.off", "spot", [0, 0, 90]),
           ("helmet.off", "spotlow"), ("dragknob.off", "down"), ("ChineseDragon-10kv.off", "spot"),
           ("3torus.off", "grazing"), ("cactus.off", "spot"), ("tripod.off", "down"), ("eight.off", "spotlow"),
           ("elephant.off", "grazing"), ("mannequin-devil.off", "spot")]
GROUPS = [("duo-camel-bear-grazing", [("camel.off", 2.0, [0, 0, 0], -1.5), ("bear.off", 2.0, [0, 0, 0], 1.5)], "grazing"),
          ("trio-rotor-femur-man-spot", [("rotor.off", 1.6, [0, 0, 0], -2.0), ("femur.off", 1.6, [0, 0, 90], 0.0),
                                         ("man.off", 1.6, [0, 0, 0], 2.0)], "spot"),
          ("duo-helmet-cactus-down", [("helmet.off", 1.8, [0, 0, 0], -1.2), ("cactus.off", 1.8, [0, 0, 0], 1.2)], "down")]


def read_off(path):
    """Vertices and face count of an OFF file (comments and blank lines skipped)."""
    lines = [l.split("#")[0].strip() for l in open(path)]
    lines = [l for l in lines if l]
    rest, i = lines[0][lines[0].index("OFF") + 3:].split(), 1
    if not rest:
        rest, i = lines[1].split(), 2
    nv, nf = int(rest[0]), int(rest[1])
    return [tuple(map(float, lines[i + k].split()[:3])) for k in range(nv)], nf


def rotated(v, degrees):
    """v rotated about x, then y, then z (the scene format's order of `rotate`)."""
    x, y, z = v
    for axis, deg in zip("xyz", degrees):
        c, s = math.cos(math.radians(deg)), math.sin(math.radians(deg))
        if axis == "x":
            y, z = c * y - s * z, s * y + c * z
        elif axis == "y":
            x, z = c * x + s * z, -s * x + c * z
        else:
            x, y = c * x - s * y, s * x + c * y
    return x, y, z


def placed(mesh, size, rotate, x):
    """The transform that scales the mesh's largest extent to `size` and stands it on y = 0 at (x, 0)."""
    vs, nf = read_off(MESHES + mesh)
    rv = [rotated(v, rotate) for v in vs]
    lo = [min(v[k] for v in rv) for k in range(3)]
    hi = [max(v[k] for v in rv) for k in range(3)]
    s = size / max(hi[k] - lo[k] for k in range(3))
    t = [x - s * (lo[0] + hi[0]) / 2, -s * lo[1], -s * (lo[2] + hi[2]) / 2]
    return {"scale": round(s, 6), "translate": [round(c, 5) for c in t], "rotate": rotate}, nf


def scene(parts, light):
    objects = [{"type": "plane", "name": "ground", "size": 15 if light == "grazing" else 10}]
    described = []
    for mesh, size, rotate, x in parts:
        transform, faces = placed(mesh, size, rotate, x)
        objects.append({"type": "mesh", "name": os.path.splitext(mesh)[0].replace("-", "_"),
                        "file": MESHES + mesh, "transform": transform})
        described.append("%s (%d faces)" % (mesh, faces))
    camera = {"eye": [2.161, 4.558, 7.203], "target": [0, 0.596, 0], "fov": 45, "width": 640, "height": 480}
    if light == "grazing":
        camera = {"eye": [-4.0, 7.5, 8.0], "target": [1.5, 0.6, 0], "fov": 45, "width": 640, "height": 480}
    return {"description": "tenth probe (libcgal-demo 5.5.1-2 data/meshes): " + ", ".join(described) +
            "; light " + light, "objects": objects, "light": LIGHTS[light], "camera": camera}


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(os.path.abspath(__file__)), "scenes")
    os.makedirs(out, exist_ok=True)
    scenes = {}
    for entry in SINGLES:
        mesh, light = entry[0], entry[1]
        rotate = entry[2] if len(entry) > 2 else [0, 0, 0]
        name = os.path.splitext(mesh)[0].lower().replace("_", "-") + "-" + light
        scenes[name] = scene([(mesh, 2.5, rotate, 0.0)], light)
    for name, parts, light in GROUPS:
        scenes[name] = scene(parts, light)
    for name, s in scenes.items():
        with open(os.path.join(out, name + ".json"), "w") as f:
            json.dump(s, f, indent=1)
            f.write("\n")
    print("%d scenes in %s" % (len(scenes), out))


if __name__ == "__main__":
    main()
