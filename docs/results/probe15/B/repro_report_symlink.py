# validate(report_dir=R) writes through a symbolic link planted in R (the CLI replaces the link)
import os as _os
ROOT = _os.path.abspath(_os.path.join(_os.path.dirname(__file__), "../../../.."))  # the repository
SV = _os.environ.get("SV", _os.path.join(ROOT, "build/apps/shadowvol"))  # the shadowvol binary
TMP = "/tmp/probe15b"  # scratch
_os.makedirs(TMP, exist_ok=True)
import shadowvol as sv, os, shutil
R = TMP + "/rep_sym2"; shutil.rmtree(R, ignore_errors=True); os.makedirs(R)
open(TMP + "/victim5.txt", "w").write("precious\n")
os.symlink(TMP + "/victim5.txt", R + "/frame.png")
sv.validate(sv.load_scene(ROOT + "/data/scenes/fandisk.json"), resolution=64, size=(160, 120), report_dir=R)
print("victim5.txt now starts with", open(TMP + "/victim5.txt", "rb").read()[:8])
