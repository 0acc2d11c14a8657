#!/usr/bin/env python3
"""Probe 11: one scene per assimp-testmodels mesh, seeded pseudo-random scale (1e-3..1e4 across),
placement (half of them up to 1e5 from the origin), rotation, light (spot / directional down /
directional grazing 10-15 deg) and a ground plane; camera looks at the object.
Bounds of the rotated mesh come from `shadowvol scene --json` (read-only use of the CLI)."""
import json, math, os, random, subprocess, sys

HERE = os.path.dirname(os.path.abspath(__file__))
EXE = os.environ.get("SHADOWVOL", "build/apps/shadowvol")
# assimp-testmodels unpacked as docs/results/probe11/README.md says (never committed)
M = os.environ.get("PROBE_MODELS", "/tmp/probe9/x/usr/share/assimp/models/")
OUT = os.path.join(HERE, "scenes")
MESHES = [
    "OBJ/spider.obj", "OBJ/regr01.obj", "OBJ/concave_polygon.obj", "OFF/Wuson.off", "PLY/cube_binary.ply",
    "STL/Spider_ascii.stl", "3DS/fels.3ds", "3DS/test1.3ds", "3DS/cubes_with_alpha.3DS", "Collada/duck.dae",
    "Collada/teapots.DAE", "Collada/sphere.dae", "Collada/COLLADA.dae", "Collada/earthCylindrical.DAE",
    "glTF/CesiumMilkTruck/CesiumMilkTruck.gltf", "glTF/TwoBoxes/TwoBoxes.gltf", "glTF2/draco/2CylinderEngine.gltf",
    "glTF2/ClearCoat-glTF/ClearCoatTest.gltf", "glTF2/simple_skin/simple_skin.gltf",
    "FBX/cubes_with_mirroring_and_pivot.fbx", "FBX/huesitos.fbx", "FBX/animation_with_skeleton.fbx",
    "X/BCN_Epileptic.X", "X/fromtruespace_bin32.x", "BLEND/Suzanne_248.blend", "BLEND/HUMAN.blend",
    "BLEND/MirroredCube_252.blend", "MS3D/jeep1.ms3d", "LWO/LXOB_Modo/CrazyEngine.lxo", "COB/dwarf.cob",
    "Q3D/E-AT-AT.q3o", "AC/SphereWithLight.ac", "MD2/sydney.md2", "NFF/NFF/spheres.nff", "SMD/holy_grailref.smd",
    "DXF/PinkEggFromLW.dxf", "SIB/heffalump.sib", "X3D/ComputerKeyboard.x3d", "AMF/test9.amf",
]
LIGHTS = ["spot", "down", "grazing"]


def bounds(path, rotate):
    scene = {"objects": [{"type": "mesh", "name": "m", "file": path, "transform": {"rotate": rotate}}],
             "light": {"type": "directional", "direction": [0, -1, 0]},
             "camera": {"eye": [1e6, 1e6, 1e6], "target": [0, 0, 0]}}
    tmp = os.path.join(OUT, ".bounds.json")
    with open(tmp, "w") as f:
        json.dump(scene, f)
    r = subprocess.run([EXE, "scene", "--scene", tmp, "--json"], capture_output=True, text=True, timeout=120)
    os.remove(tmp)
    d = json.loads(r.stdout)
    return d["bounds"]["min"], d["bounds"]["max"], d["triangles"]


def r6(x):
    return float("%.15g" % x)


