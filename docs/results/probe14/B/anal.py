import json, sys, collections
from run import parse
import os
rs = [json.loads(l) for l in open('results.jsonl')]
for r in rs:
    if r['cmd'] == 'validate' and 'noreport' in r and r['rc'] in (0, 3):
        try:
            r.update(parse(os.path.join('rep', r['scene'] + '__' + r['tag']))); del r['noreport']
        except Exception as e: pass
for r in rs:
    bad = []
    if r['rc'] not in (0, 3): bad.append(f"rc={r['rc']}")
    if r['cmd'] == 'validate':
        if 'noreport' in r: bad.append('noreport')
        if r.get('svc') is not None and r['svc'] < 0.9999: bad.append(f"svc={r['svc']:.5f} dis={r['svcDis']}")
        if r.get('zz') is not None and r['zz'] < 0.9999: bad.append(f"zz={r['zz']}")
        if r.get('mesh') is False: bad.append('mesh invalid')
        if r.get('passed') is False: bad.append(f"FAILED {r.get('fails')}")
    else:
        if r['rc'] == 0 and r.get('check') != 0: bad.append(f"check={r.get('check')} {r.get('checkOut','')[:200]}")
        if r['rc'] != 0: bad.append(r.get('stderr', '')[-200:])
    if r.get('nan?') or 'stderr' in r and 'nan' in r['stderr'].lower(): bad.append('NAN?')
    if bad: print(r['cmd'], r['scene'], r['tag'], '|', '; '.join(bad))
# refined worse than unrefined / vs sm2048
by = collections.defaultdict(dict)
for r in rs:
    if r['cmd'] == 'validate' and 'err' in r: by[r['scene']][r['tag']] = r
print('--- error table (err %% missed/false)')
for s, d in by.items():
    row = ' '.join(f"{t}:{d[t]['err']}({d[t]['missed']}/{d[t]['false']})" for t in d)
    flag = ''
    if 'expR6' in d and 'exp256' in d and d['expR6']['err'] > 1.5 * d['exp256']['err'] + 0.02: flag += ' R6>exp!'
    if 'expR6G4' in d and 'expR6' in d and d['expR6G4']['err'] > 1.5 * d['expR6']['err'] + 0.02: flag += ' G4>R6!'
    if 'gpuR6' in d and 'expR6' in d and abs(d['gpuR6']['err'] - d['expR6']['err']) > 0.05 + 0.5*d['expR6']['err']: flag += ' gpuR6!=expR6'
    if 'gpu256' in d and 'exp256' in d and abs(d['gpu256']['err'] - d['exp256']['err']) > 0.05 + 0.5*d['exp256']['err']: flag += ' gpu!=exp'
    print(s, d[next(iter(d))]['exS'], row, flag)
