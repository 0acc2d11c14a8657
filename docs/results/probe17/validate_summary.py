#!/usr/bin/env python3
"""Reads validate --json on stdin; prints error %, missed, false, stencil agreement, verdict, errorCauses."""
import json,sys
d=json.load(sys.stdin)
def one(d,tag):
    m=d['againstExact']['method']
    ec=d.get('errorCauses')
    print(tag,'err%%=%.4f missed=%s false=%s stencilVsCount=%s verdict=%s causes=%s'%(100*m['errorFraction'],m['missedShadow'],m['falseShadow'],(d.get('stencilVsCount') or {}).get('fraction') if isinstance(d.get('stencilVsCount'),dict) else d.get('stencilVsCount'),d.get('verdict'),json.dumps(ec)[:200]))
if 'lights' in d:
    for i,l in enumerate(d['lights']): one(l,'light%d'%i)
else: one(d,'')
