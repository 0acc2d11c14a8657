import os as _os
ROOT = _os.path.abspath(_os.path.join(_os.path.dirname(__file__), "../../../.."))  # the repository
SV = _os.environ.get("SV", _os.path.join(ROOT, "build/apps/shadowvol"))  # the shadowvol binary
import shadowvol as sv, threading, os, signal, time
sc = sv.load_scene(ROOT + "/data/scenes/bunny.json")
threading.Timer(0.5, lambda: os.kill(os.getpid(), signal.SIGINT)).start()
t = time.time()
try: sv.capture_depth(sc, 8192, 8192, capture="back"); print("returned", round(time.time()-t,2))
except KeyboardInterrupt: print("KeyboardInterrupt raised", round(time.time()-t,2), "s after the call began (SIGINT sent at 0.5 s)")