def main():
    rng = random.Random(20261211)
    os.makedirs(OUT, exist_ok=True)
    names = []
    for i, mesh in enumerate(MESHES):
        light = LIGHTS[i % 3] if rng.random() < 0.7 else rng.choice(LIGHTS)
        size = 10 ** rng.uniform(-3, 4)                 # world units across (largest extent)
        rotate = [rng.choice([0, 0, -90, 90, rng.uniform(-180, 180)]), rng.uniform(-180, 180), rng.choice([0, 0, rng.uniform(-30, 30)])]
        rotate = [round(a, 3) for a in rotate]
        far = rng.random() < 0.5
        if far:
            mag = 10 ** rng.uniform(2, 5)
            u = [rng.gauss(0, 1) for _ in range(3)]
            n = math.sqrt(sum(c * c for c in u))
            offset = [mag * c / n for c in u]
        else:
            offset = [rng.uniform(-1, 1) * size, 0.0, rng.uniform(-1, 1) * size]
        gap = size * rng.choice([0, 0, 0.02, 0.1, 0.3])   # height of the lowest point over the ground
        lo, hi, tris = bounds(M + mesh, rotate)
        ext = max(h - l for l, h in zip(lo, hi))
        s = size / ext
        c = [(l + h) / 2 for l, h in zip(lo, hi)]
        # mesh centre in x/z at offset, lowest point at offset_y + gap
        t = [offset[0] - s * c[0], offset[1] + gap - s * lo[1], offset[2] - s * c[2]]
        height = s * (hi[1] - lo[1])
        centre = [offset[0], offset[1] + gap + height / 2, offset[2]]
        az = rng.uniform(0, 360)
        if light == "spot":
            elev = math.radians(rng.uniform(35, 75))
            d = size * rng.uniform(2.0, 5.0)
            pos = [centre[0] + d * math.cos(elev) * math.cos(math.radians(az)), centre[1] + d * math.sin(elev),
                   centre[2] + d * math.cos(elev) * math.sin(math.radians(az))]
            fov = rng.uniform(50, 90)
            L = {"type": "spot", "position": [r6(v) for v in pos], "target": [r6(v) for v in [centre[0], offset[1], centre[2]]], "fov": round(fov, 2)}
            gsize = 6 * size
        elif light == "down":
            L = {"type": "directional", "direction": [0, -1, 0]}
            gsize = 3 * size
        else:
            elev = math.radians(rng.uniform(10, 15))
            L = {"type": "directional", "direction": [r6(-math.cos(elev) * math.cos(math.radians(az))), r6(-math.sin(elev)),
                                                       r6(-math.cos(elev) * math.sin(math.radians(az)))]}
            gsize = 14 * size
        caz, cel, cd = math.radians(rng.uniform(0, 360)), math.radians(rng.uniform(20, 55)), size * rng.uniform(2.2, 4.0)
        look = centre
        if light == "grazing":  # look between the object and its shadow (the light ray through the centre meets the ground)
            dirv = L["direction"]
            tg = (centre[1] - offset[1]) / -dirv[1]
            hit = [centre[k] + tg * dirv[k] for k in range(3)]
            look = [(centre[k] + hit[k]) / 2 for k in range(3)]
            cd = max(cd, 0.9 * math.dist(centre, hit) + 1.5 * size)
        eye = [look[0] + cd * math.cos(cel) * math.cos(caz), look[1] + cd * math.sin(cel), look[2] + cd * math.cos(cel) * math.sin(caz)]
        base = os.path.splitext(os.path.basename(mesh))[0].lower().replace("_", "-").replace(" ", "-")
        name = "%02d-%s-%s%s" % (i, base, light, "-far" if far else "")
        scene = {
            "description": "probe11: %s (%d triangles), %.3g units across, %s, at %s, light %s" % (mesh, tris, size, "lifted %.3g" % gap if gap else "on the ground", [r6(v) for v in offset], light),
            "objects": [
                {"type": "plane", "name": "ground", "size": r6(gsize), "transform": {"translate": [r6(offset[0]), r6(offset[1]), r6(offset[2])]}},
                {"type": "mesh", "name": "m", "file": M + mesh, "transform": {"translate": [r6(v) for v in t], "rotate": rotate, "scale": r6(s)}},
            ],
            "light": L,
            "camera": {"eye": [r6(v) for v in eye], "target": [r6(v) for v in look], "fov": 45, "width": 640, "height": 480},
        }
        with open(os.path.join(OUT, name + ".json"), "w") as f:
            json.dump(scene, f, indent=1)
            f.write("\n")
        names.append(name)
    print("%d scenes in %s" % (len(names), OUT))


if __name__ == "__main__":
    main()
