import json
from run import validate
for n in json.load(open('set9.json')):
    for tag, o in [('gpu256', ['--resolution', '256']), ('exp256', ['--resolution', '256', '--volume', 'explicit']),
                   ('expR6', ['--resolution', '256', '--volume', 'explicit', '--refine', '6']), ('gpuR6', ['--resolution', '256', '--refine', '6']),
                   ('sm2048', ['--resolution', '2048', '--method', 'shadowmap'])]:
        print(json.dumps(validate(n, tag, o)), flush=True)
