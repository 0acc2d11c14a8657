#!/usr/bin/env python3
"""Misclassified % of a point light's frames against exact shadows: the explicit cube volume at
several cube-face sizes and capture modes, silhouette volumes and cube shadow maps, one
`shadowvol validate` each.

    python3 scripts/point_light_eval.py [SCENE.json ...]    # default: data/scenes/point/*.json

Prints a Markdown table (README "Point lights"); reports go to out/point-eval/."""
import glob
import json
import os
import subprocess
import sys

SHADOWVOL = os.environ.get("SHADOWVOL", "./build/apps/shadowvol")
RUNS = [("hybrid 64", ["--resolution", "64", "--capture", "back"]), ("hybrid 128", ["--resolution", "128", "--capture", "back"]),
        ("hybrid 256", ["--resolution", "256", "--capture", "back"]), ("hybrid 512", ["--resolution", "512", "--capture", "back"]),
        ("hybrid front 256", ["--resolution", "256", "--capture", "front"]),
        ("hybrid midpoint 256", ["--resolution", "256", "--capture", "midpoint"]),
        ("silhouette", ["--method", "silhouette"]),
        ("cube shadowmap 128", ["--method", "shadowmap", "--resolution", "128", "--capture", "back"]),
        ("cube shadowmap 256", ["--method", "shadowmap", "--resolution", "256", "--capture", "back"]),
        ("cube shadowmap 512", ["--method", "shadowmap", "--resolution", "512", "--capture", "back"]),
        ("cube pcf3 256", ["--method", "pcf3", "--resolution", "256", "--capture", "back"])]


def run(scene, name, args):
    out = os.path.join("out", "point-eval", os.path.splitext(os.path.basename(scene))[0], name.replace(" ", "-"))
    cmd = [SHADOWVOL, "validate", "--json", "--scene", scene, "--report", out] + args
    p = subprocess.run(cmd, capture_output=True, text=True)
    if p.returncode not in (0, 3):
        sys.exit(f"{' '.join(cmd)} failed ({p.returncode}): {p.stderr.strip()}")
    j = json.loads(p.stdout)
    err = 100.0 * j["againstExact"]["method"]["errorFraction"]
    agree = j["stencilVsCount"]["fraction"] if isinstance(j.get("stencilVsCount"), dict) else None
    return err, agree


def main():
    scenes = sys.argv[1:] or sorted(glob.glob("data/scenes/point/*.json"))
    print("| scene | " + " | ".join(n for n, _ in RUNS) + " | lowest stencil vs counts |")
    print("|---|" + "---:|" * (len(RUNS) + 1))
    for scene in scenes:
        cells, agreements = [], []
        for name, args in RUNS:
            err, agree = run(scene, name, args)
            cells.append(f"{err:.4f}")
            if agree is not None:
                agreements.append(agree)
        low = f"{100.0 * min(agreements):.4f} %" if agreements else "-"
        print(f"| {os.path.splitext(os.path.basename(scene))[0]} | " + " | ".join(cells) + f" | {low} |")


if __name__ == "__main__":
    main()
