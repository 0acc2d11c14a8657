# whole default scene scaled by factor k (positions, sizes), into s2/
import json, os
D = '/tmp/probe13/B/s2'; os.makedirs(D, exist_ok=True)
for k in ['1e-300', '1e-200', '1e-100', '1e-30', '1e-10', '1e10', '1e11']:
    f = float(k)
    s = {"objects": [{"type": "plane", "name": "ground", "size": 20 * f},
                     {"type": "sphere", "name": "sphere", "radius": 1 * f, "detail": 3, "transform": {"translate": [0, 2 * f, 0]}}],
         "light": {"type": "spot", "position": [3 * f, 9 * f, 2 * f], "target": [-0.3 * f, 0, -0.2 * f], "fov": 55},
         "camera": {"eye": [0, 6 * f, 11 * f], "target": [0, 1 * f, 0], "fov": 45, "width": 320, "height": 240}}
    json.dump(s, open(f'{D}/spot_{k}.json', 'w'))
    s['light'] = {"type": "directional", "direction": [-0.3, -1, -0.2]}
    json.dump(s, open(f'{D}/dir_{k}.json', 'w'))
    s['light'] = {"type": "point", "position": [3 * f, 9 * f, 2 * f]}
    json.dump(s, open(f'{D}/point_{k}.json', 'w'))
