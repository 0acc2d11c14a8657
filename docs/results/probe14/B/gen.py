#!/usr/bin/env python3
"""probe14/B scene generator. Writes scenes/*.json. Meshes referred to by /tmp/probe9 paths.
Each scene is a canonical layout (ground 8x8 at y=0, meshes ~2 units) put through a whole-scene
similarity W = T * R * s applied to objects (as 'matrix'), light and camera (explicit up vectors,
explicit near/far/extent where rotation would change the AABB-based fit)."""
import os as _os
ROOT = _os.path.abspath(_os.path.join(_os.path.dirname(__file__), "../../../.."))  # the repository
SV = _os.environ.get("SV", _os.path.join(ROOT, "build/apps/shadowvol"))  # the shadowvol binary
import json, math, os, subprocess, sys
BIN = SV  # deep-spot.sh passes its SV
D = '/tmp/probe9/d/data/meshes/'
X = '/tmp/probe9/x/usr/share/assimp/models/'
HERE = os.path.dirname(os.path.abspath(__file__))
MESH = {
 'joint': D+'joint.off', 'itemb': D+'itemb.off', 'blobclosed': D+'blob-closed.off', 'oblong': D+'oblong.off',
 'oblongshuf': D+'oblong-shuffled.off', 'rotor': D+'rotor_small.off', 'pinion': D+'pinion_small.off',
 'alstom': D+'ALSTOM_TEST4.off', 'knot2': D+'knot2.off', 'anchor': D+'anchor_dense.off',
 'sphere966': D+'sphere966.off', 'dtorus3': D+'double-torus-3-holes.off', 'threepeaks': D+'three_peaks.off',
 'border': D+'mesh_with_border.off', 'cubemeshed': D+'cube-meshed.off', 'poly': D+'poly2x^2+y^2-0.062500.off',
 'fandiskbox': D+'fandisk-box.off', 'cheesebox': D+'cheese-box.off', 'quint': D+'quint_tris.off',
 'retinal': D+'retinal.off', 'cylref': D+'cylinder_locally_refined.off', 'geosphere': D+'geosphere.off',
 'patch13': D+'patch-13.off', 'duck': X+'Collada/duck_triangulate.dae', 'c4d': X+'Collada/Cinema4D.dae',
 'spheretri': X+'Collada/sphere_triangulate.dae', 'bearbis': D+'bear_bis.off', 'larger': D+'larger_sphere.off',
}
_bc = os.path.join(HERE, 'bounds.json')
BOUNDS = json.load(open(_bc)) if os.path.exists(_bc) else {}
def bounds(key):
    if key not in BOUNDS:
        t = os.path.join(HERE, '_b.json')
        json.dump({'objects': [{'type': 'mesh', 'file': MESH[key]}], 'light': {'type': 'directional', 'direction': [0, -1, 0]},
                   'camera': {'eye': [0, 0, 1e4], 'target': [0, 0, 0]}}, open(t, 'w'))
        r = json.loads(subprocess.run([BIN, 'scene', '--scene', t, '--json'], capture_output=True, text=True).stdout)
        o = r.get('origin', [0, 0, 0])
        BOUNDS[key] = [[a + b for a, b in zip(r['bounds']['min'], [0,0,0])], [a for a in r['bounds']['max']], r['triangles']]
        json.dump(BOUNDS, open(_bc, 'w'))
    return BOUNDS[key]

def mm(A, B): return [[sum(A[i][k]*B[k][j] for k in range(4)) for j in range(4)] for i in range(4)]
def T(t): return [[1,0,0,t[0]],[0,1,0,t[1]],[0,0,1,t[2]],[0,0,0,1]]
def S(s):
    s = s if isinstance(s, list) else [s, s, s]
    return [[s[0],0,0,0],[0,s[1],0,0],[0,0,s[2],0],[0,0,0,1]]
def R(rx, ry, rz):
    a, b, c = map(math.radians, (rx, ry, rz))
    X_ = [[1,0,0,0],[0,math.cos(a),-math.sin(a),0],[0,math.sin(a),math.cos(a),0],[0,0,0,1]]
    Y_ = [[math.cos(b),0,math.sin(b),0],[0,1,0,0],[-math.sin(b),0,math.cos(b),0],[0,0,0,1]]
    Z_ = [[math.cos(c),-math.sin(c),0,0],[math.sin(c),math.cos(c),0,0],[0,0,1,0],[0,0,0,1]]
    return mm(Z_, mm(Y_, X_))
