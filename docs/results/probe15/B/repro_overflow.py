# A float64 depth beyond float32's range becomes +inf (= "no hit") without an error
import os as _os
ROOT = _os.path.abspath(_os.path.join(_os.path.dirname(__file__), "../../../.."))  # the repository
SV = _os.environ.get("SV", _os.path.join(ROOT, "build/apps/shadowvol"))  # the shadowvol binary
import shadowvol as sv, numpy as np
sc = sv.load_scene(ROOT + "/data/scenes/fandisk.json")
d = sv.capture_depth(sc, 32, 32, capture="back")
A = d.depth.astype(np.float64); A[np.isfinite(A)] = 1e39      # every hit texel: a finite, non-negative depth
m = sv.DepthMap.from_array(A, d.light_view, d.light_projection, d.near, d.far)
print(d.hit_count, "hit texels in ->", m.hit_count, "hit texels out;", len(sv.build_volume(m)[1]), "volume triangles")
