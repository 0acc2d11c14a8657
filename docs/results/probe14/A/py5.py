import os as _os
ROOT = _os.path.abspath(_os.path.join(_os.path.dirname(__file__), "../../../.."))  # the repository
SV = _os.environ.get("SV", _os.path.join(ROOT, "build/apps/shadowvol"))  # the shadowvol binary
import shadowvol as sv, threading, time
ticks = []
stop = False
def tick():
    while not stop:
        ticks.append(time.time()); time.sleep(0.1)
th = threading.Thread(target=tick); th.start()
sc = sv.load_scene(ROOT + '/data/scenes/tree.json')
t0 = time.time(); d = sv.capture_depth(sc, 4000, 4000); t1 = time.time()
print('capture', round(t1-t0,1), 's; ticks during it', sum(1 for t in ticks if t0 < t < t1))
t0 = time.time(); V, F, st = sv.build_volume(d, refine=8, scene=sc, refine_grid=8); t1 = time.time()
print('build', round(t1-t0,1), 's; ticks during it', sum(1 for t in ticks if t0 < t < t1))
t0 = time.time(); r = sv.render(sc, resolution=1024, size=(1600,1200)); t1 = time.time()
print('render', round(t1-t0,1), 's; ticks during it', sum(1 for t in ticks if t0 < t < t1))
stop = True; th.join()
