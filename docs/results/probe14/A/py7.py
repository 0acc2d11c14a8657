import shadowvol as sv, time, sys
t0 = time.time()
try:
    r = sv.validate(sv.default_scene(), resolution=64, size=(int(sys.argv[1]), int(sys.argv[1])))
    print('OK', r['passed'], time.time() - t0)
except Exception as e:
    print(type(e).__name__, str(e)[:300], time.time() - t0)
