#!/usr/bin/python3
"""Independent readers for shadowvol's output formats (own parsers with numpy, no shadowvol code).
Prints V, T, finiteness, closedness (every directed edge matched by its reverse exactly once),
signed volume, bounds; checks glTF 2.0 rules (accessor min/max for POSITION and that they are exact,
bufferView byteLength/offset within buffer, 4-byte alignment, componentType, GLB chunk padding)."""
import sys, struct, json, base64, os
import numpy as np
from collections import Counter

def read_ply(p):
    data = open(p, "rb").read()
    end = data.index(b"end_header") ; hdr_end = data.index(b"\n", end) + 1
    hdr = data[:hdr_end].decode("ascii").split("\n")
    fmt = None; elems = []; comments = []
    for line in hdr:
        t = line.split()
        if not t: continue
        if t[0] == "format": fmt = t[1]
        elif t[0] == "comment": comments.append(line)
        elif t[0] == "element": elems.append([t[1], int(t[2]), []])
        elif t[0] == "property": elems[-1][2].append(t[1:])
    assert fmt == "binary_little_endian", fmt
    tmap = {"float": "f4", "double": "f8", "uchar": "u1", "uint": "u4", "int": "i4", "uint8": "u1", "uint32": "u4", "float32": "f4", "float64": "f8"}
    off = hdr_end; V = F = None
    for name, n, props in elems:
        if name == "vertex":
            dt = np.dtype([(pp[1], "<" + tmap[pp[0]]) for pp in props])
            arr = np.frombuffer(data, dt, n, off); off += dt.itemsize * n
            V = np.stack([arr["x"], arr["y"], arr["z"]], 1).astype(np.float64)
        elif name == "face":
            pp = props[0]; assert pp[0] == "list"
            ct, it = "<" + tmap[pp[1]], "<" + tmap[pp[2]]
            cs, isz = np.dtype(ct).itemsize, np.dtype(it).itemsize
            if props and len(props) == 1:
                # assume all triangles; verify counts
                dt = np.dtype([("c", ct), ("i", it, 3)])
                arr = np.frombuffer(data, dt, n, off); off += dt.itemsize * n
                assert (arr["c"] == 3).all(), "non-triangle face"
                F = arr["i"].astype(np.int64)
    assert off == len(data), f"PLY: {len(data) - off} trailing bytes"
    return V, F, comments

def read_obj(p):
    V = []; F = []; com = []
    for line in open(p):
        if line.startswith("v "): V.append([float(x) for x in line.split()[1:4]])
        elif line.startswith("f "): F.append([int(x.split("/")[0]) - 1 for x in line.split()[1:]])
        elif line.startswith("#"): com.append(line.strip())
    return np.array(V), np.array(F, dtype=np.int64).reshape(-1, 3), com

def read_off(p):
    toks = open(p).read().split()
    assert toks[0] == "OFF"
    nv, nf = int(toks[1]), int(toks[2]); i = 4
    V = np.array(toks[i:i + 3 * nv], dtype=np.float64).reshape(nv, 3); i += 3 * nv
    F = []
    for _ in range(nf):
        k = int(toks[i]); F.append([int(x) for x in toks[i + 1:i + 1 + k]]); i += 1 + k
    assert i == len(toks), f"OFF: {len(toks) - i} trailing tokens"
    return V, np.array(F, dtype=np.int64), []

def read_stl(p):
    d = open(p, "rb").read(); n = struct.unpack_from("<I", d, 80)[0]
    assert len(d) == 84 + 50 * n, f"STL size {len(d)} != {84 + 50 * n}"
    dt = np.dtype([("n", "<f4", 3), ("v", "<f4", (3, 3)), ("a", "<u2")])
    arr = np.frombuffer(d, dt, n, 84)
    P = arr["v"].reshape(-1, 3).astype(np.float64)
    uniq, inv = np.unique(P, axis=0, return_inverse=True)
    return uniq, inv.reshape(-1, 3), [d[:80].rstrip(b"\0 ").decode("latin1")]

