import json, sys
from run import validate, build
names = json.load(open(sys.argv[3] if len(sys.argv) > 3 else 'set1.json'))
V = [('gpu256', ['--resolution', '256']),
     ('exp256', ['--resolution', '256', '--volume', 'explicit']),
     ('expR6', ['--resolution', '256', '--volume', 'explicit', '--refine', '6']),
     ('expR6G4', ['--resolution', '256', '--volume', 'explicit', '--refine', '6', '--refine-grid', '4']),
     ('gpuR6', ['--resolution', '256', '--refine', '6']),
     ('sm2048', ['--resolution', '2048', '--method', 'shadowmap']),
     ('sil', ['--method', 'silhouette'])]
B = [('back', ['--capture', 'back']), ('front', ['--capture', 'front']), ('entry', ['--capture', 'entry']),
     ('mid', ['--capture', 'midpoint']), ('autoR6', ['--refine', '6']), ('entryR6G4', ['--capture', 'entry', '--refine', '6', '--refine-grid', '4']),
     ('frontR6blur', ['--capture', 'front', '--refine', '6', '--blur']), ('fixedquad', ['--triangulation', 'fixed', '--cap', 'quad']),
     ('backblurfixed', ['--capture', 'back', '--blur', '--triangulation', 'fixed'])]
for n in names[int(sys.argv[1]):int(sys.argv[2])]:
    for tag, o in V:
        r = validate(n, tag, o); print(json.dumps(r), flush=True)
    for tag, o in B:
        r = build(n, tag, o + ['--resolution', '192']); print(json.dumps(r), flush=True)
