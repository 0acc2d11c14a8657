import signal; signal.signal(signal.SIGINT, signal.default_int_handler)
import shadowvol as sv, numpy as np, sys, time, resource
n = int(sys.argv[1]); step = int(sys.argv[2]) if len(sys.argv) > 2 else 2
sc = sv.default_scene(); d = sv.capture_depth(sc, 64, 64)
big = np.full((n, n), np.inf, np.float32); big[::step, ::step] = d.far*0.8
m = sv.DepthMap.from_array(big, d.light_view, d.light_projection, d.near, d.far, light=d.light)
t0 = time.time()
V, F, st = sv.build_volume(m)
print(n, 'V', V.shape, 'F', F.shape, f'{time.time()-t0:.1f}s', 'maxrss MB', resource.getrusage(resource.RUSAGE_SELF).ru_maxrss//1024)
