#!/usr/bin/env python3
"""Writes the probe's mesh variants and scenes into /tmp/probe13/A/gen/ (run: python3 gen.py)."""
import base64, json, math, os, struct

OUT = "/tmp/probe13/A/gen"
os.makedirs(OUT, exist_ok=True)


def w(name, data, mode="w"):
    with open(os.path.join(OUT, name), mode + ("b" if isinstance(data, bytes) else "")) as f:
        f.write(data)


# ---------------------------------------------------------------- base shapes
# Unit cube centred at (0, 0.5, 0) (size 1), quads wound outward (CCW seen from outside).
CUBE_V = [(-.5, 0, -.5), (.5, 0, -.5), (.5, 0, .5), (-.5, 0, .5),
          (-.5, 1, -.5), (.5, 1, -.5), (.5, 1, .5), (-.5, 1, .5)]
CUBE_Q = [(0, 1, 2, 3), (4, 7, 6, 5), (0, 4, 5, 1), (1, 5, 6, 2), (2, 6, 7, 3), (3, 7, 4, 0)]
CUBE_T = [t for q in CUBE_Q for t in ((q[0], q[1], q[2]), (q[0], q[2], q[3]))]

# L-shaped prism: L outline in XZ, extruded along Y from 0 to 1. The outline starts at a convex
# vertex that does not see the whole L, so a fan from corner 0 leaves the polygon.
L2 = [(2, 0), (2, 1), (1, 1), (1, 2), (0, 2), (0, 0)]  # (x, z), CCW seen from +y? check below


def area2(poly):
    return sum(poly[i][0] * poly[(i + 1) % len(poly)][1] - poly[(i + 1) % len(poly)][0] * poly[i][1]
               for i in range(len(poly)))


# In XZ with Y up, a face seen from +Y is CCW when (x, -z) is CCW, i.e. area2 over (x, z) < 0.
if area2(L2) > 0:
    L2 = L2[::-1]
n = len(L2)
L_V = [(x - 1, 0.0, z - 1) for x, z in L2] + [(x - 1, 1.0, z - 1) for x, z in L2]
top = tuple(n + i for i in range(n))                       # seen from +Y: CCW
bottom = tuple(reversed(range(n)))                         # seen from -Y
# rotate so that the polygon starts at a convex vertex that cannot see the reflex one's far side
L_F = [top, bottom] + [(i, (i + 1) % n, n + (i + 1) % n, n + i) for i in range(n)]


def fix_side_winding(V, F):
    """Orients the side quads outward using the outline's own edge normals (caps left as built)."""
    A = area2(L2)
    out = [F[0], F[1]]
    for f in F[2:]:
        i, j = f[0], f[1]
        dx, dz = V[j][0] - V[i][0], V[j][2] - V[i][2]
        want = (dz, -dx) if A > 0 else (-dz, dx)          # outward normal in XZ
        a, b, c = V[f[0]], V[f[1]], V[f[2]]
        nx = (b[1]-a[1])*(c[2]-a[2])-(b[2]-a[2])*(c[1]-a[1]); nz = (b[0]-a[0])*(c[1]-a[1])-(b[1]-a[1])*(c[0]-a[0])
        out.append(tuple(f) if nx*want[0] + nz*want[1] > 0 else tuple(reversed(f)))
    return out


L_F = fix_side_winding(L_V, L_F)


def tri_of(F):
    """Ear-free fan (as shadowvol does) - only for reference."""
    return [(f[0], f[k], f[k + 1]) for f in F for k in range(1, len(f) - 1)]


def L_correct_tris():
    """The L prism triangulated correctly (caps split at the reflex vertex)."""
    V = L_V
    # find the reflex vertex index r in the outline, fan from it (the L is star-shaped from it)
    r = L2.index((1, 1))
    tris = []
    for cap, off, rev in ((list(range(n)), n, False), (list(range(n)), 0, True)):
        order = [(r + k) % n for k in range(n)]
        for k in range(1, n - 1):
            t = (off + order[0], off + order[k], off + order[k + 1])
            tris.append(t)
    # orient caps: top CCW from +Y, bottom opposite
    top_ok = []
    for t in tris:
        a, b, c = V[t[0]], V[t[1]], V[t[2]]
        ny = (b[2]-a[2])*(c[0]-a[0])-(b[0]-a[0])*(c[2]-a[2])
        want_up = a[1] > 0.5
        top_ok.append(t if (ny > 0) == want_up else (t[0], t[2], t[1]))
    sides = [t for f in L_F[2:] for t in ((f[0], f[1], f[2]), (f[0], f[2], f[3]))]
    return top_ok + sides


