#!/usr/bin/env python3
"""Issue 10's accuracy goals from a refine_eval.py results file (README "Silhouette refinement").

  python3 scripts/refine_goals.py out/refine-eval/results.jsonl [--closed a,b,...] [--ratio 1.5]
      [--grid8 out/s8/results.jsonl]

For each scene: the refined volumes' error at 128² and 256² against the 2048² shadow map
(`shadowmap auto 2048`, the goal "128² at most the 2048² map"), and at 256² against the silhouette
volume (the goal "within 1.5x of silhouette volumes", counted on the --closed scenes only, where
silhouette volumes are exact). With --grid8 (refine_eval.py's results of `--refine-grid 8 --methods
"refined auto 128"`), also the 128² goal with the 8 x 8 sub-grid; both sub-grids are also counted
against the better of the auto and front 2048² maps (`shadowmap front 2048`) where those ran.
Prints a Markdown table and the counts. Stdlib only.
"""
import argparse
import json


def load(path):
    """scene -> method -> record (the last record of a pair wins, as refine_eval.py resumes)."""
    cells = {}
    for line in open(path):
        r = json.loads(line)
        cells.setdefault(r["scene"], {})[r["method"]] = r
    return cells


def error(cells, scene, method):
    r = cells.get(scene, {}).get(method)
    return r.get("error") if r else None


def fmt(x):
    return "-" if x is None else "%.4f" % (100.0 * x)


def within(a, b, ratio):
    """a within ratio x b; an exact b (0) needs an exact a."""
    return a is not None and b is not None and (a <= ratio * b if b > 0 else a == 0)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("results")
    ap.add_argument("--closed", default="", help="comma-separated scenes whose meshes are closed")
    ap.add_argument("--ratio", type=float, default=1.5)
    ap.add_argument("--grid8", help="results of the 8 x 8 sub-grid at 128² (refined auto 128)")
    a = ap.parse_args()
    cells = load(a.results)
    if a.grid8:
        for scene, methods in load(a.grid8).items():
            if "refined auto 128" in methods:
                cells.setdefault(scene, {})["refined auto 128 S=8"] = methods["refined auto 128"]
    closed = [s for s in a.closed.split(",") if s]
    volumes = [m for m in ("refined auto 128", "refined auto 128 S=8", "refined auto 256", "refined entry 128",
                           "refined entry 256")
               if any(m in c for c in cells.values())]
    print("| scene | 2048² map | " + " | ".join(volumes) + " | silhouette |")
    print("|---|---:|" + "---:|" * len(volumes) + "---:|")
    for scene in sorted(cells):
        row = [fmt(error(cells, scene, "shadowmap auto 2048"))] + [fmt(error(cells, scene, m)) for m in volumes]
        print("| %s | %s | %s |" % (scene, " | ".join(row), fmt(error(cells, scene, "silhouette"))))
    print()
    for m in volumes:
        scenes = [s for s in cells if error(cells, s, m) is not None and error(cells, s, "shadowmap auto 2048") is not None]
        met = [s for s in scenes if error(cells, s, m) <= error(cells, s, "shadowmap auto 2048")]
        print("%s at most the 2048² map: %d of %d; missed: %s" %
              (m, len(met), len(scenes), ", ".join(sorted(set(scenes) - set(met))) or "none"))
        better = [s for s in scenes if error(cells, s, "shadowmap front 2048") is not None]
        if better:
            met = [s for s in better if error(cells, s, m) <= min(error(cells, s, "shadowmap auto 2048"),
                                                                 error(cells, s, "shadowmap front 2048"))]
            print("%s at most the better of the auto and front 2048² maps: %d of %d; missed: %s" %
                  (m, len(met), len(better), ", ".join(sorted(set(better) - set(met))) or "none"))
    for m in [v for v in volumes if v.endswith("256")]:
        scenes = [s for s in closed if error(cells, s, m) is not None and error(cells, s, "silhouette") is not None]
        met = [s for s in scenes if within(error(cells, s, m), error(cells, s, "silhouette"), a.ratio)]
        ratios = ["%s %s" % (s, "%.2fx" % (error(cells, s, m) / error(cells, s, "silhouette"))
                             if error(cells, s, "silhouette") > 0 else "(silhouette exact)")
                  for s in sorted(set(scenes) - set(met))]
        print("%s within %gx of silhouette volumes: %d of %d closed; missed: %s" %
              (m, a.ratio, len(met), len(scenes), ", ".join(ratios) or "none"))


if __name__ == "__main__":
    main()