def ap(M, p, w=1): return [sum(M[i][k]*v for k, v in enumerate(list(p)+[w])) for i in range(3)]
def flat(M): return [M[i][j] for i in range(4) for j in range(4)]

def mesh_obj(key, size, center, rot=(0,0,0), name=None, extra=None, mirror=False):
    lo, hi, _ = bounds(key)
    c = [(a+b)/2 for a, b in zip(lo, hi)]; ext = max(b-a for a, b in zip(lo, hi))
    M = mm(T(center), mm(R(*rot), mm(S([-size/ext if mirror else size/ext, size/ext, size/ext]), T([-v for v in c]))))
    o = {'type': 'mesh', 'name': name or key, 'file': MESH[key], '_M': M}
    if extra: o.update(extra)
    return o
def prim(d, M=None):
    d = dict(d); d['_M'] = M or T([0,0,0]); return d

def make(name, objs, light, cam, W=None, s=1.0):
    """W: whole-scene 4x4 similarity (rotation*uniform scale s + translation)."""
    W = W or T([0,0,0])
    out = []
    for o in objs:
        o = dict(o); M = mm(W, o.pop('_M'))
        o['transform'] = {'matrix': flat(M)}; out.append(o)
    L = dict(light)
    for k in ('position', 'target'):
        if k in L: L[k] = ap(W, L[k])
    def nz(v):
        n = math.sqrt(sum(x*x for x in v)); return [x/n for x in v]
    for k in ('direction', 'up'):
        if k in L: L[k] = nz(ap(W, L[k], 0))
    for k in ('near', 'far', 'extent'):
        if k in L: L[k] = L[k]*s
    C = dict(cam)
    C['eye'] = ap(W, C['eye']); C['target'] = ap(W, C['target']); C['up'] = nz(ap(W, C.get('up', [0,1,0]), 0))
    for k in ('near', 'far'):
        if k in C: C[k] = C[k]*s
    sc = {'description': name, 'objects': out, 'light': L, 'camera': C}
    os.makedirs(os.path.join(HERE, 'scenes'), exist_ok=True)
    json.dump(sc, open(os.path.join(HERE, 'scenes', name + '.json'), 'w'), indent=1)
    return name

GROUND = prim({'type': 'plane', 'name': 'ground', 'size': 8})
CAM = {'eye': [0.5, 4.5, 7], 'target': [0, 0.8, 0], 'fov': 45, 'width': 320, 'height': 240, 'up': [0,1,0]}
LIGHTS = {
 'spot': {'type': 'spot', 'position': [3, 6, 2], 'target': [0, 0.8, 0], 'fov': 55, 'up': [0,1,0]},
 'dir': {'type': 'directional', 'direction': [0.4, -1, 0.3], 'up': [0,1,0]},
 'down': {'type': 'directional', 'direction': [0, -1, 0], 'up': [0,0,-1]},
 'graze': {'type': 'directional', 'direction': [1, -0.12, 0.25], 'up': [0,1,0]},
 'point': {'type': 'point', 'position': [1.2, 3.8, 0.9]},
 'close': {'type': 'spot', 'position': [0.6, 2.6, 0.4], 'target': [0, 0.5, 0], 'fov': 120, 'up': [0,1,0]},
}
def Wof(s=1.0, t=(0,0,0), r=(0,0,0)): return mm(T(t), mm(R(*r), S(s)))

# fixed windows/planes so that a rotated whole scene fits the same (AABB fit is not rotation-invariant)
def fixed(light):
    L = dict(light)
    if L['type'] == 'directional':
        d = L['direction']; n = math.sqrt(sum(v*v for v in d)); d = [v/n for v in d]
        L['position'] = [-6*v for v in d]; L['position'][1] += 0.8; L['extent'] = 5.0; L['near'] = 0.5; L['far'] = 14.0
    elif L['type'] == 'spot':
        L['near'] = 1.0; L['far'] = 14.0
    elif L['type'] == 'point':
        L['near'] = 0.05; L['far'] = 12.0
    return L
