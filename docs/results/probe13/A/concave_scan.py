#!/usr/bin/env python3
"""Lists OFF/OBJ files with concave (non-convex) planar polygon faces, which a fan from corner 0 may triangulate outside the polygon."""
import sys, glob, math
def faces_off(fn):
    toks=[l.split('#')[0].split() for l in open(fn, errors='replace')]
    toks=[t for t in toks if t]
    h=toks[0]; i=1
    if len(h)>1: nv,nf=int(h[1]),int(h[2])
    else: nv,nf=int(toks[1][0]),int(toks[1][1]); i=2
    V=[tuple(map(float,t[:3])) for t in toks[i:i+nv]]
    F=[list(map(int,t[1:1+int(t[0])])) for t in toks[i+nv:i+nv+nf]]
    return V,F
def faces_obj(fn):
    V=[];F=[]
    for l in open(fn, errors='replace'):
        p=l.split('#')[0].split()
        if not p: continue
        if p[0]=='v': V.append(tuple(map(float,p[1:4])))
        if p[0]=='f': F.append([int(x.split('/')[0]) for x in p[1:]]); F[-1]=[i-1 if i>0 else len(V)+i for i in F[-1]]
    return V,F
def sub(a,b): return [a[i]-b[i] for i in range(3)]
def cross(u,v): return [u[1]*v[2]-u[2]*v[1],u[2]*v[0]-u[0]*v[2],u[0]*v[1]-u[1]*v[0]]
def dot(u,v): return sum(u[i]*v[i] for i in range(3))
for fn in sys.argv[1:]:
    try:
        V,F=(faces_obj if fn.endswith('.obj') else faces_off)(fn)
    except Exception as e:
        continue
    bad=0; flipped=0; ng=0
    for f in F:
        if len(f)<4: continue
        ng+=1
        P=[V[i] for i in f]
        n=[0,0,0]
        for k in range(len(P)):  # Newell normal
            a,b=P[k],P[(k+1)%len(P)]
            n[0]+=(a[1]-b[1])*(a[2]+b[2]); n[1]+=(a[2]-b[2])*(a[0]+b[0]); n[2]+=(a[0]-b[0])*(a[1]+b[1])
        conc=any(dot(cross(sub(P[k],P[k-1]),sub(P[(k+1)%len(P)],P[k])),n)<0 for k in range(len(P)))
        bad+=conc
        # a fan triangle wound against the polygon
        flipped+=any(dot(cross(sub(P[k],P[0]),sub(P[k+1],P[0])),n)<0 for k in range(1,len(P)-1))
    if bad: print('%s: %d polygons (>3 corners), %d concave, %d with a fan triangle wound against the polygon'%(fn,ng,bad,flipped))
