#!/usr/bin/env python3
"""Writes an OFF mesh as a triangle soup (every corner its own vertex) with each copy of a vertex
moved by up to `jitter` x its largest coordinate, per axis (seeded): the input the rims' seal is
for (docs/results/open-rims, "The seal").

Usage: python3 jitter_soup.py IN.off OUT.off [--jitter 1e-5] [--seed 1]   (stdlib only)
"""
import argparse
import random


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("inp")
    ap.add_argument("out")
    ap.add_argument("--jitter", type=float, default=1e-5)
    ap.add_argument("--seed", type=int, default=1)
    a = ap.parse_args()
    words = open(a.inp).read().split()
    if words[0] != "OFF":
        raise SystemExit(a.inp + ": not an OFF file")
    nv, nf, i = int(words[1]), int(words[2]), 4
    verts = [tuple(map(float, words[i + 3 * k:i + 3 * k + 3])) for k in range(nv)]
    i += 3 * nv
    faces = []
    for _ in range(nf):
        n = int(words[i])
        faces.append([int(w) for w in words[i + 1:i + 1 + n]])
        i += 1 + n
    tris = [(f[0], f[k], f[k + 1]) for f in faces for k in range(1, len(f) - 1)]
    rng = random.Random(a.seed)
    scale = a.jitter * max(abs(c) for v in verts for c in v)
    with open(a.out, "w") as out:
        out.write("OFF\n%d %d 0\n" % (3 * len(tris), len(tris)))
        for t in tris:
            for v in t:
                out.write("%.9g %.9g %.9g\n" % tuple(c + rng.uniform(-1.0, 1.0) * scale for c in verts[v]))
        for k in range(len(tris)):
            out.write("3 %d %d %d\n" % (3 * k, 3 * k + 1, 3 * k + 2))


if __name__ == "__main__":
    main()