CAMF = dict(CAM, near=2.0, far=20.0)

if __name__ == '__main__':
    names = []
    # 1) single meshes under several lights, canonical placement
    set1 = [('joint', 'spot', (20, 30, 0)), ('itemb', 'dir', (0, 45, 10)), ('blobclosed', 'spot', (0, 0, 0)),
            ('oblong', 'graze', (10, 20, 5)), ('oblongshuf', 'spot', (10, 20, 5)), ('rotor', 'down', (70, 0, 0)),
            ('pinion', 'dir', (-90, 0, 0)), ('alstom', 'spot', (-90, 0, 0)), ('knot2', 'point', (0, 0, 0)),
            ('anchor', 'spot', (0, 0, 0)), ('sphere966', 'close', (0, 0, 0)), ('dtorus3', 'graze', (30, 0, 0)),
            ('threepeaks', 'down', (30, 0, 0)), ('border', 'spot', (30, 0, 0)), ('cubemeshed', 'point', (33, 21, 7)),
            ('poly', 'dir', (0, 0, 0)), ('fandiskbox', 'spot', (15, 40, 0)), ('cheesebox', 'graze', (0, 10, 0)),
            ('quint', 'dir', (20, 20, 20)), ('retinal', 'spot', (0, 0, 0)), ('cylref', 'graze', (90, 0, 20)),
            ('geosphere', 'point', (0, 0, 0)), ('patch13', 'down', (20, 0, 0)), ('duck', 'spot', (0, 30, 0)),
            ('c4d', 'dir', (0, 0, 0)), ('bearbis', 'spot', (0, -30, 0))]
    for key, li, rot in set1:
        names.append(make(f'{key}_{li}', [GROUND, mesh_obj(key, 2.0, [0, 1.3, 0], rot)], LIGHTS[li], CAM))
    json.dump(names, open(os.path.join(HERE, 'set1.json'), 'w'))
    print(len(names), 'scenes')

def invariance_set():
    """set2: the same scene under whole-scene similarities (light and camera moved too)."""
    base = [('anchor', 'spot', (0, 0, 0)), ('pinion', 'dir', (-90, 0, 0)), ('knot2', 'point', (0, 0, 0)),
            ('dtorus3', 'graze', (30, 0, 0)), ('rotor', 'down', (70, 0, 0)), ('duck', 'close', (0, 30, 0))]
    Ws = {'id': (1.0, (0, 0, 0), (0, 0, 0)), 's1e-3': (1e-3, (0, 0, 0), (0, 0, 0)), 's1e4': (1e4, (0, 0, 0), (0, 0, 0)),
          't1e6': (1.0, (1e6, -3e5, 7e5), (0, 0, 0)), 's1e-3t1e5': (1e-3, (1e5, 2e4, -1e5), (0, 0, 0)),
          's1e4t1e6': (1e4, (-1e6, 5e5, 1e6), (0, 0, 0)), 'rot': (1.0, (0, 0, 0), (37, -23, 61)),
          'rot_s1e-3_t1e5': (1e-3, (3e4, 1e5, -2e4), (37, -23, 61))}
    names = []
    for key, li, rot in base:
        for wn, (s, t, r) in Ws.items():
            if li == 'point' and wn.startswith('rot'): continue  # a cube map is axis-aligned: not rotation-invariant
            names.append(make(f'inv_{key}_{li}_{wn}', [GROUND, mesh_obj(key, 2.0, [0, 1.3, 0], rot)], fixed(LIGHTS[li]), CAMF, Wof(s, t, r), s))
    json.dump(names, open(os.path.join(HERE, 'set2.json'), 'w'))
    return names
if __name__ == '__main__' and 'inv' in sys.argv:
    print(len(invariance_set()), 'invariance scenes')

def read_off(path):
    toks = []
    for line in open(path):
        line = line.split('#')[0]
        toks += line.split()
    assert toks[0].endswith('OFF'); i = 1
    nv, nf = int(toks[i]), int(toks[i+1]); i += 3
    V = [[float(toks[i+3*k+j]) for j in range(3)] for k in range(nv)]; i += 3*nv
    F = []
    for _ in range(nf):
        n = int(toks[i]); F.append([int(t) for t in toks[i+1:i+1+n]]); i += 1+n
        # skip colour tokens: none in the files used here
    return V, F
