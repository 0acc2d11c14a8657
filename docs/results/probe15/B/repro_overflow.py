# A float64 depth beyond float32's range becomes +inf (= "no hit") without an error
import shadowvol as sv, numpy as np
sc = sv.load_scene("/work/main/data/scenes/fandisk.json")
d = sv.capture_depth(sc, 32, 32, capture="back")
A = d.depth.astype(np.float64); A[np.isfinite(A)] = 1e39      # every hit texel: a finite, non-negative depth
m = sv.DepthMap.from_array(A, d.light_view, d.light_projection, d.near, d.far)
print(d.hit_count, "hit texels in ->", m.hit_count, "hit texels out;", len(sv.build_volume(m)[1]), "volume triangles")
