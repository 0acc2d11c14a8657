#!/usr/bin/env python3
# Probe 19 (findings.md here): one line per validate --report folder: error %, missed, false, pixels, errorCauses, verdict, stencil vs count.
# Usage: python3 docs/results/probe19/pct.py DIR...
import json,sys
for d in sys.argv[1:]:
    j=json.load(open(d+'/report.json'))
    m=j['againstExact']['method']
    ec=j.get('errorCauses')
    ec={k:ec.get(k) for k in ('resolution','capture')} if isinstance(ec,dict) else '-'
    v=j['verdict']; vv='PASS' if v.get('accurate') and v.get('consistent') else 'FAIL '+str(v.get('failures'))
    s=j.get('stencilVsCount'); sv=s.get('fraction') if isinstance(s,dict) else '-'
    print(d, '%.4f%%'%(100*m['errorFraction']), 'missed',m['missedShadow'],'false',m['falseShadow'],'of',m['pixels'],'causes',ec,vv,'svc',sv)
