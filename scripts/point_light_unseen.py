#!/usr/bin/env python3
"""The unseen scenes under a point light: each scene of data/scenes/unseen with its light replaced
by a point light at the spot light's position (3 units above the camera's target, offset 0.7 and
0.4 sideways, for lights without a position), written to out/point-unseen/; then `shadowvol
validate` of the cube volume, of the cube shadow map at the same texels per face, and of the
dual-paraboloid map at the same texel count.

    bash scripts/fetch_unseen_meshes.sh
    python3 scripts/point_light_unseen.py [--resolution 128] [--volume auto|gpu|explicit] [--refine K]
        [--capture back|front|midpoint]

Prints per scene whether the frame is consistent, the three errors (misclassified %) and the ratio
of the volume's to the cube shadow map's, then the count where the volume's error is at most the
shadow map's and the median ratio, and the same for the dual-paraboloid map against the cube map.
With --refine K the cube volume is refined: the GPU cube volume (auto, gpu) by K bisection rays per
boundary edge cast on the GPU (six face volumes; the GPU's walk before 2026-12-04), the explicit one (--volume explicit) by K rays per
boundary edge; --capture sets the cube volume's capture mode (the shadow maps keep back capture)."""
import argparse
import glob
import json
import os
import statistics
import subprocess
import sys

SHADOWVOL = os.environ.get("SHADOWVOL", "./build/apps/shadowvol")


def point_variant(path, out_dir):
    j = json.load(open(path))
    for o in j["objects"]:
        if "file" in o:
            o["file"] = os.path.abspath(os.path.join(os.path.dirname(path), o["file"]))
    light = j["light"]
    if "position" in light:
        pos = light["position"]
    else:
        t = j["camera"]["target"]
        pos = [t[0] + 0.7, t[1] + 3.0, t[2] + 0.4]
    j["light"] = {"type": "point", "position": pos}
    j["description"] = "point-light variant of " + path
    out = os.path.join(out_dir, os.path.basename(path))
    json.dump(j, open(out, "w"), indent=1)
    return out


def validate(scene, report, args):
    p = subprocess.run([SHADOWVOL, "validate", "--json", "--scene", scene, "--report", report] + args,
                       capture_output=True, text=True)
    if p.returncode not in (0, 3):
        sys.exit(f"validate {scene} {args} failed ({p.returncode}): {p.stderr.strip()}")
    return json.loads(p.stdout)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--resolution", default="128")
    ap.add_argument("--volume", default="auto", choices=["auto", "gpu", "explicit"],
                    help="the hybrid cube volume: auto (gpu), gpu or explicit")
    ap.add_argument("--refine", default="0",
                    help="refinement (0: off): rays per boundary edge for --volume explicit; on for the GPU cube volume")
    ap.add_argument("--capture", default="back", choices=["back", "front", "midpoint"],
                    help="the cube volume's capture mode")
    a = ap.parse_args()
    hybrid_args = ["--resolution", a.resolution, "--volume", a.volume, "--refine", a.refine, "--capture", a.capture]
    out_dir = os.path.join("out", "point-unseen")
    os.makedirs(out_dir, exist_ok=True)
    ratios, at_most, consistent = [], 0, 0
    dpsm_ratios, dpsm_at_most = [], 0
    scenes = sorted(glob.glob("data/scenes/unseen/*.json"))
    for path in scenes:
        scene = point_variant(path, out_dir)
        name = os.path.splitext(os.path.basename(path))[0]
        hv = validate(scene, os.path.join(out_dir, name, "hybrid"), hybrid_args)
        sm = validate(scene, os.path.join(out_dir, name, "shadowmap"),
                      ["--method", "shadowmap", "--resolution", a.resolution, "--capture", "back"])
        dp = validate(scene, os.path.join(out_dir, name, "dpsm"), ["--method", "dpsm", "--resolution", a.resolution, "--capture", "back"])
        h = 100.0 * hv["againstExact"]["method"]["errorFraction"]
        s = 100.0 * sm["againstExact"]["method"]["errorFraction"]
        d = 100.0 * dp["againstExact"]["method"]["errorFraction"]
        dpsm_ratios.append(d / s if s > 0 else float("inf"))
        dpsm_at_most += d <= s
        ok = hv["verdict"]["consistent"] and hv["meshChecks"]["valid"]
        consistent += ok
        ratio = h / s if s > 0 else float("inf")
        ratios.append(ratio)
        at_most += h <= s
        print(f"{name:36s} consistent {ok!s:5s} stencil {100 * hv['stencilVsCount']['fraction']:.4f} % "
              f"hybrid {h:.4f} shadowmap {s:.4f} dpsm {d:.4f} ratio {ratio:.2f}")
    print(f"consistent {consistent} of {len(scenes)}; hybrid at most the cube shadow map on {at_most} of "
          f"{len(scenes)}, median ratio {statistics.median(ratios):.2f}")
    print(f"dpsm at most the cube shadow map on {dpsm_at_most} of {len(scenes)}, median ratio "
          f"{statistics.median(dpsm_ratios):.2f}")


if __name__ == "__main__":
    main()
