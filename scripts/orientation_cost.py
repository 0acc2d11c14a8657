#!/usr/bin/env python3
"""The cost of orienting closed meshes on loading (README "Scene files", `orient`): loads a scene
holding a closed UV sphere of 1.3 million triangles (written as OFF to a temporary folder) with
`shadowvol scene`, with the default "orient": "outward" and with "as-stored", ROUNDS times each
(interleaved), and prints the median wall time and peak resident memory of each.
Usage: python3 scripts/orientation_cost.py [--exe build/apps/shadowvol] [--rounds 3]
Stdlib only.
"""
import argparse
import json
import math
import os
import statistics
import subprocess
import tempfile
import time


def write_sphere(path, segments=1000, rings=650):
    """A closed UV sphere: two poles and (rings - 1) rings of `segments` vertices, wound outward."""
    with open(path, "w") as out:
        count = 2 + (rings - 1) * segments
        out.write("OFF\n%d %d 0\n" % (count, 2 * segments * (rings - 1)))
        out.write("0 1 0\n0 -1 0\n")
        for i in range(1, rings):
            th = math.pi * i / rings
            for j in range(segments):
                ph = 2 * math.pi * j / segments
                out.write("%.9f %.9f %.9f\n" % (math.sin(th) * math.cos(ph), math.cos(th), math.sin(th) * math.sin(ph)))

        def v(i, j):
            return 2 + (i - 1) * segments + j % segments

        for j in range(segments):
            out.write("3 0 %d %d\n" % (v(1, j + 1), v(1, j)))
        for i in range(1, rings - 1):
            for j in range(segments):
                out.write("3 %d %d %d\n3 %d %d %d\n" % (v(i, j), v(i, j + 1), v(i + 1, j + 1),
                                                        v(i, j), v(i + 1, j + 1), v(i + 1, j)))
        for j in range(segments):
            out.write("3 1 %d %d\n" % (v(rings - 1, j), v(rings - 1, j + 1)))


def scene(mesh, orient):
    return {"objects": [{"type": "plane", "size": 10},
                        {"type": "mesh", "file": mesh, "orient": orient, "transform": {"translate": [0, 1.5, 0]}}],
            "light": {"type": "spot", "position": [3, 9, 2], "target": [0, 0, 0], "fov": 50},
            "camera": {"eye": [0, 5, 10], "target": [0, 1, 0]}}


def load(exe, path):
    t0 = time.monotonic()
    p = subprocess.Popen([exe, "scene", "--scene", path], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    _, status, usage = os.wait4(p.pid, 0)
    if status != 0:
        raise SystemExit("%s scene --scene %s failed (status %d)" % (exe, path, status))
    return time.monotonic() - t0, usage.ru_maxrss / 1024.0


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--exe", default="build/apps/shadowvol")
    ap.add_argument("--rounds", type=int, default=3)
    a = ap.parse_args()
    with tempfile.TemporaryDirectory() as d:
        mesh = os.path.join(d, "sphere.off")
        write_sphere(mesh)
        paths = {}
        for orient in ("outward", "as-stored"):
            paths[orient] = os.path.join(d, orient + ".json")
            with open(paths[orient], "w") as f:
                json.dump(scene(mesh, orient), f)
        runs = {k: [] for k in paths}
        for _ in range(a.rounds):
            for k, p in paths.items():
                runs[k].append(load(a.exe, p))
        for k, r in runs.items():
            print("orient %-10s %.2f s  %.0f MB peak (median of %d)" %
                  (k, statistics.median(t for t, _ in r), statistics.median(m for _, m in r), a.rounds))


if __name__ == "__main__":
    main()