def write_off(path, V, F):
    with open(path, 'w') as f:
        f.write(f'OFF\n{len(V)} {len(F)} 0\n')
        for v in V: f.write('%.17g %.17g %.17g\n' % tuple(v))
        for t in F: f.write(str(len(t)) + ' ' + ' '.join(map(str, t)) + '\n')

def broken_meshes():
    """meshes/*.off: real meshes made broken in known ways."""
    import random
    os.makedirs(os.path.join(HERE, 'meshes'), exist_ok=True)
    out = {}
    V, F = read_off(D + 'pinion_small.off')
    tri = [t for f in F for t in ([f] if len(f) == 3 else [[f[0], f[k], f[k+1]] for k in range(1, len(f)-1)])]
    # duplicated faces: every face twice
    write_off(os.path.join(HERE, 'meshes/pinion_dup.off'), V, tri + tri); out['pinion_dup'] = 'meshes/pinion_dup.off'
    # half the faces flipped at random (inconsistent, closed)
    rnd = random.Random(7); fl = [t[::-1] if rnd.random() < 0.5 else t for t in tri]
    write_off(os.path.join(HERE, 'meshes/pinion_flip.off'), V, fl); out['pinion_flip'] = 'meshes/pinion_flip.off'
    # whole mesh inside out
    write_off(os.path.join(HERE, 'meshes/pinion_inv.off'), V, [t[::-1] for t in tri]); out['pinion_inv'] = 'meshes/pinion_inv.off'
    # zero-area triangles added: (a,a,b) and collinear (a,b,mid)
    V2 = list(V); extra = []
    for t in tri[::5]:
        a, b = V[t[0]], V[t[1]]; V2.append([(x+y)/2 for x, y in zip(a, b)]); extra += [[t[0], t[0], t[1]], [t[0], t[1], len(V2)-1]]
    write_off(os.path.join(HERE, 'meshes/pinion_degen.off'), V2, tri + extra); out['pinion_degen'] = 'meshes/pinion_degen.off'
    # self-intersecting: the mesh and a copy rotated by 20 deg about y, shifted, in ONE file (closed, overlapping parts)
    V3, F3 = read_off(D + 'anchor_dense.off')
    tri3 = [t for f in F3 for t in ([f] if len(f) == 3 else [[f[0], f[k], f[k+1]] for k in range(1, len(f)-1)])]
    Rm = R(0, 20, 0); n = len(V3)
    V3b = V3 + [[a + d for a, d in zip(ap(Rm, v), [0.12, 0.05, 0.0])] for v in V3]
    write_off(os.path.join(HERE, 'meshes/anchor_x2.off'), V3b, tri3 + [[a+n, b+n, c+n] for a, b, c in tri3]); out['anchor_x2'] = 'meshes/anchor_x2.off'
    # non-manifold: joint with a fin (a single triangle sharing an existing edge -> edge of 3 faces)
    V4, F4 = read_off(D + 'joint.off')
    tri4 = [t for f in F4 for t in ([f] if len(f) == 3 else [[f[0], f[k], f[k+1]] for k in range(1, len(f)-1)])]
    fins = []
    for t in tri4[::15]:
        a, b, c = V4[t[0]], V4[t[1]], V4[t[2]]
        cen = [(x+y+z)/3 for x, y, z in zip(a, b, c)]
        nrm = [cen[k] for k in range(3)]; L = math.sqrt(sum(x*x for x in nrm)) or 1
        V4.append([cen[k] + 0.3*nrm[k]/L for k in range(3)]); fins.append([t[0], t[1], len(V4)-1]); fins.append([t[1], t[0], len(V4)-1])
    write_off(os.path.join(HERE, 'meshes/joint_fins.off'), V4, tri4 + fins); out['joint_fins'] = 'meshes/joint_fins.off'
    # open: pinion with 10% of faces removed (holes), and half of the rest flipped
    rnd = random.Random(3); op = [t for t in tri if rnd.random() > 0.1]; op = [t[::-1] if rnd.random() < 0.5 else t for t in op]
    write_off(os.path.join(HERE, 'meshes/pinion_open_flip.off'), V, op); out['pinion_open_flip'] = 'meshes/pinion_open_flip.off'
    for k, v in out.items(): MESH[k] = os.path.join(HERE, v)
    return out

