# Parent makes one GL call, then forks; the child's first call is validate (or what argv[2] names).
import os as _os
ROOT = _os.path.abspath(_os.path.join(_os.path.dirname(__file__), "../../../.."))  # the repository
SV = _os.environ.get("SV", _os.path.join(ROOT, "build/apps/shadowvol"))  # the shadowvol binary
import shadowvol as sv, multiprocessing as mp, sys
sc = sv.load_scene(ROOT + "/data/scenes/fandisk.json")
pre = sys.argv[1]
if pre == "render": sv.render(sc, resolution=64, size=(160,120))
if pre == "gpucap": sv.capture_depth(sc, 64, 64, capture="back", device="gpu")
if pre == "validate": sv.validate(sc, resolution=64, size=(160,120))
def child(q):
    out = []
    for what in sys.argv[2].split(","):
        try:
            if what == "validate":
                v = sv.validate(sc, resolution=64, size=(160,120)); out.append(("validate", v["passed"], v["verdict"]["failures"]))
            elif what == "render":
                r = sv.render(sc, resolution=64, size=(160,120)); out.append(("render", int(r["stencil"].sum())))
        except Exception as e: out.append((what, "EXC", type(e).__name__, str(e)))
    q.put(out)
ctx = mp.get_context("fork"); q = ctx.Queue(); p = ctx.Process(target=child, args=(q,)); p.start(); p.join(120)
print("parent:", pre, "| child:", sys.argv[2], "| exit", p.exitcode, q.get() if not q.empty() else None)
