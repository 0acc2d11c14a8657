#!/usr/bin/env python3
"""Silhouette refinement against shadow maps and silhouette volumes, scene by scene (README
"Silhouette refinement"): runs `shadowvol validate` (640x480, the scene's camera) for each scene and
method and prints a Markdown table of the misclassified fraction of pixels facing the light (%),
with the stencil-vs-count agreement of every volume.

Usage: python3 scripts/refine_eval.py [--exe build/apps/shadowvol] [--refine 6]
           [--chord-points | --refine-grid S [--no-hidden-search]] [--out DIR] [--methods "refined 128,refined 256"]
           [--validate-args "--exact-offset-scale 1"] SCENE.json ...

--validate-args appends its options to every `shadowvol validate` call (split as a shell would,
shlex); e.g. "--exact-offset-scale 1" measures against the legacy exact reference of the tables
written before 2026-12-06 (README "Validation"). Options with no space in them need the = form:
--validate-args=--no-snap.

Results go to DIR/results.jsonl (default out/refine-eval) as they come; a rerun with the same DIR
skips what is there. Stdlib only.
"""
import argparse
import json
import os
import shlex
import subprocess
import sys


def methods(k, chords=False, grid=1, hidden=True):
    """Column key -> validate options."""
    ref = (["--volume", "explicit", "--refine", str(k)] + (["--chord-points"] if chords else []) +
           (["--refine-grid", str(grid)] if grid > 1 else []) + ([] if hidden else ["--no-hidden-search"]))
    back = ["--capture", "back"]  # what these columns measured before --capture auto became the default
    return {
        "shadowmap 2048": ["--method", "shadowmap", "--resolution", "2048"] + back,
        "shadowmap front 2048": ["--method", "shadowmap", "--resolution", "2048", "--capture", "front"],
        "shadowmap midpoint 2048": ["--method", "shadowmap", "--resolution", "2048", "--capture", "midpoint"],
        "shadowmap auto 2048": ["--method", "shadowmap", "--resolution", "2048", "--capture", "auto"],
        "shadowmap entry 2048": ["--method", "shadowmap", "--resolution", "2048", "--capture", "entry"],
        "hybrid 256": ["--volume", "explicit", "--resolution", "256"] + back,
        "hybrid entry 256": ["--volume", "explicit", "--resolution", "256", "--capture", "entry"],
        "refined 128": ref + ["--resolution", "128"] + back,
        "refined 256": ref + ["--resolution", "256"] + back,
        "refined front 128": ref + ["--resolution", "128", "--capture", "front"],
        "refined front 256": ref + ["--resolution", "256", "--capture", "front"],
        "refined midpoint 128": ref + ["--resolution", "128", "--capture", "midpoint"],
        "refined midpoint 256": ref + ["--resolution", "256", "--capture", "midpoint"],
        "refined auto 128": ref + ["--resolution", "128", "--capture", "auto"],
        "refined auto 256": ref + ["--resolution", "256", "--capture", "auto"],
        "refined entry 128": ref + ["--resolution", "128", "--capture", "entry"],
        "refined entry 256": ref + ["--resolution", "256", "--capture", "entry"],
        "silhouette": ["--method", "silhouette"],
        # The refined GPU volume (no sub-grid, chord points or a choice of crossings: the GPU's rays).
        "gpu refined back 128": ["--volume", "gpu", "--refine", str(k), "--resolution", "128"] + back,
        "gpu refined back 256": ["--volume", "gpu", "--refine", str(k), "--resolution", "256"] + back,
        "gpu refined entry 128": ["--volume", "gpu", "--refine", str(k), "--resolution", "128", "--capture", "entry"],
        "gpu refined entry 256": ["--volume", "gpu", "--refine", str(k), "--resolution", "256", "--capture", "entry"],
    }