def special_set():
    broken_meshes()
    n = []
    for key in ('pinion_dup', 'pinion_flip', 'pinion_inv', 'pinion_degen', 'anchor_x2', 'joint_fins', 'pinion_open_flip'):
        n.append(make(f'brk_{key}_spot', [GROUND, mesh_obj(key, 2.0, [0, 1.3, 0], (-60, 0, 0))], LIGHTS['spot'], CAM))
        n.append(make(f'brk_{key}_down', [GROUND, mesh_obj(key, 2.0, [0, 1.3, 0], (-60, 0, 0))], LIGHTS['down'], CAM))
    # nested / overlapping objects: a box around part of a mesh, a sphere inside a mesh, a mesh through a box
    n.append(make('nest_sphere_in_box_spot', [GROUND, prim({'type': 'box', 'size': 2}, T([0, 1.2, 0])), prim({'type': 'sphere', 'radius': 0.6, 'detail': 3}, T([0.2, 1.2, 0]))], LIGHTS['spot'], CAM))
    n.append(make('overlap_knot_box_dir', [GROUND, mesh_obj('knot2', 2.2, [0, 1.4, 0], (0, 0, 0)), prim({'type': 'box', 'size': [0.5, 2.5, 0.5]}, mm(T([0.3, 1.4, 0]), R(0, 0, 30)))], LIGHTS['dir'], CAM))
    n.append(make('trio_overlap_spot', [GROUND, mesh_obj('anchor', 2.0, [0, 1.3, 0]), mesh_obj('rotor', 1.5, [0.6, 1.2, 0.3], (0, 0, 90)), mesh_obj('geosphere', 1.0, [-0.5, 1.5, 0.2])], LIGHTS['spot'], CAM))
    # lights: grazing nearly parallel, straight-down spot, light inside bbox (torus hole), camera below ground
    n.append(make('graze_flat_pinion', [GROUND, mesh_obj('pinion', 2.0, [0, 1.0, 0], (-90, 0, 0))], {'type': 'directional', 'direction': [1, -0.02, 0.1]}, CAM))
    n.append(make('spotdown_anchor', [GROUND, mesh_obj('anchor', 2.0, [0, 1.3, 0])], {'type': 'spot', 'position': [0, 6, 0], 'target': [0, 0, 0], 'fov': 60}, CAM))
    n.append(make('pointinbox_dtorus', [GROUND, mesh_obj('dtorus3', 3.0, [0, 1.5, 0], (90, 0, 0))], {'type': 'point', 'position': [0.0, 1.9, 0.0]}, CAM))
    n.append(make('spotinbox_knot', [GROUND, mesh_obj('knot2', 3.0, [0, 1.6, 0], (0, 0, 0))], {'type': 'spot', 'position': [0.05, 1.6, 0.05], 'target': [0, 0, 0], 'fov': 150}, CAM))
    n.append(make('below_cam_anchor', [GROUND, mesh_obj('anchor', 2.0, [0, 1.3, 0])], LIGHTS['spot'], {'eye': [0.5, -3, 6], 'target': [0, 1, 0], 'fov': 50}))
    n.append(make('below_cam_point_cube', [GROUND, mesh_obj('cubemeshed', 1.5, [0, 1.3, 0], (20, 30, 0))], LIGHTS['point'], {'eye': [0.5, -2, 5], 'target': [0, 1.3, 0], 'fov': 60}))
    n.append(make('close_point_rotor', [GROUND, mesh_obj('rotor', 2.0, [0, 1.3, 0], (90, 0, 0))], {'type': 'point', 'position': [0.05, 2.45, 0.02]}, CAM))
    n.append(make('mirror_duck_spot', [GROUND, mesh_obj('duck', 2.0, [0, 1.3, 0], (0, 30, 0), mirror=True)], LIGHTS['spot'], CAM))
    json.dump(n, open(os.path.join(HERE, 'set3.json'), 'w'))
    return n
