#!/usr/bin/python3
"""Independent mesh reader/checker: PLY (ascii/binary), OBJ, OFF, STL, glTF, GLB."""
import sys, struct, json, base64, math, os, re
import numpy as np
from collections import Counter

problems = []
def P(msg):
    problems.append(msg)

PLY_T = {'char':'i1','int8':'i1','uchar':'u1','uint8':'u1','short':'i2','int16':'i2','ushort':'u2','uint16':'u2',
         'int':'i4','int32':'i4','uint':'u4','uint32':'u4','float':'f4','float32':'f4','double':'f8','float64':'f8'}

def read_ply(path):
    data = open(path,'rb').read()
    end = data.find(b'end_header\n')
    if not data.startswith(b'ply\n'): P('PLY: bad magic')
    hdr = data[:end].decode('ascii').split('\n')
    body = data[end+len(b'end_header\n'):]
    fmt=None; elems=[]; comments=[]
    for l in hdr[1:]:
        t=l.split()
        if not t: continue
        if t[0]=='format': fmt=t[1]; 
        elif t[0]=='comment': comments.append(l)
        elif t[0]=='element': elems.append([t[1],int(t[2]),[]])
        elif t[0]=='property':
            elems[-1][2].append(t[1:])
        else: P('PLY: unknown header line %r'%l)
    info={'comments':comments,'format':fmt,'elements':[(e[0],e[1],e[2]) for e in elems]}
    V=None;F=[]
    if fmt=='ascii':
        toks=body.split(); pos=0
        for name,cnt,props in elems:
            rows=[]
            for i in range(cnt):
                row=[]
                for p in props:
                    if p[0]=='list':
                        n=int(toks[pos]);pos+=1
                        row.append([int(x) for x in toks[pos:pos+n]]);pos+=n
                    else:
                        row.append(float(toks[pos]));pos+=1
                rows.append(row)
            if name=='vertex': V=np.array([[r[0],r[1],r[2]] for r in rows],dtype=np.float64).reshape(-1,3)
            if name=='face': F=[r[0] for r in rows]
        if pos!=len(toks): P('PLY ascii: %d trailing tokens'%(len(toks)-pos))
    else:
        en='<' if fmt=='binary_little_endian' else '>'
        off=0
        for name,cnt,props in elems:
            if all(p[0]!='list' for p in props):
                dt=np.dtype([(p[1],en+PLY_T[p[0]]) for p in props])
                arr=np.frombuffer(body,dtype=dt,count=cnt,offset=off); off+=dt.itemsize*cnt
                if name=='vertex':
                    info['vtype']=props[0][0]
                    V=np.stack([arr['x'].astype(np.float64),arr['y'].astype(np.float64),arr['z'].astype(np.float64)],1)
            else:
                # assume one list property (face)
                lp=[p for p in props if p[0]=='list']
                ct=np.dtype(en+PLY_T[lp[0][1]]); it=np.dtype(en+PLY_T[lp[0][2]])
                info['ftype']=(lp[0][1],lp[0][2])
                for i in range(cnt):
                    n=int(np.frombuffer(body,ct,1,off)[0]); off+=ct.itemsize
                    F.append(list(np.frombuffer(body,it,n,off).astype(np.int64))); off+=it.itemsize*n
                    for p in props:
                        if p[0]!='list': off+=PLY_T[p[0]] and np.dtype(PLY_T[p[0]]).itemsize
        if off!=len(body): P('PLY: body size %d != header-implied %d'%(len(body),off))
    return V,F,info

def read_obj(path):
    V=[];F=[];info={'comments':[]}
    for ln,l in enumerate(open(path,encoding='utf-8'),1):
        t=l.split()
        if not t: continue
        if t[0]=='#': info['comments'].append(l.strip()); continue
        if t[0].startswith('#'): info['comments'].append(l.strip()); continue
        if t[0]=='v': V.append([float(x) for x in t[1:4]])
        elif t[0]=='f':
            idx=[]
            for x in t[1:]:
                i=int(x.split('/')[0])
                if i<0: i=len(V)+i+1
                if i<1 or i>len(V): P('OBJ line %d: index %d out of range'%(ln,i))
                idx.append(i-1)
            F.append(idx)
        else: info.setdefault('other',Counter())[t[0]]+=1
    return np.array(V,dtype=np.float64).reshape(-1,3),F,info

