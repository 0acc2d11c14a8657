# capture_depth(capture="auto") + build_volume(refine=6) vs `shadowvol build --refine 6` (auto by default)
import shadowvol as sv, subprocess, json
S = "/work/main/data/scenes/bunny.json"
sc = sv.load_scene(S)
d = sv.capture_depth(sc, 64, 64)                 # auto, as README's example
V, F, st = sv.build_volume(d, refine=6, scene=sc)
print("python: capture", d.capture, "->", len(V), "vertices", len(F), "triangles")
c = json.loads(subprocess.run(["/tmp/probe15b/sv", "build", "--scene", S, "--resolution", "64", "--refine", "6",
                               "--out", "/tmp/probe15b/cli_r6.ply", "--json"], capture_output=True, text=True).stdout)
print("CLI:    capture", c["capture"], "->", c["vertices"], "vertices", c["triangles"], "triangles;", c["captureAuto"])
