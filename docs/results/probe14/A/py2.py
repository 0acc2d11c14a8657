import shadowvol as sv, numpy as np, sys, time, resource
sc = sv.default_scene()
d = sv.capture_depth(sc, 64, 64)
print('depth dtype', d.depth.dtype, d.depth.shape, d.depth.flags['WRITEABLE'], d.light, d.capture, d.near, d.far)
def t(label, f):
    t0 = time.time()
    try:
        r = f(); print(f"{label}: OK {type(r).__name__} {time.time()-t0:.2f}s", str(r)[:200].replace('\n',' '))
    except Exception as e:
        print(f"{label}: {type(e).__name__}: {str(e)[:250]} ({time.time()-t0:.2f}s)")
    print(f"   maxrss {resource.getrusage(resource.RUSAGE_SELF).ru_maxrss//1024} MB"); sys.stdout.flush()
V, P = d.light_view, d.light_projection
def fa(arr, **kw): return sv.DepthMap.from_array(arr, V, P, d.near, d.far, light=d.light, **kw)
t('from_array 3x65536', lambda: fa(np.full((3, 65536), d.far*0.9, np.float32)))
t('from_array 3x65537', lambda: fa(np.full((3, 65537), d.far*0.9, np.float32)))
t('from_array 65536x3 build', lambda: sv.build_volume(fa(np.full((65536, 3), d.far*0.9, np.float32)))[2])
t('from_array 3x65536 build', lambda: sv.build_volume(fa(np.full((3, 65536), d.far*0.9, np.float32)))[2])
t('from_array 16385x16385 float32', lambda: fa(np.full((16385, 16385), np.inf, np.float32)))
big = np.full((12000, 12000), np.inf, np.float32); big[::2, ::2] = d.far*0.8
t('from_array 12000x12000 checker', lambda: fa(big))
m = fa(big)
t('build 12000 checker', lambda: sv.build_volume(m)[2])
