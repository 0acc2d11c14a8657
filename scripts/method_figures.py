"""Figures of docs/method.md: the default scene's shadow volume as a wireframe, without and with
silhouette refinement, seen from a camera beside the scene. Uses the Python module.

    PYTHONPATH=build/python /usr/bin/python3 scripts/method_figures.py docs/images

Writes volume-24.svg and volume-24-refined.svg, and PNG copies when rsvg-convert (Debian's
librsvg2-bin) is installed: the PNGs are what docs/method.md shows.
"""

import shutil
import subprocess
import sys
from pathlib import Path

import numpy as np

import shadowvol as sv


def look_at(eye, target, up):
    f = target - eye
    f /= np.linalg.norm(f)
    s = np.cross(f, up)
    s /= np.linalg.norm(s)
    u = np.cross(s, f)
    m = np.eye(4)
    m[0, :3], m[1, :3], m[2, :3] = s, u, -f
    m[:3, 3] = -m[:3, :3] @ eye
    return m


def view_points(V, view):
    return (view @ np.c_[V, np.ones(len(V))].T).T


def project(V, view, fov_deg, width, height):
    p = view_points(V, view)
    t = 1.0 / np.tan(np.radians(fov_deg) / 2)
    x = t * (height / width) * p[:, 0] / -p[:, 2]
    y = t * p[:, 1] / -p[:, 2]
    return np.c_[(x + 1) * width / 2, (1 - y) * height / 2]


def edges(F):
    e = np.sort(np.r_[F[:, [0, 1]], F[:, [1, 2]], F[:, [2, 0]]], axis=1)
    return np.unique(e, axis=0)


def svg(scene, V, F, title, width=720, height=480):
    light = np.array(scene.describe()["light"]["position"])
    eye = np.array([13.0, 4.0, 11.0])  # outside the ground (+-10): nothing behind the camera
    view = look_at(eye, np.array([-0.5, 0.0, -0.5]), np.array([0.0, 1.0, 0.0]))
    SV, SF = scene.mesh()
    out = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{width}" height="{height}" '
           f'viewBox="0 0 {width} {height}"><rect width="100%" height="100%" fill="white"/>']
    # The scene, flat-shaded by the light, far triangles first (painter's order).
    a, b, c = SV[SF[:, 0]], SV[SF[:, 1]], SV[SF[:, 2]]
    n = np.cross(b - a, c - a)
    n /= np.maximum(np.linalg.norm(n, axis=1, keepdims=True), 1e-30)
    to_light = light - (a + b + c) / 3
    to_light /= np.linalg.norm(to_light, axis=1, keepdims=True)
    shade = 0.45 + 0.55 * np.clip(np.einsum("ij,ij->i", n, to_light), 0, 1)
    depth = view_points((a + b + c) / 3, view)[:, 2]
    P2 = project(SV, view, 40, width, height)
    for k in np.argsort(depth):
        g = int(200 * shade[k]) + 30
        pts = " ".join(f"{x:.1f},{y:.1f}" for x, y in P2[SF[k]])
        colour = f"#{g:02x}{g:02x}{max(g - 12, 0):02x}"
        out.append(f'<polygon points="{pts}" fill="{colour}" stroke="{colour}" stroke-width="0.4"/>')
    P = project(V, view, 40, width, height)
    for a, b in edges(F):
        out.append(f'<line x1="{P[a, 0]:.1f}" y1="{P[a, 1]:.1f}" x2="{P[b, 0]:.1f}" y2="{P[b, 1]:.1f}" '
                   'stroke="#0072B2" stroke-width="0.6" stroke-opacity="0.8"/>')
    lx, ly = project(light[None, :], view, 40, width, height)[0]
    out.append(f'<circle cx="{lx:.1f}" cy="{ly:.1f}" r="5" fill="#E69F00"/>')
    out.append(f'<text x="10" y="22" font-family="sans-serif" font-size="15">{title}</text></svg>')
    return "\n".join(out) + "\n"


def main():
    out = Path(sys.argv[1] if len(sys.argv) > 1 else "docs/images")
    out.mkdir(parents=True, exist_ok=True)
    scene = sv.default_scene()
    depth = sv.capture_depth(scene, 24, 24)
    for refine, name in ((0, "volume-24.svg"), (6, "volume-24-refined.svg")):
        V, F, stats = sv.build_volume(depth, refine=refine, scene=scene if refine else None)  # scene= only with refine
        title = (f"default scene, 24x24 depth map: {len(F)} triangles"
                 + (f", refine 6 ({stats['raysCast']} rays)" if refine else ""))
        (out / name).write_text(svg(scene, V, F, title))
        print(f"wrote {out / name}")
        if shutil.which("rsvg-convert"):
            png = (out / name).with_suffix(".png")
            subprocess.run(["rsvg-convert", str(out / name), "-o", str(png)], check=True)
            print(f"wrote {png}")


if __name__ == "__main__":
    main()