if __name__ == '__main__' and 'special' in sys.argv:
    print(len(special_set()), 'special scenes')

def below_set():
    n = []
    cam = {'eye': [0.3, -1.0, 9.0], 'target': [0, 1.3, 0], 'fov': 40}
    n.append(make('below2_anchor_graze', [GROUND, mesh_obj('anchor', 2.0, [0, 1.3, 0])], LIGHTS['graze'], cam))
    n.append(make('below2_pinion_lowpoint', [GROUND, mesh_obj('pinion', 2.0, [0, 1.5, 0], (-60, 0, 0)), mesh_obj('geosphere', 0.6, [0.3, 0.4, 1.6])], {'type': 'point', 'position': [1.5, 0.3, 1.2]}, cam))
    n.append(make('below2_knot_lowspot', [GROUND, mesh_obj('knot2', 2.0, [0, 1.5, 0], (80, 0, 0))], {'type': 'spot', 'position': [2.5, 0.2, 2.5], 'target': [0, 1.5, 0], 'fov': 70}, cam))
    json.dump(n, open(os.path.join(HERE, 'set4.json'), 'w'))
    return n
if __name__ == '__main__' and 'below' in sys.argv:
    print(len(below_set()), 'below scenes')

def rot_exact_set():
    """rotation invariance with light planes inside both fits (so neither is moved by the fit)."""
    n = []
    L = dict(LIGHTS['spot'], near=3.6, far=10.2)
    for wn, (s, t, r) in {'id': (1, (0, 0, 0), (0, 0, 0)), 'rot': (1, (0, 0, 0), (37, -23, 61)), 'rot2': (1, (0, 0, 0), (-71, 13, 5)),
                          'rot_s1e4_t1e6': (1e4, (1e6, 2e6, -1e6), (37, -23, 61))}.items():
        n.append(make(f'rx_anchor_spot_{wn}', [GROUND, mesh_obj('anchor', 2.0, [0, 1.3, 0])], L, CAMF, Wof(s, t, r), s))
    json.dump(n, open(os.path.join(HERE, 'set5.json'), 'w'))
    return n
if __name__ == '__main__' and 'rotx' in sys.argv:
    print(len(rot_exact_set()), 'rot scenes')

def extra_set():
    n = []
    a = mesh_obj('anchor', 2.0, [0, 1.3, 0])
    n.append(make('dupobj_anchor_spot', [GROUND, a, dict(a, name='anchor2')], LIGHTS['spot'], CAM))
    lo, hi, _ = bounds('pinion'); 
    n.append(make('rest_box_on_ground_dir', [GROUND, prim({'type': 'box', 'size': 1.0}, mm(T([0, 0.5, 0]), R(0, 30, 0))), prim({'type': 'box', 'size': [0.5, 1.5, 0.5]}, T([1.2, 0.75, 0.8]))], LIGHTS['dir'], CAM))
    n.append(make('rest_box_on_ground_spot', [GROUND, prim({'type': 'box', 'size': 1.0}, mm(T([0, 0.5, 0]), R(0, 30, 0))), prim({'type': 'cylinder', 'radius': 0.3, 'height': 1.5}, T([1.2, 0.75, 0.8]))], LIGHTS['spot'], CAM))
    n.append(make('graze_extreme_anchor', [GROUND, mesh_obj('anchor', 2.0, [0, 1.3, 0])], {'type': 'directional', 'direction': [1, -0.004, 0.2]}, CAM))
    n.append(make('spot_touching_knot', [GROUND, mesh_obj('knot2', 2.0, [0, 1.3, 0], (90, 0, 0))], {'type': 'spot', 'position': [0.0, 2.35, 0.0], 'target': [0, 0, 0], 'fov': 100}, CAM))
    n.append(make('coplanar_boxes_dir', [GROUND, prim({'type': 'box', 'size': 1.0}, T([0, 1.0, 0])), prim({'type': 'box', 'size': 1.0}, T([0.5, 1.0, 0.3]))], LIGHTS['dir'], CAM))
    json.dump(n, open(os.path.join(HERE, 'set6.json'), 'w'))
    return n
if __name__ == '__main__' and 'extra' in sys.argv:
    print(len(extra_set()), 'extra scenes')

