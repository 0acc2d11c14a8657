import shadowvol as sv, numpy as np, sys, time, resource, traceback
sc = sv.default_scene()
def t(label, f):
    t0 = time.time()
    try:
        r = f(); print(f"{label}: OK {type(r).__name__} {time.time()-t0:.2f}s", str(r)[:150].replace('\n',' '))
    except Exception as e:
        print(f"{label}: {type(e).__name__}: {str(e)[:250]} ({time.time()-t0:.2f}s)")
    print(f"   maxrss {resource.getrusage(resource.RUSAGE_SELF).ru_maxrss//1024} MB"); sys.stdout.flush()
t('capture 100000x100000', lambda: sv.capture_depth(sc, 100000, 100000))
t('capture 65536x3', lambda: sv.capture_depth(sc, 65536, 3))
t('capture 3x65536', lambda: sv.capture_depth(sc, 3, 65536))
t('capture 16384x16384', lambda: sv.capture_depth(sc, 16384, 16384))
t('capture 2**31 x 3', lambda: sv.capture_depth(sc, 2**31, 3))
t('capture 2**40 x 3', lambda: sv.capture_depth(sc, 2**40, 3))
t('capture 65537x65537', lambda: sv.capture_depth(sc, 65537, 65537))
t('receiver_texel_size 0', lambda: sc.receiver_texel_size(0))
t('receiver_texel_size -1', lambda: sc.receiver_texel_size(-1))
t('receiver_texel_size 2**31-1', lambda: sc.receiver_texel_size(2**31-1))
t('fit_light_to_view 2**31-1', lambda: sv.default_scene().fit_light_to_view(2**31-1))
t('fit_light_to_view 0', lambda: sv.default_scene().fit_light_to_view(0))
t('fit_light_to_view 1', lambda: sv.default_scene().fit_light_to_view(1))