# ---------------------------------------------------------------- writers
def obj(V, F, extra_head="", extra_tail="", neg=False, eol="\n"):
    s = extra_head
    for v in V:
        s += "v %r %r %r%s" % (v[0], v[1], v[2], eol)
    for f in F:
        if neg:
            s += "f " + " ".join(str(i - len(V)) for i in f) + eol
        else:
            s += "f " + " ".join(str(i + 1) for i in f) + eol
    return s + extra_tail


def off(V, F, kw="OFF", vextra="", fextra=""):
    s = "%s\n%d %d 0\n" % (kw, len(V), len(F))
    for v in V:
        s += "%r %r %r%s\n" % (v[0], v[1], v[2], vextra)
    for f in F:
        s += "%d %s%s\n" % (len(f), " ".join(map(str, f)), fextra)
    return s


def ply_binary(V, F, endian=">", ctype="d", itype="I", ltype="B", odd=False):
    """Binary PLY. odd=True: extra vertex properties before/after x y z, a list property in the
    vertex element, face element declared before vertex, an extra element between, and an extra list
    property in the face element before vertex_indices."""
    tn = {"d": "double", "f": "float", "I": "uint", "i": "int", "B": "uchar", "H": "ushort", "h": "short", "b": "char"}
    hdr = ["ply", "format binary_%s_endian 1.0" % ("big" if endian == ">" else "little"), "comment probe13"]
    body = b""
    vert_el = ["element vertex %d" % len(V)]
    if odd:
        vert_el += ["property uchar red", "property list uchar float texlist", "property %s z" % tn[ctype],
                    "property float nx", "property %s x" % tn[ctype], "property %s y" % tn[ctype], "property ushort flags"]
    else:
        vert_el += ["property %s x" % tn[ctype], "property %s y" % tn[ctype], "property %s z" % tn[ctype]]
    face_el = ["element face %d" % len(F)]
    if odd:
        face_el += ["property list uchar float texcoord", "property uchar quality",
                    "property list %s %s vertex_index" % (tn[ltype], tn[itype]), "property int material"]
    else:
        face_el += ["property list %s %s vertex_indices" % (tn[ltype], tn[itype])]

    def vbytes():
        b = b""
        for v in V:
            if odd:
                b += struct.pack(endian + "B", 200) + struct.pack(endian + "B", 2) + struct.pack(endian + "2f", 0.25, 0.75)
                b += struct.pack(endian + ctype, v[2]) + struct.pack(endian + "f", 0.0)
                b += struct.pack(endian + ctype * 2, v[0], v[1]) + struct.pack(endian + "H", 7)
            else:
                b += struct.pack(endian + ctype * 3, *v)
        return b

    def fbytes():
        b = b""
        for f in F:
            if odd:
                b += struct.pack(endian + "B", 6) + struct.pack(endian + "6f", *([0.5] * 6)) + struct.pack(endian + "B", 9)
            b += struct.pack(endian + ltype, len(f)) + struct.pack(endian + itype * len(f), *f)
            if odd:
                b += struct.pack(endian + "i", -3)
        return b

    if odd:
        edge_el = ["element edge 2", "property int vertex1", "property int vertex2"]
        edges = struct.pack(endian + "4i", 0, 1, 1, 2)
        hdr += face_el + edge_el + vert_el
        body = fbytes() + edges + vbytes()
    else:
        hdr += vert_el + face_el
        body = vbytes() + fbytes()
    return ("\n".join(hdr + ["end_header"]) + "\n").encode() + body


def ply_ascii(V, F, eol="\n", sep=" "):
    s = eol.join(["ply", "format ascii 1.0", "element vertex %d" % len(V), "property float x", "property float y",
                  "property float z", "element face %d" % len(F), "property list uchar int vertex_indices",
                  "end_header"]) + eol
    for v in V:
        s += sep.join("%r" % c for c in v) + eol
    for f in F:
        s += sep.join(str(x) for x in [len(f)] + list(f)) + eol
    return s


