import json, sys
from run import validate, build
names = json.load(open(sys.argv[1]))
V = [('gpu256', ['--resolution', '256']), ('exp256', ['--resolution', '256', '--volume', 'explicit']),
     ('expR6', ['--resolution', '256', '--volume', 'explicit', '--refine', '6']),
     ('expR6G4', ['--resolution', '256', '--volume', 'explicit', '--refine', '6', '--refine-grid', '4']),
     ('gpuR6', ['--resolution', '256', '--refine', '6']), ('gpuFront', ['--resolution', '256', '--capture', 'front']),
     ('rays', ['--resolution', '256', '--volume', 'explicit', '--refine', '6', '--depth-from', 'rays'])]
for n in names:
    for tag, o in V:
        print(json.dumps(validate(n, tag, o)), flush=True)
    print(json.dumps(build(n, 'R6G4', ['--resolution', '192', '--refine', '6', '--refine-grid', '4'])), flush=True)
    print(json.dumps(build(n, 'gpudev', ['--resolution', '192', '--device', 'gpu', '--capture', 'front'])), flush=True)