def extreme_set():
    n = []
    for key, li, rot in [('anchor', 'spot', (0, 0, 0)), ('pinion', 'dir', (-90, 0, 0)), ('rotor', 'down', (70, 0, 0))]:
        for wn, (s, t) in {'s1e-5': (1e-5, (0, 0, 0)), 's1e-5t1e2': (1e-5, (1e2, 50, -30)), 's1e-3t1e6': (1e-3, (1e6, 0, 1e6)),
                           's1e6t1e8': (1e6, (1e8, 0, -1e8)), 's1e-4t1e4': (1e-4, (1e4, 1e4, 0))}.items():
            n.append(make(f'ext_{key}_{li}_{wn}', [GROUND, mesh_obj(key, 2.0, [0, 1.3, 0], rot)], fixed(LIGHTS[li]), CAMF, Wof(s, t), s))
    json.dump(n, open(os.path.join(HERE, 'set7.json'), 'w'))
    return n
if __name__ == '__main__' and 'ext' in sys.argv:
    print(len(extreme_set()), 'extreme scenes')

def multi_set():
    n = []
    for wn, (s, t) in {'id': (1, (0, 0, 0)), 's1e-3t1e5': (1e-3, (1e5, 0, 3e4)), 's1e4t1e6': (1e4, (-1e6, 2e6, 0))}.items():
        objs = [GROUND, mesh_obj('anchor', 2.0, [-0.8, 1.3, 0]), mesh_obj('pinion', 1.6, [1.2, 1.0, 0.5], (-90, 0, 0))]
        W = Wof(s, t)
        sc = make(f'multi_{wn}', objs, fixed(LIGHTS['spot']), CAMF, W, s)
        p = os.path.join(HERE, 'scenes', sc + '.json'); j = json.load(open(p))
        L1 = fixed(LIGHTS['point']); L2 = fixed(LIGHTS['graze'])
        extra = []
        for L in (L1, L2):
            L = dict(L)
            for k in ('position', 'target'):
                if k in L: L[k] = ap(W, L[k])
            for k in ('direction', 'up'):
                if k in L:
                    v = ap(W, L[k], 0); nn = math.sqrt(sum(x*x for x in v)); L[k] = [x/nn for x in v]
            for k in ('near', 'far', 'extent'):
                if k in L: L[k] *= s
            L['intensity'] = 0.5; extra.append(L)
        j['lights'] = [dict(j.pop('light'), intensity=0.5)] + extra
        json.dump(j, open(p, 'w'), indent=1); n.append(sc)
    json.dump(n, open(os.path.join(HERE, 'set8.json'), 'w'))
    return n
if __name__ == '__main__' and 'multi' in sys.argv:
    print(len(multi_set()), 'multi scenes')

def sliver_meshes():
    """pinion inside out, plus zero-area slivers: (a,a,b) only, or (a,b,mid(ab)) only."""
    V, F = read_off(D + 'pinion_small.off')
    tri = [t for f in F for t in ([f] if len(f) == 3 else [[f[0], f[k], f[k+1]] for k in range(1, len(f)-1)])]
    inv = [t[::-1] for t in tri]
    write_off(os.path.join(HERE, 'meshes/pinion_inv_rep.off'), V, inv + [[inv[0][0], inv[0][0], inv[0][1]]])
    V2 = V + [[(x+y)/2 for x, y in zip(V[inv[0][0]], V[inv[0][1]])]]
    write_off(os.path.join(HERE, 'meshes/pinion_inv_sliver.off'), V2, inv + [[inv[0][0], inv[0][1], len(V2)-1]])
    V3 = V + [[(x+y)/2 for x, y in zip(V[tri[0][0]], V[tri[0][1]])]]
    write_off(os.path.join(HERE, 'meshes/pinion_sliver.off'), V3, tri + [[tri[0][0], tri[0][1], len(V3)-1]])
    n = []
    for k in ('pinion_inv_rep', 'pinion_inv_sliver', 'pinion_sliver', 'pinion_inv'):
        MESH[k] = os.path.join(HERE, 'meshes', k + '.off')
        n.append(make(f'sl_{k}_spot', [GROUND, mesh_obj(k, 2.0, [0, 1.3, 0], (-60, 0, 0))], LIGHTS['spot'], CAM))
    return n
