import os as _os
ROOT = _os.path.abspath(_os.path.join(_os.path.dirname(__file__), "../../../.."))  # the repository
SV = _os.environ.get("SV", _os.path.join(ROOT, "build/apps/shadowvol"))  # the shadowvol binary
import shadowvol as sv, numpy as np
sc = sv.load_scene(ROOT + "/data/scenes/fandisk.json"); d = sv.capture_depth(sc, 32, 32, capture="back")
for kw in [dict(refine=2, scene=sc, refine_grid=3), dict(refine_grid=2), dict(flatten_cap=False, cap="quad"),
           dict(hidden_search=False), dict(refine=17, scene=sc), dict(blur_offset=0.1)]:
    try: sv.build_volume(d, **kw)
    except sv.InputError as e: print(sorted(k for k in kw if k != "scene"), "->", e)
for lv in [np.eye(3), np.zeros((4, 4, 1))]:
    try: sv.DepthMap.from_array(d.depth, lv, d.light_projection, d.near, d.far)
    except sv.InputError as e: print("light_view", lv.shape, "->", e)
try: sv.DepthMap.from_array(np.broadcast_to(np.float32(5), (2**21, 4)), d.light_view, d.light_projection, d.near, d.far)
except sv.InputError as e: print("depth shape (2097152, 4) ->", e)
