#!/usr/bin/env python3
"""F2: the same uniform scale given as `scale` and as `matrix` (writes mx/*.json)."""
import os as _os
ROOT = _os.path.abspath(_os.path.join(_os.path.dirname(__file__), "../../../.."))  # the repository
SV = _os.environ.get("SV", _os.path.join(ROOT, "build/apps/shadowvol"))  # the shadowvol binary
import json, os, subprocess
os.makedirs('mx', exist_ok=True)
def sc(tr):
    return {'objects': [{'type': 'plane', 'size': 8, 'transform': {'scale': 1e-5}}, {'type': 'box', 'size': 1, 'transform': tr}],
            'light': {'type': 'directional', 'direction': [0.3, -1, 0.2]}, 'camera': {'eye': [0, 4e-5, 7e-5], 'target': [0, 0, 0]}}
cases = {'scale1e-5': {'scale': 1e-5, 'translate': [0, 1e-5, 0]},
         'mat_diag1e-5': {'matrix': [1e-5,0,0,0, 0,1e-5,0,1e-5, 0,0,1e-5,0, 0,0,0,1]},
         'mat_diag3e-5': {'matrix': [3e-5,0,0,0, 0,3e-5,0,1e-5, 0,0,3e-5,0, 0,0,0,1]},
         'mat_diag1e-4': {'matrix': [1e-4,0,0,0, 0,1e-4,0,1e-5, 0,0,1e-4,0, 0,0,0,1]}}
for k, tr in cases.items():
    p = f'mx/{k}.json'; json.dump(sc(tr), open(p, 'w'))
    r = subprocess.run([SV, 'scene', '--scene', p], capture_output=True, text=True)
    print(k, 'exit', r.returncode, (r.stderr.strip().splitlines() or [''])[-1][:200])
