#!/usr/bin/env python3
"""What the sub-grid's search for hidden surfaces costs (docs/results/hidden-surfaces): builds each
scene's refined volume on the 4 x 4 sub-grid (K = 6) with and without the search, interleaved, in
one process (the Python module, so the scene's Embree BVH is not part of the figure), and prints a
Markdown table of hidden quads, rays, the build's median time and the search's own time.

Usage: /usr/bin/python3 scripts/hidden_search_cost.py [--repeat 15] [SCENE.json ...]
(after a build with the Python module: build/python; numpy as the module needs it).
"""
import argparse
import os
import statistics
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "build", "python"))
import shadowvol as sv  # noqa: E402

DEFAULT_SCENES = ["data/scenes/default.json", "data/scenes/bunny.json", "data/scenes/armadillo.json",
                  "data/scenes/unseen/biped-nonmanifold-grazing.json", "data/scenes/sweep-800000.json"]


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--repeat", type=int, default=15, help="builds of each kind per scene and size")
    ap.add_argument("scenes", nargs="*", default=DEFAULT_SCENES)
    a = ap.parse_args()
    print("| scene | N | hidden quads | rays without / with | build ms without / with (median of %d) | search ms |"
          % a.repeat)
    print("|---|---:|---:|---:|---:|---:|")
    for path in a.scenes:
        scene = sv.load_scene(path)
        for n in (128, 256):
            depth = sv.capture_depth(scene, n, n, capture="auto")
            runs = {False: [], True: []}
            for _ in range(a.repeat):
                for search in (False, True):
                    _, _, st = sv.build_volume(depth, refine=6, refine_grid=4, hidden_search=search, scene=scene)
                    runs[search].append(st)
            med = lambda rs, k: statistics.median(r["ms"][k] for r in rs)  # noqa: E731
            w, o = runs[True], runs[False]
            print("| %s | %d | %d | %d / %d | %.1f / %.1f | %.1f |" % (
                os.path.splitext(os.path.basename(path))[0], n, w[0]["hiddenQuads"], o[0]["raysCast"],
                w[0]["raysCast"], med(o, "total"), med(w, "total"), med(w, "hidden")), flush=True)


if __name__ == "__main__":
    main()
