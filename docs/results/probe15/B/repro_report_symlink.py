# validate(report_dir=R) writes through a symbolic link planted in R (the CLI replaces the link)
import shadowvol as sv, os, shutil
R = "/tmp/probe15b/rep_sym2"; shutil.rmtree(R, ignore_errors=True); os.makedirs(R)
open("/tmp/probe15b/victim5.txt", "w").write("precious\n")
os.symlink("/tmp/probe15b/victim5.txt", R + "/frame.png")
sv.validate(sv.load_scene("/work/main/data/scenes/fandisk.json"), resolution=64, size=(160, 120), report_dir=R)
print("victim5.txt now starts with", open("/tmp/probe15b/victim5.txt", "rb").read()[:8])