def read_off(path):
    toks=[]
    for l in open(path,encoding='utf-8'):
        l=l.split('#')[0]; toks+=l.split()
    if toks[0]!='OFF': P('OFF: bad magic %r'%toks[0])
    nv,nf,ne=int(toks[1]),int(toks[2]),int(toks[3]); pos=4
    V=np.array([float(x) for x in toks[pos:pos+3*nv]]).reshape(-1,3); pos+=3*nv
    F=[]
    for i in range(nf):
        n=int(toks[pos]);pos+=1
        F.append([int(x) for x in toks[pos:pos+n]]);pos+=n
    if pos!=len(toks): P('OFF: %d trailing tokens'%(len(toks)-pos))
    return V,F,{}

def read_stl(path):
    data=open(path,'rb').read()
    info={}
    if len(data)>=84:
        n=struct.unpack('<I',data[80:84])[0]
        if 84+50*n==len(data):
            info['header']=data[:80]
            arr=np.frombuffer(data,dtype=np.dtype([('n','<f4',3),('v','<f4',(3,3)),('a','<u2')]),count=n,offset=84)
            nr=np.linalg.norm(arr['n'].astype(np.float64),axis=1)
            bad=np.sum((np.abs(nr-1)>1e-3)&(nr!=0))
            if bad: P('STL: %d normals neither unit nor zero'%bad)
            # check normal agrees with winding
            v=arr['v'].astype(np.float64)
            cr=np.cross(v[:,1]-v[:,0],v[:,2]-v[:,0]); cn=np.linalg.norm(cr,axis=1)
            ok=cn>0
            dots=np.sum(cr[ok]/cn[ok,None]*arr['n'][ok],axis=1)
            if np.any(dots< 0.5): P('STL: %d facet normals disagree with winding'%np.sum(dots<0.5))
            pts=v.reshape(-1,3)
            # weld bit-identical
            uniq,inv=np.unique(arr['v'].reshape(-1,3),axis=0,return_inverse=True)
            F=inv.reshape(-1,3).tolist()
            return uniq.astype(np.float64),F,info
        elif data[:5].lower()==b'solid':
            pass
        else:
            P('STL: binary count %d does not match size %d'%(n,len(data)))
    P('STL ascii not handled'); return np.zeros((0,3)),[],info

