# RSS after malloc_trim grows linearly with GL calls (each call makes a fresh EGL context)
import shadowvol as sv, gc, ctypes, sys
from pathlib import Path
libc = ctypes.CDLL("libc.so.6")
def rss():
    libc.malloc_trim(0)
    return int([l for l in open("/proc/self/status") if l.startswith("VmRSS")][0].split()[1])
sc = sv.load_scene(Path(__file__).resolve().parents[4] / "data/scenes/fandisk.json")
f = {"render_none": lambda: sv.render(sc, method="none", size=(160, 120)),
     "validate_explicit": lambda: sv.validate(sc, resolution=64, size=(160, 120), volume="explicit"),
     "capture_cpu": lambda: sv.capture_depth(sc, 64, 64, capture="back")}[sys.argv[1]]
for _ in range(20): f()
gc.collect(); r0 = rss()
for _ in range(300): f()
gc.collect(); print(sys.argv[1], round((rss() - r0) / 300, 1), "KB per call over 300 calls")