def tris(V, F):
    return [(V[f[0]], V[f[k]], V[f[k + 1]]) for f in F for k in range(1, len(f) - 1)]


def normal(a, b, c):
    u = [b[i] - a[i] for i in range(3)]; v = [c[i] - a[i] for i in range(3)]
    return (u[1]*v[2]-u[2]*v[1], u[2]*v[0]-u[0]*v[2], u[0]*v[1]-u[1]*v[0])


def stl_ascii(V, F, style="plain"):
    if style == "upper":
        kw = dict(solid="SOLID", facet="FACET NORMAL", outer="OUTER LOOP", vertex="VERTEX", endloop="ENDLOOP",
                  endfacet="ENDFACET", endsolid="ENDSOLID")
    else:
        kw = dict(solid="solid", facet="facet normal", outer="outer loop", vertex="vertex", endloop="endloop",
                  endfacet="endfacet", endsolid="endsolid")
    eol = "\r\n" if style in ("crlf", "messy") else "\n"
    ind = "\t" if style == "messy" else "  "
    s = kw["solid"] + " probe" + eol
    for t in tris(V, F):
        nrm = normal(*t)
        s += ind + kw["facet"] + (" %e %e %e" % nrm) + eol + ind * 2 + kw["outer"] + eol
        for p in t:
            if style == "messy":
                s += ind * 3 + kw["vertex"] + "\t  %e\t%e   %e  " % p + eol
            else:
                s += ind * 3 + kw["vertex"] + " %e %e %e" % p + eol
        s += ind * 2 + kw["endloop"] + eol + ind + kw["endfacet"] + eol
        if style == "messy":
            s += eol  # blank line between facets
    s += kw["endsolid"] + " probe" + eol
    return s


def stl_binary(V, F, header=b"solid binary header that begins with solid", pad=b""):
    T = tris(V, F)
    b = header.ljust(80, b" ")[:80] + struct.pack("<I", len(T))
    for t in T:
        b += struct.pack("<3f", *normal(*t)) + b"".join(struct.pack("<3f", *p) for p in t) + b"\0\0"
    return b + pad


def gltf(meshes, nodes, scene_nodes, name, binary=False):
    """meshes: list of (V, T) triangle lists; nodes: glTF node dicts (with 'mesh' index)."""
    buf = b""
    accessors, views, gmeshes = [], [], []
    for V, T in meshes:
        vb = b"".join(struct.pack("<3f", *v) for v in V)
        ib = b"".join(struct.pack("<3I", *t) for t in T)
        views.append({"buffer": 0, "byteOffset": len(buf), "byteLength": len(vb), "target": 34962})
        buf += vb
        views.append({"buffer": 0, "byteOffset": len(buf), "byteLength": len(ib), "target": 34963})
        buf += ib
        mn = [min(v[i] for v in V) for i in range(3)]; mx = [max(v[i] for v in V) for i in range(3)]
        accessors.append({"bufferView": len(views) - 2, "componentType": 5126, "count": len(V), "type": "VEC3",
                          "min": mn, "max": mx})
        accessors.append({"bufferView": len(views) - 1, "componentType": 5125, "count": 3 * len(T), "type": "SCALAR"})
        gmeshes.append({"primitives": [{"attributes": {"POSITION": len(accessors) - 2}, "indices": len(accessors) - 1}]})
    doc = {"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": scene_nodes}], "nodes": nodes,
           "meshes": gmeshes, "accessors": accessors, "bufferViews": views}
    if binary:
        doc["buffers"] = [{"byteLength": len(buf)}]
        js = json.dumps(doc).encode()
        js += b" " * (-len(js) % 4)
        bb = buf + b"\0" * (-len(buf) % 4)
        out = struct.pack("<3I", 0x46546C67, 2, 12 + 8 + len(js) + 8 + len(bb))
        out += struct.pack("<2I", len(js), 0x4E4F534A) + js + struct.pack("<2I", len(bb), 0x004E4942) + bb
        w(name, out)
    else:
        doc["buffers"] = [{"byteLength": len(buf),
                           "uri": "data:application/octet-stream;base64," + base64.b64encode(buf).decode()}]
        w(name, json.dumps(doc, indent=1))


