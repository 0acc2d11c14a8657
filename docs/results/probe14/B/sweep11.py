import json
from run import validate
names = json.load(open('set1.json')) + json.load(open('set3.json')) + json.load(open('set6.json'))
for n in names:
    for tag, o, size in [('odd_gpuR6', ['--resolution', '200', '--refine', '6'], '173x131'),
                         ('odd_expG4', ['--resolution', '300', '--volume', 'explicit', '--refine', '6', '--refine-grid', '4'], '257x143'),
                         ('odd_blur', ['--resolution', '100', '--blur', '--triangulation', 'fixed'], '199x101')]:
        r = validate(n, tag, o, size=size)
        print(json.dumps(r), flush=True)