CT = {5120: "i1", 5121: "u1", 5122: "i2", 5123: "u2", 5125: "u4", 5126: "f4"}
NC = {"SCALAR": 1, "VEC2": 2, "VEC3": 3, "VEC4": 4, "MAT4": 16}
def gltf_common(g, bins, problems):
    if g.get("asset", {}).get("version") != "2.0": problems.append("asset.version not 2.0")
    for i, bv in enumerate(g["bufferViews"]):
        b = bins[bv["buffer"]]
        o = bv.get("byteOffset", 0)
        if o + bv["byteLength"] > len(b): problems.append(f"bufferView {i} past buffer end")
        if o % 4: problems.append(f"bufferView {i} offset {o} not 4-aligned")
    for i, b in enumerate(g["buffers"]):
        if b["byteLength"] > len(bins[i]): problems.append(f"buffer {i} byteLength {b['byteLength']} > data {len(bins[i])}")
    prim = g["meshes"][0]["primitives"][0]
    if prim.get("mode", 4) != 4: problems.append("mode not TRIANGLES")
    def acc(k):
        a = g["accessors"][k]; bv = g["bufferViews"][a["bufferView"]]
        o = bv.get("byteOffset", 0) + a.get("byteOffset", 0)
        dt = np.dtype("<" + CT[a["componentType"]]); nc = NC[a["type"]]
        if o % dt.itemsize: problems.append(f"accessor {k} offset not aligned to component")
        if a.get("byteOffset", 0) + a["count"] * nc * dt.itemsize > bv["byteLength"]: problems.append(f"accessor {k} past bufferView")
        arr = np.frombuffer(bins[bv["buffer"]], dt, a["count"] * nc, o).reshape(a["count"], nc)
        return a, bv, arr
    pa, pbv, P = acc(prim["attributes"]["POSITION"])
    if pa["componentType"] != 5126 or pa["type"] != "VEC3": problems.append("POSITION not float VEC3")
    if "min" not in pa or "max" not in pa: problems.append("POSITION min/max missing")
    else:
        if list(map(float, P.min(0))) != pa["min"] or list(map(float, P.max(0))) != pa["max"]:
            problems.append(f"POSITION min/max {pa['min']} {pa['max']} != data {P.min(0)} {P.max(0)}")
    if pbv.get("target") not in (None, 34962): problems.append("position bufferView target")
    if "indices" in prim:
        ia, ibv, I = acc(prim["indices"])
        if ia["componentType"] not in (5121, 5123, 5125): problems.append("index componentType")
        if ia["type"] != "SCALAR": problems.append("index type")
        if ibv.get("byteStride"): problems.append("index bufferView has byteStride")
        F = I.reshape(-1, 3).astype(np.int64)
    else: F = np.arange(len(P)).reshape(-1, 3)
    node = g["nodes"][g["scenes"][g.get("scene", 0)]["nodes"][0]]
    extra = [f"node {json.dumps({k: v for k, v in node.items() if k != 'name'})}"]
    return P.astype(np.float64), F, extra

def read_gltf(p):
    g = json.load(open(p)); problems = []
    bins = []
    for b in g["buffers"]:
        u = b["uri"]; assert u.startswith("data:application/octet-stream;base64,") or u.startswith("data:application/gltf-buffer;base64,"), u[:60]
        bins.append(base64.b64decode(u.split(",", 1)[1]))
    V, F, extra = gltf_common(g, bins, problems)
    return V, F, extra + problems

def read_glb(p):
    d = open(p, "rb").read(); problems = []
    magic, ver, length = struct.unpack_from("<4sII", d, 0)
    if magic != b"glTF" or ver != 2: problems.append("bad header")
    if length != len(d): problems.append(f"header length {length} != file {len(d)}")
    o = 12; chunks = []
    while o < len(d):
        cl, ct = struct.unpack_from("<I4s", d, o)
        if cl % 4: problems.append(f"chunk {ct} length {cl} not padded to 4")
        chunks.append((ct, d[o + 8:o + 8 + cl])); o += 8 + cl
    if o != len(d): problems.append("chunks overrun")
    assert chunks[0][0] == b"JSON"
    js = chunks[0][1]
    if js.rstrip(b" ") != js and not js.endswith(b" "): pass
    if any(c not in b" " for c in js[len(js.rstrip()):]): problems.append("JSON chunk padded with non-space")
    g = json.loads(js)
    binchunk = chunks[1][1] if len(chunks) > 1 else b""
    if len(chunks) > 1 and chunks[1][0] != b"BIN\0": problems.append("2nd chunk not BIN")
    if "uri" in g["buffers"][0]: problems.append("GLB buffer 0 has uri")
    if g["buffers"][0]["byteLength"] > len(binchunk) or len(binchunk) - g["buffers"][0]["byteLength"] > 3:
        problems.append(f"buffer byteLength {g['buffers'][0]['byteLength']} vs BIN chunk {len(binchunk)}")
    V, F, extra = gltf_common(g, [binchunk], problems)
    return V, F, extra + problems

def analyse(p):
    ext = os.path.splitext(p)[1][1:].lower()
    V, F, notes = {"ply": read_ply, "obj": read_obj, "off": read_off, "stl": read_stl, "gltf": read_gltf, "glb": read_glb}[ext](p)
    finite = bool(np.isfinite(V).all())
    inrange = bool(((F >= 0) & (F < len(V))).all())
    e = np.concatenate([F[:, [0, 1]], F[:, [1, 2]], F[:, [2, 0]]])
    c = Counter(map(tuple, e.tolist()))
    closed = all(v == 1 and c.get((b, a), 0) == 1 for (a, b), v in c.items())
    used = len(np.unique(F)) == len(V)
    a, b, cc = V[F[:, 0]], V[F[:, 1]], V[F[:, 2]]
    vol = float(np.einsum("ij,ij->i", a, np.cross(b, cc)).sum() / 6)
    area0 = int((np.linalg.norm(np.cross(b - a, cc - a), axis=1) == 0).sum())
    return dict(V=len(V), T=len(F), finite=finite, idx_ok=inrange, closed=closed, all_used=used, zero_area=area0,
                vol=vol, bmin=V.min(0).tolist(), bmax=V.max(0).tolist(), notes=notes), V, F

if __name__ == "__main__":
    for p in sys.argv[1:]:
        try:
            r, V, F = analyse(p)
            print(p, json.dumps(r))
        except Exception as ex:
            print(p, "READ FAILED:", repr(ex))
