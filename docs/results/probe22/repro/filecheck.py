#!/usr/bin/python3
import sys, json, zlib, struct, os, csv, math
import xml.etree.ElementTree as ET
import numpy as np

def bad_const(c): raise ValueError('non-standard JSON constant ' + c)

def walk_nums(o, path, out):
    if isinstance(o, dict):
        for k, v in o.items(): walk_nums(v, path + '/' + str(k), out)
    elif isinstance(o, list):
        for i, v in enumerate(o): walk_nums(v, path + '/' + str(i), out)
    elif isinstance(o, float) and not math.isfinite(o): out.append(path)

def check_json(p):
    probs = []
    try:
        raw = open(p, 'rb').read()
        txt = raw.decode('utf-8')
        o = json.loads(txt, parse_constant=bad_const)
        if not txt.endswith('\n'): probs.append('no trailing newline (minor)')
    except Exception as e:
        return ['JSON: %r' % e]
    return probs

def check_png(p):
    probs = []
    d = open(p, 'rb').read()
    if d[:8] != b'\x89PNG\r\n\x1a\n': return ['PNG signature']
    off = 8; chunks = []; idat = b''
    while off < len(d):
        if off + 8 > len(d): probs.append('truncated chunk header'); break
        ln, typ = struct.unpack('>I4s', d[off:off+8])
        body = d[off+8:off+8+ln]; crc = d[off+8+ln:off+12+ln]
        if len(crc) != 4: probs.append('truncated chunk %r' % typ); break
        if zlib.crc32(typ + body) & 0xffffffff != struct.unpack('>I', crc)[0]: probs.append('CRC mismatch in %r' % typ)
        chunks.append((typ, body)); off += 12 + ln
        if typ == b'IDAT': idat += body
        if typ == b'IEND':
            if off != len(d): probs.append('%d bytes after IEND' % (len(d) - off))
            break
    types = [c[0] for c in chunks]
    if types[0] != b'IHDR': probs.append('first chunk not IHDR')
    if types[-1] != b'IEND': probs.append('no IEND')
    w, h, bd, ct, cm, fm, il = struct.unpack('>IIBBBBB', chunks[0][1])
    try:
        raw = zlib.decompress(idat)
    except Exception as e:
        return probs + ['zlib: %r' % e]
    ch = {0: 1, 2: 3, 3: 1, 4: 2, 6: 4}[ct]
    bpp = ch * bd / 8
    if il == 0:
        stride = int(math.ceil(w * ch * bd / 8))
        if len(raw) != h * (stride + 1): probs.append('IDAT size %d != %d' % (len(raw), h * (stride + 1)))
        ft = set(raw[i*(stride+1)] for i in range(h))
        if max(ft) > 4: probs.append('bad filter type')
    if ct == 3 and b'PLTE' not in types: probs.append('palette image without PLTE')
    return probs + ['(info %dx%d bd%d ct%d)' % (w, h, bd, ct)]

def check_svg(p):
    try:
        t = ET.parse(p); r = t.getroot()
        if not r.tag.endswith('svg'): return ['root %r' % r.tag]
        probs = []
        # NaN/inf in attributes
        for el in r.iter():
            for k, v in el.attrib.items():
                if any(s in v.lower() for s in ('nan', 'inf')) and k not in ('font-family',):
                    probs.append('attr %s=%r' % (k, v[:60]))
        return probs[:5]
    except Exception as e:
        return ['SVG XML: %r' % e]

def check_csv(p):
    probs = []
    rows = list(csv.reader(open(p, newline='')))
    if not rows: return ['empty']
    n = len(rows[0])
    for i, r in enumerate(rows[1:], 2):
        if len(r) != n: probs.append('row %d has %d fields, header %d' % (i, len(r), n))
        for x in r:
            if x.lower() in ('nan', 'inf', '-inf', 'infinity'): probs.append('row %d value %r' % (i, x))
    return probs[:10] + ['(%d rows x %d cols)' % (len(rows) - 1, n)]

def check_pfm(p):
    d = open(p, 'rb').read(); probs = []
    # header: "Pf\n" or "PF\n", "W H\n", "scale\n"
    parts = []; off = 0
    for k in range(3):
        e = d.index(b'\n', off); parts.append(d[off:e]); off = e + 1
    typ = parts[0].strip()
    if typ not in (b'Pf', b'PF'): probs.append('type %r' % typ)
    w, h = map(int, parts[1].split())
    sc = float(parts[2])
    ch = 1 if typ == b'Pf' else 3
    en = '<' if sc < 0 else '>'
    need = w * h * ch * 4
    if len(d) - off != need: probs.append('data %d bytes, header implies %d' % (len(d) - off, need))
    a = np.frombuffer(d, dtype=en + 'f4', count=w * h * ch, offset=off)
    nf = np.sum(~np.isfinite(a))
    probs.append('(info %s %dx%d scale %g; nonfinite %d; min %g max %g; header %r)' % (typ, w, h, sc, nf, np.nanmin(a), np.nanmax(a), d[:off]))
    return probs

for p in sys.argv[1:]:
    ext = p.rsplit('.', 1)[-1].lower()
    f = {'json': check_json, 'png': check_png, 'svg': check_svg, 'csv': check_csv, 'pfm': check_pfm}.get(ext)
    if not f: continue
    try: r = f(p)
    except Exception as e: r = ['EXC %r' % e]
    real = [x for x in r if not x.startswith('(')]
    print(('OK   ' if not real else 'BAD  ') + p + ' ' + '; '.join(r))
