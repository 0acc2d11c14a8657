# Refusals that reach Python in the library's terms (source "volume options", C++ struct/field
# names, side-file JSON pointers, a C++ function) instead of this module's keywords.
import sys, numpy as np; sys.path.insert(0, '/tmp/probe21/py'); import shadowvol as sv
s = sv.load_scene('/work/main/data/scenes/bunny.json')
d = sv.capture_depth(s, 64, 64)
def show(label, f):
    try: f(); print(label, '-> accepted')
    except Exception as e: print(f'{label}\n   {type(e).__name__}: {e}\n   source={getattr(e,"source",None)!r} field={getattr(e,"field",None)!r}')
show('build_volume(refine=6, scene=s, refine_grid=3)', lambda: sv.build_volume(d, refine=6, scene=s, refine_grid=3))
show('build_volume(bias=100.0)', lambda: sv.build_volume(d, bias=100.0))
show('build_volume(blur=True, blur_offset=1e300)', lambda: sv.build_volume(d, blur=True, blur_offset=1e300))
show('render(platform="bogus")', lambda: sv.render(sv.default_scene(), platform='bogus'))
show('capture_depth(device="gpu", platform="bogus")', lambda: sv.capture_depth(s, 32, 32, device='gpu', platform='bogus'))
show('capture_depth(point-light scene)', lambda: sv.capture_depth(sv.load_scene('/work/main/data/scenes/point/room.json'), 32, 32))
show('from_array(near=nan)', lambda: sv.DepthMap.from_array(np.array(d.depth), d.light_view, d.light_projection, float('nan'), d.far))
show('from_array(light_view=NaN matrix)', lambda: sv.DepthMap.from_array(np.array(d.depth), np.full((4,4), np.nan), d.light_projection, d.near, d.far))
show('from_array(0 rows x 5 columns)', lambda: sv.DepthMap.from_array(np.zeros((0,5),np.float32), d.light_view, d.light_projection, d.near, d.far))
show('from_array(1 x 1)', lambda: sv.DepthMap.from_array(np.ones((1,1),np.float32), d.light_view, d.light_projection, d.near, d.far))
show('validate(max_error=-0.1)', lambda: sv.validate(s, max_error=-0.1))