def run(exe, scene, opts, report, extra=()):
    r = subprocess.run([exe, "validate", "--scene", scene, "--report", report, "--json"] + opts + list(extra),
                       capture_output=True, text=True)
    if r.returncode not in (0, 3):
        # Silhouette volumes refuse meshes that are neither closed manifolds nor open sheets.
        return {"refused": (r.stderr.strip().splitlines() or ["exit %d" % r.returncode])[-1]}
    j = json.loads(r.stdout)
    m = j["againstExact"]["method"]
    agree = j["stencilVsCount"]["fraction"] if isinstance(j["stencilVsCount"], dict) else None
    return {"error": m["errorFraction"], "missed": m["missedShadow"], "false": m["falseShadow"],
            "agree": agree, "passed": j["passed"]}


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--exe", default="build/apps/shadowvol")
    ap.add_argument("--refine", type=int, default=6, help="refinement steps K (default 6, the sweep's)")
    ap.add_argument("--out", default="out/refine-eval")
    ap.add_argument("--chord-points", action="store_true", help="refined methods with --chord-points")
    ap.add_argument("--refine-grid", type=int, default=1, help="refined methods on an S x S sub-grid (2, 4, 8)")
    ap.add_argument("--no-hidden-search", action="store_true",
                    help="refined methods on the sub-grid without its search for hidden surfaces")
    ap.add_argument("--methods", help="comma-separated columns (default: all): " + ", ".join(methods(6)))
    ap.add_argument("--validate-args", default="", metavar="OPTIONS",
                    help="options appended to every validate call, one string split as a shell would "
                         "(default none), e.g. --validate-args \"--exact-offset-scale 1\" for the legacy "
                         "exact reference; recorded as validateArgs in results.jsonl, and a rerun into the "
                         "same --out reuses only records made with the same string")
    ap.add_argument("scenes", nargs="+")
    a = ap.parse_args()
    try:
        extra = shlex.split(a.validate_args)
    except ValueError as e:
        ap.error("--validate-args: %s" % e)
    os.makedirs(a.out, exist_ok=True)
    path = os.path.join(a.out, "results.jsonl")
    done = {}
    if os.path.exists(path):
        for line in open(path):
            rec = json.loads(line)
            if rec.get("validateArgs", "") == a.validate_args:
                done[(rec["scene"], rec["method"])] = rec
    cols = methods(a.refine, a.chord_points, a.refine_grid, not a.no_hidden_search)
    if a.methods:
        keys = [k.strip() for k in a.methods.split(",")]
        unknown = [k for k in keys if k not in cols]
        if unknown:
            ap.error("unknown method(s): " + ", ".join(unknown))
        cols = {k: cols[k] for k in keys}
    with open(path, "a") as out:
        for scene in a.scenes:
            name = os.path.splitext(os.path.basename(scene))[0]
            for key, opts in cols.items():
                if (name, key) in done:
                    continue
                rec = {"scene": name, "method": key, "refine": a.refine, "refineGrid": a.refine_grid,
                       "hiddenSearch": not a.no_hidden_search}
                if a.validate_args:
                    rec["validateArgs"] = a.validate_args
                rec.update(run(a.exe, scene, opts, os.path.join(a.out, "report"), extra))
                out.write(json.dumps(rec) + "\n")
                out.flush()
                done[(name, key)] = rec
                print(name, key, rec.get("error", rec.get("refused")), file=sys.stderr, flush=True)

    print("| scene | " + " | ".join(cols) + " |")
    print("|---|" + "---:|" * len(cols))
    worst = 1.0
    for scene in a.scenes:
        name = os.path.splitext(os.path.basename(scene))[0]
        cells = []
        for key in cols:
            rec = done.get((name, key), {})
            if "error" not in rec:
                cells.append("refused" if "refused" in rec else "-")
                continue
            cells.append("%.4f" % (100 * rec["error"]))
            if rec.get("agree") is not None:
                worst = min(worst, rec["agree"])
        print("| %s | %s |" % (name, " | ".join(cells)))
    print("\nLowest stencil-vs-count agreement of any volume above: %.5f%%" % (100 * worst))


if __name__ == "__main__":
    main()