if __name__ == '__main__' and 'sliver' in sys.argv:
    print(sliver_meshes())

def inshadow_set():
    """camera inside the shadow volume (under the caster), whole scene moved/scaled; a wide spot near the ground."""
    n = []
    for wn, (s, t, r) in {'id': (1, (0, 0, 0), (0, 0, 0)), 's1e-3t1e5': (1e-3, (1e5, -2e4, 3e4), (0, 0, 0)),
                          's1e4t1e6': (1e4, (1e6, 1e6, 1e6), (0, 0, 0)), 'rot': (1, (0, 0, 0), (37, -23, 61))}.items():
        cam = {'eye': [0.1, 0.35, 0.1], 'target': [3, 0.2, 1.5], 'fov': 70, 'near': 0.05, 'far': 20}
        objs = [GROUND, prim({'type': 'box', 'size': [3, 0.2, 3]}, T([0, 1.5, 0])), mesh_obj('anchor', 1.0, [2.5, 0.5, 1.0])]
        n.append(make(f'insh_{wn}', objs, dict(LIGHTS['spot'], position=[0.5, 5, 0.3], target=[0, 0, 0], fov=90, near=1.0, far=8), cam, Wof(s, t, r), s))
        objs2 = [GROUND, mesh_obj('knot2', 1.0, [0.8, 0.6, 0.3], (90, 0, 0)), mesh_obj('rotor', 0.8, [-0.9, 0.4, 0.6])]
        n.append(make(f'wide_{wn}', objs2, {'type': 'spot', 'position': [0, 0.15, 0], 'target': [0.3, 0.15, 0.2], 'fov': 170, 'up': [0, 1, 0]}, CAMF, Wof(s, t, r), s))
    json.dump(n, open(os.path.join(HERE, 'set9.json'), 'w'))
    return n
if __name__ == '__main__' and 'insh' in sys.argv:
    print(len(inshadow_set()), 'inshadow scenes')

def wide2():
    objs = [GROUND, mesh_obj('knot2', 0.7, [1.0, 0.45, 0.4], (90, 0, 0)), mesh_obj('rotor', 0.6, [-0.9, 0.35, 0.7]), mesh_obj('anchor', 0.7, [0.1, 0.4, 1.4])]
    n = [make('wide2_fov160', objs, {'type': 'spot', 'position': [0, 1.2, 0], 'target': [0.2, 0, 0.6], 'fov': 160}, dict(CAM, eye=[0.3, 3.0, 4.5], target=[0, 0.3, 0.8])),
         make('wide2_fov90', objs, {'type': 'spot', 'position': [0, 1.2, 0], 'target': [0.2, 0, 0.6], 'fov': 90}, dict(CAM, eye=[0.3, 3.0, 4.5], target=[0, 0.3, 0.8]))]
    json.dump(n, open(os.path.join(HERE, 'set10.json'), 'w')); return n
if __name__ == '__main__' and 'wide2' in sys.argv:
    print(wide2())

def twospot():
    """F0: scenes/anchor_spot.json with a second spot light (needs set1 written first)."""
    j = json.load(open(os.path.join(HERE, 'scenes', 'anchor_spot.json')))
    L = j.pop('light'); L['intensity'] = 0.5
    j['lights'] = [L, dict(L, position=[-3, 6, 1.5])]
    json.dump(j, open(os.path.join(HERE, 'scenes', 'twospot_anchor.json'), 'w'), indent=1)
if __name__ == '__main__' and 'twospot' in sys.argv:
    twospot()

def twopoint():
    """room.json (shipped) with a second point light; mesh paths made absolute."""
    j = json.load(open(ROOT + '/data/scenes/point/room.json'))
    for o in j['objects']:
        if 'file' in o: o['file'] = os.path.join(ROOT + '/data/scenes/point', o['file'])
    L = j.pop('light'); L['intensity'] = 0.5
    j['lights'] = [L, dict(L, position=[1.0, 2.5, -0.8])]
    json.dump(j, open(os.path.join(HERE, 'scenes', 'twopoint_room.json'), 'w'), indent=1)
if __name__ == '__main__' and 'twopoint' in sys.argv:
    twopoint()
