# A folder written by `sv validate --report R` keeps its report.json (of another scene) after validate(report_dir=R)
import shadowvol as sv, subprocess, json, os, shutil
R = "/tmp/probe15b/rep_stale"; shutil.rmtree(R, ignore_errors=True)
subprocess.run(["/tmp/probe15b/sv", "validate", "--scene", "/work/main/data/scenes/fandisk.json", "--resolution", "64",
                "--size", "160x120", "--report", R], capture_output=True)
sv.validate(sv.load_scene("/work/main/data/scenes/plate.json"), resolution=64, size=(160, 120), report_dir=R)
print(sorted(os.listdir(R)), "report.json's scene:", json.load(open(R + "/report.json"))["scene"]["source"])
