#!/usr/bin/env python3
"""The scenes where silhouette volumes apply, for refine_goals.py's --closed (README "Silhouette
refinement"): every mesh object a closed 2-manifold by `shadowvol check`, and a scene of generated
objects only (plate, tree, ...) when its silhouette volume was exact in the results.

  python3 scripts/closed_scenes.py EXE RESULTS.jsonl SCENE.json ...   # prints a,b,c

(The tenth probe's test, a silhouette error under 1 %, also counted scenes whose open meshes cast
small shadows that the silhouette volume leaves out: docs/results/probe16.) Stdlib only.
"""
import json
import os
import subprocess
import sys


def closed_mesh(exe, path):
    run = subprocess.run([exe, "check", path, "--json"], capture_output=True, text=True)
    return bool(run.stdout) and json.loads(run.stdout).get("closedManifold", False)


def main():
    exe, results, paths = sys.argv[1], sys.argv[2], sys.argv[3:]
    silhouette = {d["scene"]: d.get("error") for d in map(json.loads, open(results)) if d["method"] == "silhouette"}
    names = []
    for path in paths:
        base = os.path.dirname(path)
        meshes = [os.path.join(base, o["file"]) for o in json.load(open(path))["objects"] if o["type"] == "mesh"]
        name = os.path.basename(path)[:-len(".json")]
        error = silhouette.get(name)
        if error is not None and all(closed_mesh(exe, m) for m in meshes) and (meshes or error == 0.0):
            names.append(name)
    print(",".join(sorted(names)))


if __name__ == "__main__":
    main()
