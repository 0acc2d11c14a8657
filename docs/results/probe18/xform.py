# usage: xform.py SRC.json DST.json SCALE DX DY DZ: the scene scaled by SCALE about the origin, then moved by (DX, DY, DZ)
import json, sys, os
def transform(src, dst, s, off):
    d=json.load(open(src)); srcdir=os.path.dirname(os.path.abspath(src))
    P=lambda p: [p[i]*s+off[i] for i in range(3)]
    for o in d['objects']:
        if o['type']=='mesh': o['file']=os.path.normpath(os.path.join(srcdir,o['file']))
        t=o.get('transform',{})
        assert 'matrix' not in t
        sc=t.get('scale',1)
        t['scale']=[x*s for x in sc] if isinstance(sc,list) else sc*s
        t['translate']=P(t.get('translate',[0,0,0]))
        o['transform']=t
    lights=d['lights'] if 'lights' in d else [d['light']]
    for l in lights:
        for k in ('position','target'):
            if k in l: l[k]=P(l[k])
        for k in ('near','far','extent'):
            if k in l: l[k]*=s
    c=d['camera']
    for k in ('eye','target'):
        if k in c: c[k]=P(c[k])
    for k in ('near','far'):
        if k in c: c[k]*=s
    json.dump(d,open(dst,'w'),indent=1)
transform(sys.argv[1],sys.argv[2],float(sys.argv[3]),[float(x) for x in sys.argv[4:7]])
