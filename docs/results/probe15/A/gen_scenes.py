#!/usr/bin/env python3
"""Generate base scenes and translated/scaled copies into /tmp/probe15/scenes."""
import os as _os
ROOT = _os.path.abspath(_os.path.join(_os.path.dirname(__file__), "../../../.."))  # the repository
SV = _os.environ.get("SV", _os.path.join(ROOT, "build/apps/shadowvol"))  # the shadowvol binary
import json, copy, os
OUT = "/tmp/probe15/scenes"
base = {}
d = json.load(open(ROOT + "/data/scenes/default.json"))
d.pop("description", None)
base["default"] = d
base["camel"] = {
  "objects": [
    {"type": "plane", "name": "ground", "size": 8},
    {"type": "mesh", "name": "camel", "file": "/tmp/probe9/d/data/meshes/camel.off",
     "transform": {"translate": [0, 0.99, 0], "scale": 2, "rotate": [0, 35, 0]}}],
  "lights": [
    {"type": "spot", "position": [2.0, 5.0, 2.5], "target": [0, 0.5, 0], "fov": 50, "intensity": 0.6},
    {"type": "directional", "direction": [-0.6, -1.0, -0.3], "intensity": 0.4}],
  "camera": {"eye": [3.5, 2.5, 4.0], "target": [0, 0.6, 0], "fov": 45, "width": 320, "height": 240}}
base["bull"] = {
  "objects": [
    {"type": "plane", "name": "ground", "size": [8, 6]},
    {"type": "mesh", "name": "bull", "file": "/tmp/probe9/d/data/meshes/bull.off",
     "transform": {"translate": [0.2, 0.69, -0.1], "scale": 2, "rotate": [0, -20, 0]}},
    {"type": "box", "name": "crate", "size": [0.5, 0.8, 0.5], "transform": {"translate": [1.6, 0.4, 0.8], "rotate": [0, 15, 0]}}],
  "lights": [
    {"type": "directional", "direction": [0.5, -0.8, -0.4], "intensity": 0.5},
    {"type": "spot", "position": [-2.5, 4.0, 3.0], "target": [0.3, 0.3, 0], "fov": 60, "intensity": 0.5}],
  "camera": {"eye": [-1.0, 3.0, 5.0], "target": [0.3, 0.4, 0], "fov": 50, "width": 320, "height": 240}}
base["elk"] = {  # elk is ~200 units big: scale it down to 2 units
  "objects": [
    {"type": "plane", "name": "ground", "size": 10},
    {"type": "mesh", "name": "elk", "file": "/tmp/probe9/d/data/meshes/elk.off",
     "transform": {"translate": [0, 1.12, 0], "scale": 0.011, "rotate": [-90, 0, 0]}}],
  "lights": [
    {"type": "spot", "position": [1.5, 6.0, -2.0], "target": [0, 0.5, 0], "fov": 45, "intensity": 0.7},
    {"type": "directional", "direction": [0.3, -1.0, 0.7], "intensity": 0.3}],
  "camera": {"eye": [2.0, 3.0, 5.0], "target": [0, 0.7, 0], "fov": 45, "width": 320, "height": 240}}

def vadd(v, o): return [a + o for a in v]
def vmul(v, s): return [a * s for a in v]

def translated(sc, off):
    sc = copy.deepcopy(sc)
    for ob in sc["objects"]:
        t = ob.setdefault("transform", {})
        t["translate"] = vadd(t.get("translate", [0, 0, 0]), off)
    for L in sc.get("lights", [sc.get("light")]):
        for k in ("position", "target"):
            if k in L: L[k] = vadd(L[k], off)
    c = sc["camera"]
    for k in ("eye", "target"): c[k] = vadd(c[k], off)
    return sc

def scaled(sc, s):
    sc = copy.deepcopy(sc)
    for ob in sc["objects"]:
        t = ob.setdefault("transform", {})
        t["translate"] = vmul(t.get("translate", [0, 0, 0]), s)
        old = t.get("scale", 1)
        t["scale"] = vmul(old, s) if isinstance(old, list) else old * s
    for L in sc.get("lights", [sc.get("light")]):
        for k in ("position", "target"):
            if k in L: L[k] = vmul(L[k], s)
        for k in ("near", "far", "extent"):
            if k in L: L[k] *= s
    c = sc["camera"]
    for k in ("eye", "target"): c[k] = vmul(c[k], s)
    for k in ("near", "far"):
        if k in c: c[k] *= s
    return sc