CT={5120:('i1',1),5121:('u1',1),5122:('i2',2),5123:('u2',2),5125:('u4',4),5126:('f4',4)}
NC={'SCALAR':1,'VEC2':2,'VEC3':3,'VEC4':4,'MAT4':16}
def read_gltf(path):
    data=open(path,'rb').read(); info={}
    bins=[]
    if path.lower().endswith('.glb'):
        magic,ver,length=struct.unpack('<4sII',data[:12])
        if magic!=b'glTF': P('GLB magic')
        if ver!=2: P('GLB version %d'%ver)
        if length!=len(data): P('GLB header length %d != file size %d'%(length,len(data)))
        off=12; chunks=[]
        while off<len(data):
            cl,ctype=struct.unpack('<II',data[off:off+8])
            if cl%4: P('GLB chunk length %d not multiple of 4'%cl)
            chunks.append((ctype,data[off+8:off+8+cl])); off+=8+cl
        if off!=len(data): P('GLB chunks overrun')
        if chunks[0][0]!=0x4E4F534A: P('GLB first chunk not JSON')
        js=chunks[0][1]
        tail=js[len(js.rstrip(b' ')):]
        if js.rstrip(b' ')!=js.rstrip(): P('GLB JSON padded with non-space')
        if len(chunks)>1:
            if chunks[1][0]!=0x004E4942: P('GLB 2nd chunk not BIN')
            b=chunks[1][1]; bins.append(b)
        jtxt=js.decode('utf-8')
    else:
        jtxt=data.decode('utf-8')
    def bad_const(c): raise ValueError('non-standard JSON constant '+c)
    g=json.loads(jtxt,parse_constant=bad_const)
    info['json']=g
    if g.get('asset',{}).get('version')!='2.0': P('glTF asset.version %r'%g.get('asset'))
    buffers=[]
    for i,b in enumerate(g.get('buffers',[])):
        if 'uri' in b:
            u=b['uri']
            m=re.match(r'data:application/(octet-stream|gltf-buffer);base64,(.*)$',u,re.S)
            if not m: P('glTF buffer %d uri not a data uri: %r'%(i,u[:60])); buffers.append(b''); continue
            raw=base64.b64decode(m.group(2),validate=True)
        else:
            raw=bins[0] if bins else b''
            if len(raw)<b['byteLength']: P('GLB BIN shorter than buffer byteLength')
            if len(raw)-b['byteLength']>3: P('GLB BIN has %d bytes beyond byteLength (>3 padding)'%(len(raw)-b['byteLength']))
        if len(raw)<b['byteLength']: P('buffer %d: data %d < byteLength %d'%(i,len(raw),b['byteLength']))
        buffers.append(raw)
    bvs=g.get('bufferViews',[])
    for i,bv in enumerate(bvs):
        o=bv.get('byteOffset',0)
        if o+bv['byteLength']>g['buffers'][bv['buffer']]['byteLength']: P('bufferView %d exceeds buffer'%i)
        if 'target' in bv and bv['target'] not in (34962,34963): P('bufferView %d target %r'%(i,bv['target']))
    def acc(i):
        a=g['accessors'][i]
        if a['componentType'] not in CT: P('accessor %d componentType %r'%(i,a['componentType']))
        dt,cs=CT[a['componentType']]; nc=NC[a['type']]
        bv=bvs[a['bufferView']]
        off=bv.get('byteOffset',0)+a.get('byteOffset',0)
        if off%cs: P('accessor %d offset %d not aligned to %d'%(i,off,cs))
        stride=bv.get('byteStride',cs*nc)
        if a.get('byteOffset',0)+stride*(a['count']-1)+cs*nc>bv['byteLength']: P('accessor %d exceeds bufferView'%i)
        buf=buffers[bv['buffer']]
        if stride==cs*nc:
            arr=np.frombuffer(buf,dtype='<'+dt,count=a['count']*nc,offset=off).reshape(a['count'],nc)
        else:
            arr=np.stack([np.frombuffer(buf,dtype='<'+dt,count=nc,offset=off+k*stride) for k in range(a['count'])])
        if 'min' in a:
            if not np.array_equal(np.array(a['min'],dtype=np.float64),arr.min(0).astype(np.float64)):
                P('accessor %d min %r != data min %r'%(i,a['min'],arr.min(0).tolist()))
        if 'max' in a:
            if not np.array_equal(np.array(a['max'],dtype=np.float64),arr.max(0).astype(np.float64)):
                P('accessor %d max %r != data max %r'%(i,a['max'],arr.max(0).tolist()))
        return arr,a
    allV=[];allF=[];base=0
    # placement via nodes
    def nodemat(n):
        if 'matrix' in n: return np.array(n['matrix'],dtype=np.float64).reshape(4,4).T
        M=np.eye(4)
        if 'scale' in n: M=np.diag(list(n['scale'])+[1])@M
        if 'rotation' in n:
            x,y,z,w=n['rotation']
            R=np.array([[1-2*(y*y+z*z),2*(x*y-z*w),2*(x*z+y*w)],[2*(x*y+z*w),1-2*(x*x+z*z),2*(y*z-x*w)],[2*(x*z-y*w),2*(y*z+x*w),1-2*(x*x+y*y)]])
            R4=np.eye(4);R4[:3,:3]=R;M=R4@M
        if 't' in n: pass
        if 'translation' in n: T=np.eye(4);T[:3,3]=n['translation'];M=T@M
        return M
    info['nodes']=g.get('nodes')
    scenes=g.get('scenes',[]); 
    if 'scene' not in g and scenes: pass
    meshes_world=[]
    def walk(ni,M):
        n=g['nodes'][ni]; M2=M@nodemat(n)
        if 'mesh' in n: meshes_world.append((n['mesh'],M2))
        for c in n.get('children',[]): walk(c,M2)
    if scenes:
        for r in scenes[g.get('scene',0)]['nodes']: walk(r,np.eye(4))
    else:
        meshes_world=[(i,np.eye(4)) for i in range(len(g.get('meshes',[])))]
        P('glTF has no scenes')
    for mi,M in meshes_world:
        for prim in g['meshes'][mi]['primitives']:
            if prim.get('mode',4)!=4: P('primitive mode %r'%prim.get('mode'))
            pos,pa=acc(prim['attributes']['POSITION'])
            if pa['componentType']!=5126 or pa['type']!='VEC3': P('POSITION not float VEC3')
            if 'min' not in pa or 'max' not in pa: P('POSITION accessor lacks min/max (required by spec)')
            info['pos_f32']=pos.copy()
            if 'indices' in prim:
                ind,ia=acc(prim['indices'])
                if ia['componentType'] not in (5121,5123,5125): P('indices componentType %r'%ia['componentType'])
                if ia['type']!='SCALAR': P('indices type')
                ind=ind.reshape(-1).astype(np.int64)
                if ind.size and ind.max()>=len(pos): P('index %d >= vertex count %d'%(ind.max(),len(pos)))
                if ind.size%3: P('index count not multiple of 3')
            else:
                ind=np.arange(len(pos))
            w=(np.c_[pos.astype(np.float64),np.ones(len(pos))]@M.T)[:,:3]
            allV.append(w); allF+= (ind.reshape(-1,3)+base).tolist(); base+=len(pos)
    V=np.concatenate(allV) if allV else np.zeros((0,3))
    return V,allF,info

