#!/usr/bin/python3
import sys; sys.argv=[sys.argv[0]]+sys.argv[1:]
exec(open('/tmp/probe22/meshcheck.py').read().split("def main")[0])
from fractions import Fraction as Fr
import numpy as np
for p in sys.argv[1:]:
    V,F,info=read_ply(p); F=np.array(F)
    a=V[F[:,0]];b=V[F[:,1]];c=V[F[:,2]]
    cr=np.cross(b-a,c-a); n=np.linalg.norm(cr,axis=1)
    L=np.maximum(np.linalg.norm(b-a,axis=1),np.linalg.norm(c-a,axis=1))
    idx=np.argsort(n/(L*L+1e-300))[:3]
    for i in idx:
        P=[[Fr(float(x)) for x in V[j]] for j in F[i]]
        u=[P[1][k]-P[0][k] for k in range(3)]; w=[P[2][k]-P[0][k] for k in range(3)]
        x=[u[1]*w[2]-u[2]*w[1],u[2]*w[0]-u[0]*w[2],u[0]*w[1]-u[1]*w[0]]
        print(p,'tri',i,F[i].tolist(),'rel area',n[i]/(L[i]**2),'exact collinear' if all(v==0 for v in x) else 'not exactly collinear')
        for j in F[i]: print('   ',repr(V[j].tolist()))