# ---------------------------------------------------------------- the cube in many variants
w("cube.obj", obj(CUBE_V, CUBE_Q))
w("cube_neg.obj", obj(CUBE_V, CUBE_Q, neg=True))
# OBJ with everything around the faces: groups, objects, materials, smoothing, vt/vn, lines, points,
# vertex colours, w, CRLF, faces "v/vt/vn", "v//vn", "v/vt"
s = "# probe13 kitchen-sink OBJ\r\nmtllib nothere.mtl\r\no Cube\r\n"
for v in CUBE_V:
    s += "v %r %r %r 0.1 0.2 0.3\r\n" % v
s += "vt 0 0\r\nvt 1 0\r\nvt 1 1\r\nvt 0 1\r\nvn 0 1 0\r\nvp 0.5 0.5\r\n"
s += "g sideA sideB\r\nusemtl red\r\ns 1\r\nl 1 2 3\r\np 1 2\r\n"
styles = ["%d", "%d/%d", "%d//1", "%d/%d/1"]
for k, f in enumerate(CUBE_Q):
    st = styles[k % 4]
    toks = [(st % ((i + 1, j % 4 + 1) if st.count("%d") == 2 else (i + 1,))) for j, i in enumerate(f)]
    s += ("g side%d\r\n" % k) + "f\t" + "  ".join(toks) + "   # face %d\r\n" % k
s += "s off\r\n"
w("cube_sink.obj", s)
# OBJ with faces before the vertices they use (forward references)
w("cube_fwd.obj", "".join("f %s\n" % " ".join(str(i + 1) for i in f) for f in CUBE_Q) +
  "".join("v %r %r %r\n" % v for v in CUBE_V))
# OBJ with a line continuation (legal OBJ), and with 'v' of 4 coordinates
w("cube_cont.obj", "".join("v %r %r %r\n" % v for v in CUBE_V) +
  "".join("f %d %d \\\n  %d %d\n" % tuple(i + 1 for i in f) for f in CUBE_Q))
# OBJ with isolated vertices, a duplicate face and a zero-area face
w("cube_junk.obj", obj(CUBE_V + [(5, 5, 5), (0, 0.5, 0)], CUBE_Q + [CUBE_Q[0]] ))
w("cube_isolated.obj", obj(CUBE_V + [(5, 5, 5)], CUBE_Q))
# inside-out cube
w("cube_inside_out.obj", obj(CUBE_V, [tuple(reversed(q)) for q in CUBE_Q]))
# OFF variants
w("cube.off", off(CUBE_V, CUBE_Q))
w("cube_c.off", off(CUBE_V, CUBE_Q, "COFF", vextra=" 255 0 0 255"))
w("cube_fc.off", off(CUBE_V, CUBE_Q, "OFF", fextra=" 0.5 0.5 0.5 1"))
w("cube_n.off", off(CUBE_V, CUBE_Q, "NOFF", vextra=" 0 1 0"))
w("cube_st.off", off(CUBE_V, CUBE_Q, "STOFF", vextra=" 0.5 0.5"))
w("cube_cn.off", off(CUBE_V, CUBE_Q, "CNOFF", vextra=" 0 1 0 1 0 0 1"))
w("cube_sameline.off", "OFF 8 6 12\n" + off(CUBE_V, CUBE_Q).split("\n", 2)[2])
w("cube_crlf.off", off(CUBE_V, CUBE_Q).replace("\n", "\r\n"))
w("cube_tabs.off", off(CUBE_V, CUBE_Q).replace(" ", "\t"))
# PLY variants
w("cube_be_d.ply", ply_binary(CUBE_V, CUBE_Q, ">", "d", "I", "B"))
w("cube_le_f.ply", ply_binary(CUBE_V, CUBE_Q, "<", "f", "i", "B"))
w("cube_be_odd.ply", ply_binary(CUBE_V, CUBE_Q, ">", "f", "H", "H", odd=True))
w("cube_le_odd.ply", ply_binary(CUBE_V, CUBE_Q, "<", "d", "b", "I", odd=True))
w("cube_ascii.ply", ply_ascii(CUBE_V, CUBE_Q))
w("cube_ascii_crlf_tab.ply", ply_ascii(CUBE_V, CUBE_Q, "\r\n", "\t"))
# STL variants
w("cube_ascii.stl", stl_ascii(CUBE_V, CUBE_Q))
w("cube_messy.stl", stl_ascii(CUBE_V, CUBE_Q, "messy"))
w("cube_upper.stl", stl_ascii(CUBE_V, CUBE_Q, "upper"))
w("cube_bin.stl", stl_binary(CUBE_V, CUBE_Q))
w("cube_bin_pad.stl", stl_binary(CUBE_V, CUBE_Q, pad=b"\0\0\0\0"))
# glTF: the cube as one mesh; several nodes; a mirrored node; instancing; matrix node; nested scale
CT = CUBE_T
gltf([(CUBE_V, CT)], [{"mesh": 0}], [0], "cube.gltf")
gltf([(CUBE_V, CT)], [{"mesh": 0}], [0], "cube.glb", binary=True)
nodes = [
    {"name": "a", "mesh": 0, "translation": [-2, 0, 0]},
    {"name": "b", "mesh": 0, "translation": [2, 0, 0], "scale": [-1, 1, 1]},           # mirrored
    {"name": "c", "mesh": 0, "translation": [0, 0, 2], "rotation": [0, 0.3826834, 0, 0.9238795]},  # 45 deg about Y
    {"name": "parent", "scale": [2, 2, 2], "translation": [0, 0, -3], "children": [4]},
    {"name": "child", "mesh": 0, "scale": [0.5, 0.25, 0.5], "matrix": None},
]
nodes[4].pop("matrix")
gltf([(CUBE_V, CT)], nodes, [0, 1, 2, 3], "cubes_nodes.gltf")
# a node given as a matrix with a mirror (det < 0) and rotation
m = [0, 0, -1, 0,  0, 1, 0, 0,  -1, 0, 0, 0,  0, 0, 0, 1]  # column-major: x->-z, z->-x  (det -1)
gltf([(CUBE_V, CT)], [{"name": "mm", "mesh": 0, "matrix": m}], [0], "cube_mirror_matrix.gltf")
# glTF with an inside-out cube (triangles reversed) and a cube inside another (nested shells)
big = [(2 * x, 2 * y - 0.5, 2 * z) for x, y, z in CUBE_V]
gltf([(big, CT), (CUBE_V, [(a, c, b) for a, b, c in CT])], [{"mesh": 0}, {"mesh": 1}], [0, 1], "nested.gltf")

