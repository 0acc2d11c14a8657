import json
from run import validate
for n in json.load(open('set8.json')):
    for tag, o in [('gpu256', ['--resolution', '256']), ('expR6', ['--resolution', '256', '--volume', 'explicit', '--refine', '6'])]:
        print(json.dumps(validate(n, tag, o)), flush=True)
for b in ['anchor_spot', 'pinion_dir', 'rotor_down']:
    for w in ['id', 's1e-3', 's1e4', 't1e6', 's1e4t1e6']:
        n = f'inv_{b}_{w}'
        for tag, o in [('fvgpu', ['--resolution', '256', '--fit', 'view']), ('fvR6', ['--resolution', '256', '--fit', 'view', '--volume', 'explicit', '--refine', '6']),
                       ('blur', ['--resolution', '256', '--blur', '--triangulation', 'fixed']), ('mid', ['--resolution', '256', '--capture', 'midpoint', '--volume', 'explicit'])]:
            print(json.dumps(validate(n, tag, o)), flush=True)
