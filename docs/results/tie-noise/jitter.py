#!/usr/bin/env python3
"""Copies of a scene with the camera moved by a fraction of a pixel (docs/results/tie-noise).

  python3 jitter.py SCENE.json OUTDIR    # writes OUTDIR/<name>-j0.json ... -j4.json, prints their paths

j0 is the scene as it is; j1..j4 move the camera's eye and target together by the offsets below,
in pixels of the image at the target's distance, along the image's right and up. A mesh object's
relative file is made absolute (the copies live elsewhere). Stdlib only.
"""
import json
import math
import os
import sys

OFFSETS = [(0.0, 0.0), (0.37, 0.11), (-0.23, 0.41), (0.13, -0.29), (-0.41, -0.17)]


def sub(a, b):
    return [x - y for x, y in zip(a, b)]


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def unit(a):
    n = math.sqrt(sum(x * x for x in a))
    return [x / n for x in a]


def main():
    path, out = sys.argv[1], sys.argv[2]
    scene = json.load(open(path))
    base = os.path.dirname(os.path.abspath(path))
    for o in scene["objects"]:
        if "file" in o and not os.path.isabs(o["file"]):
            o["file"] = os.path.normpath(os.path.join(base, o["file"]))
    cam = scene["camera"]
    eye, target = cam["eye"], cam["target"]
    forward = unit(sub(target, eye))
    up0 = cam.get("up", [0.0, 1.0, 0.0])
    right = unit(cross(forward, up0))
    up = cross(right, forward)
    distance = math.sqrt(sum(x * x for x in sub(target, eye)))
    pixel = 2.0 * distance * math.tan(math.radians(cam.get("fov", 45.0)) / 2.0) / cam.get("height", 480)
    name = os.path.basename(path)[:-len(".json")]
    os.makedirs(out, exist_ok=True)
    for k, (a, b) in enumerate(OFFSETS):
        shift = [pixel * (a * r + b * u) for r, u in zip(right, up)]
        copy = json.loads(json.dumps(scene))
        copy["camera"]["eye"] = [x + s for x, s in zip(eye, shift)]
        copy["camera"]["target"] = [x + s for x, s in zip(target, shift)]
        dest = os.path.join(out, f"{name}-j{k}.json")
        json.dump(copy, open(dest, "w"), indent=1)
        print(dest)


if __name__ == "__main__":
    main()
