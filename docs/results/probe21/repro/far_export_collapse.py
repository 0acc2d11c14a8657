# A scene 1e7 from the world origin: build_volume returns world V; sv.export writes float32 world
# coordinates without rebasing or refusing, so every vertex rounds onto a 1-unit grid.
import sys, numpy as np; sys.path.insert(0, '/tmp/probe21/py'); import shadowvol as sv
s = sv.load_scene('/tmp/probe21/work/far/far.json')
print('scene origin', s.origin, s.warnings)
d = sv.capture_depth(s, 128, 128)
V, F, st = sv.build_volume(d)
print('V', V.shape, 'unique positions in double:', len(np.unique(V, axis=0)))
for ext in ['ply', 'obj', 'off', 'stl', 'glb']:
    sv.export(V, F, f'/tmp/probe21/work/far/vol.{ext}')
    print(ext, 'written without error')
lines = open('/tmp/probe21/work/far/vol.obj').read().splitlines()
vs = np.array([[float(x) for x in l.split()[1:]] for l in lines if l.startswith('v ')])
print('OBJ: unique positions as written:', len(np.unique(vs, axis=0)), 'of', len(vs))
print('max position error written vs V:', np.abs(vs - V).max())
print(lines[:4])
