#!/usr/bin/env python3
# usage: probe.py scene.json [extra validate args...]
# SV: the binary (default build/apps/shadowvol of the repository this file is in); outputs under out/probe18.
import json, subprocess, sys, os
ROOT=os.path.abspath(os.path.join(os.path.dirname(__file__), '..', '..', '..'))
SV=os.path.abspath(os.environ.get('SV', os.path.join(ROOT, 'build', 'apps', 'shadowvol')))
sys.argv[1]=os.path.abspath(sys.argv[1])
sc=sys.argv[1]; extra=sys.argv[2:]
base=os.path.splitext(os.path.basename(sc))[0]
out=os.path.join(ROOT,'out','probe18',base)
os.makedirs(os.path.dirname(out),exist_ok=True)
def run(args, t=120):
    try:
        p=subprocess.run(args,capture_output=True,text=True,timeout=t,cwd=ROOT)
        return p.returncode,p.stdout,p.stderr
    except subprocess.TimeoutExpired:
        return 'TIMEOUT','',''
rc,o,e=run([SV,'scene','--scene',sc,'--json'])
print(f'[scene] rc={rc}', e.strip()[:800])
if rc==0:
    d=json.loads(o); L=d['light']; C=d['camera']
    print('  light near/far', L.get('near'), L.get('far'), 'cam', C.get('near'), C.get('far'), 'origin', d.get('origin'))
if rc!=0 and '--force' not in extra: sys.exit()
extra=[x for x in extra if x!='--force']
rc,o,e=run([SV,'build','--scene',sc,'--refine','6','--json','--out',out+'.ply'])
print(f'[build] rc={rc}', e.strip()[:800])
if rc==0:
    d=json.loads(o); print('  build', {k:d.get(k) for k in ['triangles','vertices']} if 'triangles' in d else list(d.keys()))
    rc2,o2,e2=run([SV,'check',out+'.ply'])
    print(f'[check] rc={rc2}', o2.strip().splitlines()[-1] if o2.strip() else '', e2.strip()[:300])
rc,o,e=run([SV,'validate','--scene',sc,'--volume','explicit','--refine','6','--json','--report',out+'_rep']+extra)
print(f'[validate] rc={rc}', e.strip()[:800])
if o.strip():
    try:
        d=json.loads(o); ae=d['againstExact']['method']; sv_=d['stencilVsCount']
        print('  err',ae['errorFraction'],'missed',ae['missedShadow'],'false',ae['falseShadow'],'exactShadowed',d['pixels']['exactShadowed'],'agree',sv_['fraction'],'passed',d['passed'],d['verdict']['failures'])
    except Exception as ex: print('  parse fail',ex,o[:300])
