# Low-severity inconsistencies in the Python API.
import sys, numpy as np, warnings; sys.path.insert(0, '/tmp/probe21/py'); import shadowvol as sv
s = sv.default_scene(); d = sv.capture_depth(s, 64, 64)
V, F, _ = sv.build_volume(d)
def show(label, f):
    try: r = f(); print(label, '-> accepted', r if not isinstance(r, tuple) else '')
    except Exception as e: print(label, '->', type(e).__name__ + ':', str(e)[:160])
warnings.simplefilter('ignore')
show('export(V as complex)  [from_array refuses complex]', lambda: sv.export(V.astype(complex), F, '/tmp/probe21/work/c.ply'))
show('export(V as bool)', lambda: sv.export(np.ones((3,3),bool), np.array([[0,1,2]]), '/tmp/probe21/work/b.ply'))
show('export(V, F.tolist())  [V.tolist() is accepted]', lambda: sv.export(V, F.tolist(), '/tmp/probe21/work/l.ply'))
show('export(.., "x.PLY") vs DepthMap.save("x.PFM"):', lambda: sv.export(V, F, '/tmp/probe21/work/x.PLY'))
show('   DepthMap.save("x.PFM")', lambda: d.save('/tmp/probe21/work/x.PFM'))
show('export to a folder: attributes', lambda: (__import__('os').makedirs('/tmp/probe21/work/f.ply', exist_ok=True), sv.export(V, F, '/tmp/probe21/work/f.ply')))
try: sv.export(V, F, '/tmp/probe21/work/f.ply')
except sv.InputError as e: print('   source/field/value =', repr(e.source), repr(e.field), repr(e.value))
a = sv.build_volume(d)[0]; b = sv.build_volume(d, flatten_cap=None)[0]
print('build_volume(flatten_cap=None) silently = flatten_cap=False:', len(a), 'vs', len(b), 'vertices')
show('build_volume(refine=True, scene=s) (bool as int)', lambda: sv.build_volume(d, refine=True, scene=s))
show('capture_depth(refine=99) [build_volume refuses refine > 16]', lambda: sv.capture_depth(s, 32, 32, refine=99))
import time; t = time.time()
show('validate(report_dir="")  [CLI refuses --report "" up front]', lambda: sv.validate(s, resolution=64, size=(64,48), report_dir=''))
print('   (refused after the frame was rendered and validated: %.2f s)' % (time.time() - t))
