"""odd depth-map resolutions and image widths on the GPU paths (after F0)."""
import json
from run import validate, build
S = ['anchor_spot', 'pinion_dir', 'geosphere_point', 'threepeaks_down']
for n in S:
    for res in ['5', '13', '101', '255', '257']:
        for tag, o, size in [('gpu', [], '161x97'), ('gpuR6', ['--refine', '6'], '320x97'), ('expR6', ['--volume', 'explicit', '--refine', '6'], '161x97'),
                             ('sm', ['--method', 'shadowmap'], '161x97'), ('zfail', ['--count', 'zfail'], '161x97'),
                             ('kq', ['--gpu-draw', 'kept-quads'], '161x97'), ('cm', ['--gpu-draw', 'compute-mesh'], '161x97')]:
            if 'point' in n and tag in ('kq', 'cm'): continue
            r = validate(n, f'r{res}_{tag}', ['--resolution', res] + o, size=size); print(json.dumps(r), flush=True)
        if 'point' not in n:
            r = build(n, f'r{res}_gpudev', ['--resolution', res, '--device', 'gpu']); print(json.dumps(r), flush=True)
