import shadowvol as sv, numpy as np, time, resource, sys
sc = sv.default_scene()
def t(label, f):
    t0 = time.time()
    try:
        r = f(); print(f"{label}: OK {time.time()-t0:.2f}s", str(r)[:150].replace('\n',' '))
    except Exception as e:
        print(f"{label}: {type(e).__name__}: {str(e)[:200]} ({time.time()-t0:.2f}s)")
    print(f"   maxrss {resource.getrusage(resource.RUSAGE_SELF).ru_maxrss//1024} MB"); sys.stdout.flush()
#t('validate 16384^2', lambda: sv.validate(sc, resolution=64, size=(16384, 16384))['passed'])
t('validate 0x0', lambda: sv.validate(sc, resolution=64, size=(0, 0))['passed'])
t('validate -1', lambda: sv.validate(sc, resolution=64, size=(-1, 5))['passed'])
t('render res 16384', lambda: sv.render(sc, resolution=16384, size=(64, 48))['total_ms'])
t('validate max_error nan', lambda: sv.validate(sc, resolution=64, size=(64, 48), max_error=float('nan'))['passed'])
t('validate max_error 2', lambda: sv.validate(sc, resolution=64, size=(64, 48), max_error=2.0)['passed'])
t('validate report_dir ""', lambda: sv.validate(sc, resolution=64, size=(64, 48), report_dir='')['passed'])
V = np.zeros((5, 3)); F = np.array([[0, 1, 2]], dtype=np.int64) * (2**33)
t('export F 2**33', lambda: sv.export(V, F, 'k/x.ply'))
F2 = np.array([[0, 1, 2], [1, 2, 3]], dtype=np.uint64); F2[1, 2] = 2**64 - 1
t('export F uint64 max', lambda: sv.export(V, F2, 'k/x.ply'))
t('export V strided', lambda: sv.export(np.random.rand(10, 6)[:, ::2], np.array([[0, 1, 2]]), 'k/x.obj'))
t('export F strided', lambda: sv.export(np.random.rand(10, 3), np.arange(18).reshape(3, 6)[:, ::2] % 10, 'k/x.obj'))
t('export float32 V', lambda: sv.export(np.random.rand(10, 3).astype(np.float32), np.array([[0, 1, 2]]), 'k/x.obj'))
t('export V int', lambda: sv.export(np.arange(30).reshape(10, 3), np.array([[0, 1, 2]]), 'k/x.obj'))
t('export F bool', lambda: sv.export(np.random.rand(10, 3), np.array([[True, False, True]]), 'k/x.obj'))
t('export huge F', lambda: sv.export(np.random.rand(3, 3), np.zeros((30_000_000, 3), np.int32), 'k/x.ply'))