for name, sc in base.items():
    variants = {"base": sc, "t1e3": translated(sc, 1e3), "t1e5": translated(sc, 1e5), "t1e7": translated(sc, 1e7),
                "s1e-3": scaled(sc, 1e-3), "s1e4": scaled(sc, 1e4)}
    for v, s in variants.items():
        json.dump(s, open(os.path.join(OUT, f"{name}-{v}.json"), "w"), indent=1)
print(sorted(os.listdir(OUT)))

# --- more variants: a rotation (objects given by 'matrix'), far translations, extreme scales
import math
def rotmat(axis, deg):
    x, y, z = axis; n = math.sqrt(x*x+y*y+z*z); x, y, z = x/n, y/n, z/n
    c, s = math.cos(math.radians(deg)), math.sin(math.radians(deg)); C = 1 - c
    return [[c+x*x*C, x*y*C-z*s, x*z*C+y*s], [y*x*C+z*s, c+y*y*C, y*z*C-x*s], [z*x*C-y*s, z*y*C+x*s, c+z*z*C]]
def mm(a, b): return [[sum(a[i][k]*b[k][j] for k in range(3)) for j in range(3)] for i in range(3)]
def mv(a, v): return [sum(a[i][k]*v[k] for k in range(3)) for i in range(3)]
def obj_matrix(t):
    S = t.get("scale", 1); S = S if isinstance(S, list) else [S]*3
    rx, ry, rz = t.get("rotate", [0, 0, 0])
    R = mm(rotmat([0,0,1], rz), mm(rotmat([0,1,0], ry), rotmat([1,0,0], rx)))
    M = [[R[i][j]*S[j] for j in range(3)] for i in range(3)]
    return M, t.get("translate", [0, 0, 0])
def rigid(sc, R, off):
    sc = copy.deepcopy(sc)
    for ob in sc["objects"]:
        M, T = obj_matrix(ob.get("transform", {}))
        M2 = mm(R, M); T2 = [a + o for a, o in zip(mv(R, T), off)]
        ob["transform"] = {"matrix": [M2[0][0], M2[0][1], M2[0][2], T2[0], M2[1][0], M2[1][1], M2[1][2], T2[1],
                                      M2[2][0], M2[2][1], M2[2][2], T2[2], 0, 0, 0, 1]}
    for L in sc.get("lights", [sc.get("light")]):
        for k in ("position", "target"):
            if k in L: L[k] = [a + o for a, o in zip(mv(R, L[k]), off)]
        for k in ("direction", "up"):
            if k in L: L[k] = mv(R, L[k])
    c = sc["camera"]
    for k in ("eye", "target"): c[k] = [a + o for a, o in zip(mv(R, c[k]), off)]
    c["up"] = mv(R, c.get("up", [0, 1, 0]))
    for L in sc.get("lights", [sc.get("light")]):
        if "up" not in L and L["type"] != "point":
            # the default up is world +Y (or -Z near vertical); carry the light's own up through R
            d = L.get("direction") or [t - p for t, p in zip(L["target"], L["position"])]
            # original direction before R: solve with R^T
            RT = [[R[j][i] for j in range(3)] for i in range(3)]
            d0 = mv(RT, d); n = math.sqrt(sum(a*a for a in d0))
            up0 = [0, 0, -1] if abs(d0[1]) / n > math.cos(math.radians(2.6)) else [0, 1, 0]
            L["up"] = mv(R, up0)
    return sc
R = rotmat([0.3, 1.0, -0.5], 37.0)
I = rotmat([0, 1, 0], 0.0)
for name, sc in base.items():
    variants = {"rot": rigid(sc, R, [0, 0, 0]), "rot-t1e6": rigid(sc, R, [1e6, -2e6, 3e6]),
                "t1e9": translated(sc, 1e9), "t1e11": translated(sc, 1e11), "mat-id": rigid(sc, I, [0,0,0]),
                "s1e-5": scaled(sc, 1e-5), "s1e8": scaled(sc, 1e8)}
    for v, s in variants.items():
        json.dump(s, open(os.path.join(OUT, f"{name}-{v}.json"), "w"), indent=1)
