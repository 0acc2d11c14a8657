#!/usr/bin/env python3
"""Tables for the README: the thesis's claims checked against a `shadowvol bench` run.

Usage: python3 scripts/sweep_claims.py MAIN/results.csv [POLY/results.csv]
Reads only the CSV files (stdlib only) and prints Markdown.
"""
import csv
import sys


def load(path):
    rows = {}
    for r in csv.DictReader(open(path)):
        rows[(r["scene"], r["method"], int(r["resolution"]))] = r
    return rows


def ms(r):
    return float(r["frame_ms"])


def err(r):
    return 100.0 * float(r["error"])


def main():
    main_rows = load(sys.argv[1])
    scenes = sorted({k[0] for k in main_rows}, key=lambda s: (s != "default", s))
    res_all = sorted({k[2] for k in main_rows if k[2] > 0})

    print("### Claim 1: hybrid from 256^2 against shadow maps up to 2048^2 (misclassified %)\n")
    print("| scene | hybrid-perfect 256 | front capture | midpoint capture | shadowmap 256 | shadowmap 2048 "
          "| smallest shadow map at least as good | silhouette |")
    print("|---|---:|---:|---:|---:|---:|---:|---:|")
    for s in scenes:
        h = main_rows.get((s, "hybrid-perfect/gpu", 256))
        if not h:
            continue
        sm = {n: main_rows[(s, "shadowmap", n)] for n in res_all if (s, "shadowmap", n) in main_rows}
        match = next((n for n in sorted(sm) if err(sm[n]) <= err(h)), None)
        sil = main_rows.get((s, "silhouette", 0))
        fr = main_rows.get((s, "hybrid-perfect-front/gpu", 256))
        mid = main_rows.get((s, "hybrid-perfect-midpoint/gpu", 256))
        opt = lambda r: f"{err(r):.3f}" if r else "-"
        print(f"| {s} | {err(h):.3f} | {opt(fr)} | {opt(mid)} | {err(sm[256]):.3f} | {err(sm[2048]):.3f} | "
              f"{match if match else 'none up to ' + str(max(sm))} | {err(sil):.4f} |" if sil else "")

    print("\n### Claims 2 and 3: cost of blur and of perfect triangulation (frame time ratios)\n")
    print("| scene | res | fixed/gpu ms | blur/fixed gpu | perfect/fixed gpu | fixed/explicit ms | blur/fixed explicit | perfect/fixed explicit |")
    print("|---|---:|---:|---:|---:|---:|---:|---:|")
    for s in scenes:
        for n in (256, 1024):
            k = lambda m: main_rows.get((s, m, n))
            fg, bg, pg = k("hybrid-fixed/gpu"), k("hybrid-fixed-blur/gpu"), k("hybrid-perfect/gpu")
            fe, be, pe = k("hybrid-fixed/explicit"), k("hybrid-fixed-blur/explicit"), k("hybrid-perfect/explicit")
            if not all((fg, bg, pg, fe, be, pe)):
                continue
            print(f"| {s} | {n} | {ms(fg):.1f} | {ms(bg)/ms(fg):.2f} | {ms(pg)/ms(fg):.2f} | "
                  f"{ms(fe):.1f} | {ms(be)/ms(fe):.2f} | {ms(pe)/ms(fe):.2f} |")

    print("\n### Claim 2 (quality): does blur reduce the error? (misclassified %, fixed vs fixed + blur, gpu)\n")
    print("| scene | res | fixed | fixed + blur | perfect | perfect + blur |")
    print("|---|---:|---:|---:|---:|---:|")
    for s in scenes:
        for n in (256, 1024):
            k = lambda m: main_rows.get((s, m, n))
            a, b, c, d = k("hybrid-fixed/gpu"), k("hybrid-fixed-blur/gpu"), k("hybrid-perfect/gpu"), k("hybrid-perfect-blur/gpu")
            if all((a, b, c, d)):
                print(f"| {s} | {n} | {err(a):.3f} | {err(b):.3f} | {err(c):.3f} | {err(d):.3f} |")

    print("\n### Claim 4: frame time against depth-map resolution (default scene, ms)\n")
    methods = ["shadowmap", "pcf5", "hybrid-perfect/gpu", "hybrid-perfect/explicit"]
    print("| resolution | " + " | ".join(methods) + " |")
    print("|---:|" + "---:|" * len(methods))
    for n in res_all:
        cells = [main_rows.get(("default", m, n)) for m in methods]
        print(f"| {n} | " + " | ".join(f"{ms(c):.1f}" if c else "-" for c in cells) + " |")

    if len(sys.argv) > 2:
        poly = load(sys.argv[2])
        pscenes = sorted({k[0] for k in poly})
        print("\n### Claim 4: frame time against triangle count (polygon sweep, 256^2 depth map, ms)\n")
        methods = ["shadowmap", "pcf5", "hybrid-fixed/gpu", "hybrid-perfect/gpu", "hybrid-perfect/explicit", "silhouette"]
        print("| triangles | " + " | ".join(methods) + " |")
        print("|---:|" + "---:|" * len(methods))
        for s in pscenes:
            tri = next(r["triangles"] for k, r in poly.items() if k[0] == s)
            cells = [poly.get((s, m, 0 if m == "silhouette" else 256)) for m in methods]
            print(f"| {int(tri):,} | " + " | ".join(f"{ms(c):.1f}" if c else "-" for c in cells) + " |")


if __name__ == "__main__":
    main()
