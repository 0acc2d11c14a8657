import json, collections, os
from run import parse
rs = [json.loads(l) for l in open('results.jsonl')]
T = collections.defaultdict(dict); Bd = collections.defaultdict(dict)
for r in rs:
    if not r['scene'].startswith('inv_'): continue
    base, w = r['scene'][4:].rsplit('_', 1) if False else (None, None)
    parts = r['scene'][4:].split('_'); base = '_'.join(parts[:2]); w = '_'.join(parts[2:])
    if r['cmd'] == 'validate':
        if 'noreport' in r:
            try: r.update(parse(os.path.join('rep', r['scene'] + '__' + r['tag'])))
            except Exception: pass
        T[base].setdefault(w, {})[r['tag']] = r
    else:
        Bd[base].setdefault(w, {})[r['tag']] = r
for base in T:
    print('==', base)
    tags = ['gpu256', 'exp256', 'expR6', 'expR6G4', 'gpuR6', 'sm2048']
    print('%-16s %6s ' % ('transform', 'exS') + ' '.join('%-18s' % t for t in tags) + ' builds(tris,check)')
    for w, d in T[base].items():
        ex = next(iter(d.values())).get('exS')
        cells = []
        for t in tags:
            r = d.get(t)
            if not r: cells.append('-'); continue
            if 'err' not in r: cells.append(f"rc{r['rc']}"); continue
            s = f"{r['err']:.3f}({r['missed']}/{r['false']})"
            if r.get('svc') is not None and r['svc'] < 0.9999: s += f"!svc{r['svc']:.4f}"
            if not r['passed']: s += 'F'
            cells.append(s)
        b = Bd[base].get(w, {})
        bs = ' '.join(f"{t}:{x.get('tris')},{x.get('check', 'rc'+str(x['rc']))}" for t, x in b.items())
        print('%-16s %6s ' % (w, ex) + ' '.join('%-18s' % c for c in cells) + ' ' + bs)
