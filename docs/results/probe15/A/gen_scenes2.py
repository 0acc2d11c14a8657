#!/usr/bin/env python3
"""More invariance variants: shipped scenes with a point light (room), a grazing directional light, a thin tree."""
import json, os, sys
sys.argv = ["x"]
exec(open("/tmp/probe15/gen_scenes.py").read().split("for name, sc in base.items():")[0])  # base, translated, scaled
import importlib
OUT2 = "/tmp/probe15/scenes3"; os.makedirs(OUT2, exist_ok=True)
for name in ("room", "hemisphere-grazing", "tree"):
    sc = json.load(open(f"/tmp/probe15/scenes2/{name}.json")); sc.pop("description", None)
    sc["camera"]["width"], sc["camera"]["height"] = 320, 240
    for v, s in {"base": sc, "t1e5": translated(sc, 1e5), "t1e7": translated(sc, 1e7), "s1e-3": scaled(sc, 1e-3), "s1e4": scaled(sc, 1e4)}.items():
        json.dump(s, open(f"{OUT2}/{name}-{v}.json", "w"), indent=1)
print(sorted(os.listdir(OUT2)))
