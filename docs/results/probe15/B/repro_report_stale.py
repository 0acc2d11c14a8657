# A folder written by `sv validate --report R` keeps its report.json (of another scene) after validate(report_dir=R)
import os as _os
ROOT = _os.path.abspath(_os.path.join(_os.path.dirname(__file__), "../../../.."))  # the repository
SV = _os.environ.get("SV", _os.path.join(ROOT, "build/apps/shadowvol"))  # the shadowvol binary
TMP = "/tmp/probe15b"  # scratch
_os.makedirs(TMP, exist_ok=True)
import shadowvol as sv, subprocess, json, os, shutil
R = TMP + "/rep_stale"; shutil.rmtree(R, ignore_errors=True)
subprocess.run([SV, "validate", "--scene", ROOT + "/data/scenes/fandisk.json", "--resolution", "64",
                "--size", "160x120", "--report", R], capture_output=True)
sv.validate(sv.load_scene(ROOT + "/data/scenes/plate.json"), resolution=64, size=(160, 120), report_dir=R)
print(sorted(os.listdir(R)), "report.json's scene:", json.load(open(R + "/report.json"))["scene"]["source"])