# ---------------------------------------------------------------- L prism
w("L_fan.obj", obj(L_V, L_F))
w("L_fan.off", off(L_V, L_F))
w("L_fan.ply", ply_binary(L_V, L_F, ">", "f", "i", "B"))
w("L_tri.obj", obj(L_V, L_correct_tris()))

# ---------------------------------------------------------------- far / tiny coordinates
def shifted(V, off, s=1.0):
    return [(x * s + off[0], y * s + off[1], z * s + off[2]) for x, y, z in V]


w("cube_at_1e6.ply", ply_binary(shifted(CUBE_V, (1e6, 0, 1e6)), CUBE_Q, "<", "f", "i", "B"))
w("cube_at_1e6_d.ply", ply_binary(shifted(CUBE_V, (1e6, 0, 1e6)), CUBE_Q, "<", "d", "i", "B"))
w("cube_at_1e7.obj", obj(shifted(CUBE_V, (1e7, 5e6, -1e7)), CUBE_Q))
w("cube_tiny.obj", obj(shifted(CUBE_V, (0, 0, 0), 1e-5), CUBE_Q))
w("cube_tiny_far.obj", obj(shifted(CUBE_V, (3.0, 0, 0), 1e-5), CUBE_Q))
gltf([(CUBE_V, CT)], [{"mesh": 0, "translation": [1e7, 0, 1e7]}], [0], "cube_node_1e7.gltf")
gltf([(shifted(CUBE_V, (1e7, 0, 1e7)), CT)], [{"mesh": 0, "translation": [-1e7, 0, -1e7]}], [0],
     "cube_stored_1e7_node_back.gltf")
print("written to", OUT)

# ---------------------------------------------------------------- stray (unused) vertices
w("cube_stray.obj", obj(CUBE_V + [(1000.0, 0.0, 1000.0)], CUBE_Q))
w("cube_stray_ply.ply", ply_binary(CUBE_V + [(1000.0, 0.0, 1000.0)], CUBE_Q, "<", "f", "i", "B"))
print("stray written")
