# capture_depth(capture="auto") + build_volume(refine=6) vs `shadowvol build --refine 6` (auto by default)
import os as _os
ROOT = _os.path.abspath(_os.path.join(_os.path.dirname(__file__), "../../../.."))  # the repository
SV = _os.environ.get("SV", _os.path.join(ROOT, "build/apps/shadowvol"))  # the shadowvol binary
TMP = "/tmp/probe15b"  # scratch
_os.makedirs(TMP, exist_ok=True)
import shadowvol as sv, subprocess, json
S = ROOT + "/data/scenes/bunny.json"
sc = sv.load_scene(S)
d = sv.capture_depth(sc, 64, 64)                 # auto, as README's example
V, F, st = sv.build_volume(d, refine=6, scene=sc)
print("python: capture", d.capture, "->", len(V), "vertices", len(F), "triangles")
c = json.loads(subprocess.run([SV, "build", "--scene", S, "--resolution", "64", "--refine", "6",
                               "--out", TMP + "/cli_r6.ply", "--json"], capture_output=True, text=True).stdout)
print("CLI:    capture", c["capture"], "->", c["vertices"], "vertices", c["triangles"], "triangles;", c["captureAuto"])
