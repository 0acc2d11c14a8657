#!/usr/bin/env python3
"""run.py validate|build SCENE TAG -- extra options. Appends a JSON line to results.jsonl."""
import os as _os
ROOT = _os.path.abspath(_os.path.join(_os.path.dirname(__file__), "../../../.."))  # the repository
SV = _os.environ.get("SV", _os.path.join(ROOT, "build/apps/shadowvol"))  # the shadowvol binary
import json, os, subprocess, sys, time
BIN = SV; HERE = os.path.dirname(os.path.abspath(__file__))
def sh(args, to=300):
    t = time.time()
    p = subprocess.run(['nice', '-n', '5', 'timeout', str(to), BIN] + args, capture_output=True, text=True)
    return p.returncode, p.stdout, p.stderr, time.time() - t
def parse(rep):
    r = {}
    j = json.load(open(os.path.join(rep, 'report.json')))
    px = j['pixels']; m = j['againstExact']['method']
    G = lambda k, f: (j.get(k) or {}).get(f) if isinstance(j.get(k), dict) else None
    r.update(exS=px['exactShadowed'], exL=px['exactLit'], missed=m['missedShadow'], false=m['falseShadow'],
             err=round(100*m['errorFraction'], 4), svc=G('stencilVsCount', 'fraction'),
             svcDis=G('stencilVsCount', 'disagree'), zz=G('zfailVsZpass', 'fraction'),
             mesh=G('meshChecks', 'valid'), passed=j['passed'], fails=j['verdict']['failures'],
             warn=len(j.get('warnings', [])), causes=[G('errorCauses', 'resolution'), G('errorCauses', 'capture')],
             capture=j['options'].get('capture'))
    return r
def validate(scene, tag, opts, size='320x240'):
    rep = os.path.join(HERE, 'rep', f'{scene}__{tag}')
    sp = scene if scene.endswith('.json') else os.path.join(HERE, 'scenes', scene + '.json')
    rc, out, err, dt = sh(['validate', '--scene', sp, '--size', size, '--report', rep] + opts)
    r = {'cmd': 'validate', 'scene': scene, 'tag': tag, 'opts': opts, 'rc': rc, 't': round(dt, 1)}
    try:
        r.update(parse(rep))
    except Exception as e:
        r['noreport'] = str(e)[:100]
    if rc not in (0, 3) or 'nan' in (out + err).lower().replace('nanoseconds', ''):
        r['stderr'] = err[-600:]; r['stdout'] = out[-400:]
    open(os.path.join(HERE, 'results.jsonl'), 'a').write(json.dumps(r) + '\n')
    return r
def build(scene, tag, opts, ext='ply'):
    sp = scene if scene.endswith('.json') else os.path.join(HERE, 'scenes', scene + '.json')
    os.makedirs(os.path.join(HERE, 'vol'), exist_ok=True)
    out = os.path.join(HERE, 'vol', f'{scene}__{tag}.{ext}')
    rc, o, e, dt = sh(['build', '--scene', sp, '--out', out, '--json'] + opts)
    r = {'cmd': 'build', 'scene': scene, 'tag': tag, 'opts': opts, 'rc': rc, 't': round(dt, 1)}
    if rc == 0:
        rc2, o2, e2, _ = sh(['check', out, '--json'])
        r['check'] = rc2
        try:
            cj = json.loads(o2); r['checkSummary'] = {k: cj[k] for k in cj if k in ('valid', 'triangles', 'volume', 'failures')}
        except Exception: r['checkOut'] = (o2 + e2)[-300:]
        if rc2 != 0: r['checkOut'] = (o2 + e2)[-600:]
        try:
            bj = json.loads(o); r['tris'] = bj.get('volume', bj).get('triangles') if isinstance(bj.get('volume', bj), dict) else None
        except Exception: pass
    else:
        r['stderr'] = e[-600:]
    if 'nan' in (o + e).lower():
        r['nan?'] = True
    open(os.path.join(HERE, 'results.jsonl'), 'a').write(json.dumps(r) + '\n')
    return r
if __name__ == '__main__':
    cmd, scene, tag = sys.argv[1:4]; opts = sys.argv[4:]
    print(json.dumps((validate if cmd == 'validate' else build)(scene, tag, opts)))
