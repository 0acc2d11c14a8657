"""build --device cpu vs gpu: triangle counts and enclosed volume (check --json) per capture."""
import os as _os
ROOT = _os.path.abspath(_os.path.join(_os.path.dirname(__file__), "../../../.."))  # the repository
SV = _os.environ.get("SV", _os.path.join(ROOT, "build/apps/shadowvol"))  # the shadowvol binary
import json, subprocess, sys
BIN = SV
def b(scene, cap, dev, extra=()):
    out = f'/tmp/probe14/B/vol/cb_{scene}_{cap}_{dev}.ply'
    r = subprocess.run(['nice', '-n', '5', 'timeout', '300', BIN, 'build', '--scene', f'scenes/{scene}.json', '--resolution', '192', '--capture', cap, '--device', dev, '--out', out] + list(extra), capture_output=True, text=True)
    if r.returncode: return ('rc', r.returncode, r.stderr[-200:])
    c = json.loads(subprocess.run([BIN, 'check', out, '--json'], capture_output=True, text=True).stdout)
    return (c['triangles'], round(c['volume'], 6), c['valid'])
for s in json.load(open('set1.json')):
    if 'point' in s: continue
    for cap in ('back', 'front', 'entry', 'midpoint'):
        a = b(s, cap, 'cpu'); g = b(s, cap, 'gpu')
        flag = '' if a[0] == 'rc' or g[0] == 'rc' or abs(a[1] - g[1]) <= 1e-4 * abs(a[1]) + 1e-9 else '  <-- volume differs'
        print(s, cap, a, g, flag, flush=True)