def check_mesh(V,F,label,weld_tol=0.0, allow_split=False):
    r={}
    if V.size and not np.all(np.isfinite(V)): P('%s: %d non-finite coordinates'%(label,np.sum(~np.isfinite(V))))
    r['V']=len(V); r['F']=len(F)
    if not F: return r
    F=np.array(F,dtype=np.int64)
    if F.shape[1]!=3: P('%s: non-triangle faces'%label); return r
    if F.max()>=len(V) or F.min()<0: P('%s: index out of range'%label); return r
    used=np.zeros(len(V),bool); used[F.reshape(-1)]=True
    if not used.all(): P('%s: %d unused vertices'%(label,np.sum(~used)))
    # duplicates of positions
    u,inv,cnt=np.unique(V,axis=0,return_inverse=True,return_counts=True)
    ndup=len(V)-len(u); r['dup_positions']=ndup
    if ndup: P('%s: %d vertices share a position with another (not welded%s)'%(label,ndup,', split pinch copies' if allow_split else ''))
    # degenerate
    a=V[F[:,0]];b=V[F[:,1]];c=V[F[:,2]]
    cr=np.cross(b-a,c-a); area=0.5*np.linalg.norm(cr,axis=1)
    nz=np.sum(area==0); r['zero_area']=int(nz)
    if nz: P('%s: %d zero-area triangles'%(label,nz))
    same=np.sum((F[:,0]==F[:,1])|(F[:,1]==F[:,2])|(F[:,0]==F[:,2]))
    if same: P('%s: %d triangles with repeated index'%(label,same))
    # manifold / orientation by index
    de=np.concatenate([F[:,[0,1]],F[:,[1,2]],F[:,[2,0]]])
    key=de[:,0]*(len(V)+1)+de[:,1]
    kc=Counter(key.tolist())
    multi=sum(1 for k,v in kc.items() if v>1)
    missing=sum(1 for k in kc if (k%(len(V)+1))*(len(V)+1)+k//(len(V)+1) not in kc)
    r['dir_edge_dup']=multi; r['unpaired']=missing
    if multi: P('%s: %d directed edges used more than once (non-manifold or inconsistent orientation)'%(label,multi))
    if missing: P('%s: %d directed edges without opposite (open boundary)'%(label,missing))
    # position-based (welded) closure
    pinv=inv.reshape(-1)
    Fp=pinv[F]
    dep=np.concatenate([Fp[:,[0,1]],Fp[:,[1,2]],Fp[:,[2,0]]])
    kp=Counter((dep[:,0]*(len(u)+1)+dep[:,1]).tolist())
    mp=sum(1 for k,v in kp.items() if v>1); r['pos_dir_edge_dup']=mp
    # signed volume (relative to centroid for precision)
    cen=V.mean(0)
    vol=np.sum(np.einsum('ij,ij->i',a-cen,np.cross(b-cen,c-cen)))/6
    r['volume']=vol
    if vol<=0: P('%s: signed volume %g <= 0 (inward)'%(label,vol))
    r['bbox']=(V.min(0).tolist(),V.max(0).tolist())
    return r

def main():
    global problems
    for path in sys.argv[1:]:
        problems=[]
        ext=path.lower().rsplit('.',1)[-1]
        try:
            if ext=='ply': V,F,info=read_ply(path)
            elif ext=='obj': V,F,info=read_obj(path)
            elif ext=='off': V,F,info=read_off(path)
            elif ext=='stl': V,F,info=read_stl(path)
            elif ext in('gltf','glb'): V,F,info=read_gltf(path)
            # triangulate polygons by fan for checking
            F2=[]
            for f in F:
                for k in range(1,len(f)-1): F2.append([f[0],f[k],f[k+1]])
            if any(len(f)!=3 for f in F): P('non-triangle faces present (%d)'%sum(len(f)!=3 for f in F))
            r=check_mesh(V,F2,os.path.basename(path))
            if ext in ('gltf','glb') and 'pos_f32' in info:
                pass
            extra=''
            if ext=='ply': extra=' vtype=%s ftype=%s comments=%s'%(info.get('vtype'),info.get('ftype'),info['comments'])
            if ext=='obj': extra=' comments=%s'%info['comments'][:3]
            if ext in('gltf','glb'): extra=' nodes=%s'%json.dumps(info.get('nodes'))[:200]
            print('%s: V=%d F=%d vol=%.6g bbox=%s%s'%(path,r['V'],r['F'],r.get('volume',0),r.get('bbox'),extra))
        except Exception as e:
            import traceback; traceback.print_exc()
            P('reader exception: %r'%e)
        for p in problems: print('   PROBLEM:',p)
        if not problems: print('   OK')

if __name__=='__main__': main()
