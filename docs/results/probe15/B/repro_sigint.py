import shadowvol as sv, threading, os, signal, time
sc = sv.load_scene("/work/main/data/scenes/bunny.json")
threading.Timer(0.5, lambda: os.kill(os.getpid(), signal.SIGINT)).start()
t = time.time()
try: sv.capture_depth(sc, 8192, 8192, capture="back"); print("returned", round(time.time()-t,2))
except KeyboardInterrupt: print("KeyboardInterrupt raised", round(time.time()-t,2), "s after the call began (SIGINT sent at 0.5 s)")
