# pickle with protocol 0 or 1 (or obj.__reduce__(), copyreg's path) aborts the interpreter (SIGABRT,
# exit 134): "terminate called after throwing ... instance allocation failed: new instance has no
# pybind11-registered base types". Same for Scene (which should raise "cannot pickle").
import sys, pickle; sys.path.insert(0, '/tmp/probe21/py'); import shadowvol as sv
d = sv.capture_depth(sv.default_scene(), 32, 32)
which = sys.argv[1] if len(sys.argv) > 1 else 'depth'
obj = d if which == 'depth' else sv.default_scene()
print('pickling', which, 'with protocol 0 ...', flush=True)
pickle.dumps(obj, protocol=0)
print('not reached')
