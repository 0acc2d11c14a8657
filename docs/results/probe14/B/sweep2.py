import json, sys
from run import validate, build
names = json.load(open('set2.json'))
V = [('gpu256', ['--resolution', '256']),
     ('exp256', ['--resolution', '256', '--volume', 'explicit']),
     ('expR6', ['--resolution', '256', '--volume', 'explicit', '--refine', '6']),
     ('expR6G4', ['--resolution', '256', '--volume', 'explicit', '--refine', '6', '--refine-grid', '4']),
     ('gpuR6', ['--resolution', '256', '--refine', '6']),
     ('sm2048', ['--resolution', '2048', '--method', 'shadowmap'])]
for n in names[int(sys.argv[1]):int(sys.argv[2])]:
    for tag, o in V:
        r = validate(n, tag, o); print(json.dumps(r), flush=True)
    r = build(n, 'R6G4', ['--resolution', '192', '--refine', '6', '--refine-grid', '4']); print(json.dumps(r), flush=True)
    r = build(n, 'front', ['--resolution', '192', '--capture', 'front']); print(json.dumps(r), flush=True)
