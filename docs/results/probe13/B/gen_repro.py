# Self-contained scene generator for findings.md (writes into /tmp/probe13/B/r/)
import json, os
D = '/tmp/probe13/B/r'; os.makedirs(D, exist_ok=True)
def base(f=1.0):
    return {"objects": [{"type": "plane", "name": "ground", "size": 20 * f},
                        {"type": "sphere", "name": "sphere", "radius": 1 * f, "detail": 3, "transform": {"translate": [0, 2 * f, 0]}}],
            "light": {"type": "spot", "position": [3 * f, 9 * f, 2 * f], "target": [-0.3 * f, 0, -0.2 * f], "fov": 55},
            "camera": {"eye": [0, 6 * f, 11 * f], "target": [0, 1 * f, 0], "fov": 45, "width": 320, "height": 240}}
def w(name, s): json.dump(s, open(f'{D}/{name}.json', 'w'))
# F1: directional light with a tiny extent
for e in ['1e-200', '5e-324', '1e-100']:
    s = base(); s['light'] = {"type": "directional", "direction": [0, -1, 0], "extent": float(e)}; w('dir_extent_' + e, s)
# F2: directional light position far along its direction
for y in ['1e6', '1e7']:
    s = base(); s['light'] = {"type": "directional", "direction": [0, -1, 0], "position": [0, float(y), 0]}; w('dir_pos_' + y, s)
# F3: the default layout scaled down
for k in ['1e-8', '1e-9', '1e-10', '1e-30']:
    w('spot_scale_' + k, base(float(k)))
# F7: directional light with a huge extent
s = base(); s['light'] = {"type": "directional", "direction": [0, -1, 0], "extent": 1e12}; w('dir_extent_1e12', s)
# F9: mesh file name with a NUL
s = base(); s['objects'][1] = {"type": "mesh", "file": "cube.obj\u0000.x"}; w('mesh_nul', s)
open(f'{D}/cube.obj', 'w').write('v -0.5 -0.5 -0.5\nv 0.5 -0.5 -0.5\nv 0.5 0.5 -0.5\nv -0.5 0.5 -0.5\nv -0.5 -0.5 0.5\nv 0.5 -0.5 0.5\nv 0.5 0.5 0.5\nv -0.5 0.5 0.5\nf 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\n')
w('default', base())
