"""CPU (Embree) vs GPU depth maps of the same scene/capture: texels hit in one only, max relative depth difference."""
import os as _os
ROOT = _os.path.abspath(_os.path.join(_os.path.dirname(__file__), "../../../.."))  # the repository
SV = _os.environ.get("SV", _os.path.join(ROOT, "build/apps/shadowvol"))  # the shadowvol binary
import json, math, struct, subprocess, sys, os
BIN = SV
def rd(p):
    f = open(p, 'rb'); f.readline(); wh = f.readline().split(); sc = float(f.readline())
    w, h = int(wh[0]), int(wh[1]); return w, h, struct.unpack(('<' if sc < 0 else '>') + '%df' % (w*h), f.read())
def run(scene, cap, res=256, extra=()):
    out = {}
    for dev in ('cpu', 'gpu'):
        p = f'dm/{os.path.basename(scene)[:-5]}_{cap}_{dev}.pfm'
        r = subprocess.run(['nice', '-n', '5', 'timeout', '300', BIN, 'depth', '--scene', scene, '--resolution', str(res), '--capture', cap, '--device', dev, '--out', p] + list(extra), capture_output=True, text=True)
        if r.returncode: return {'scene': scene, 'cap': cap, 'err': r.stderr[-300:]}
        out[dev] = (rd(p), json.load(open(p + '.json')))
    (w, h, a), ja = out['cpu']; (_, _, b), jb = out['gpu']
    far = ja['far']
    def hit(x): return math.isfinite(x) and x < far * (1 - 1e-7)
    onlyc = sum(1 for x, y in zip(a, b) if hit(x) and not hit(y)); onlyg = sum(1 for x, y in zip(a, b) if hit(y) and not hit(x))
    rel = [abs(x - y) / max(abs(x), 1e-30) for x, y in zip(a, b) if hit(x) and hit(y)]
    big = sum(1 for v in rel if v > 1e-4)
    return {'scene': os.path.basename(scene), 'cap': cap, 'hitCpuOnly': onlyc, 'hitGpuOnly': onlyg, 'maxRel': max(rel) if rel else None, 'n>1e-4': big, 'n': len(rel)}
if __name__ == '__main__':
    for s in sys.argv[1:]:
        for cap in ('back', 'front', 'entry', 'midpoint'):
            print(json.dumps(run(s, cap)), flush=True)
