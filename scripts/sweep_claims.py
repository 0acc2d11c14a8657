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

    refinement(main_rows, scenes)

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


def pareto(points, slack=1.0):
    """Indices of the (time, error) points no other point beats on both (ties kept). With slack > 1
    a point is beaten only by one faster by more than that factor (t2 * slack < t) and no worse in
    error: frame times within the factor count as equal (the spread between runs)."""
    front = []
    for i, (t, e) in enumerate(points):
        if slack > 1.0:
            beaten = any(t2 * slack < t and e2 <= e for j, (t2, e2) in enumerate(points) if j != i)
        else:
            beaten = any((t2 <= t and e2 <= e) and (t2 < t or e2 < e) for j, (t2, e2) in enumerate(points) if j != i)
        if not beaten:
            front.append(i)
    return front


def refinement(rows, scenes):
    """The refined explicit volume against shadow maps and silhouette volumes, and where it lies on
    each scene's Pareto front of (frame ms, error)."""
    ref = "hybrid-refined/explicit"
    if not any(k[1] == ref for k in rows):
        return
    print("\n### Silhouette refinement: misclassified % (frame ms)\n")
    grid = "hybrid-refined-grid/explicit"
    print("| scene | refined 128 | refined 256 | refined-front 128 | refined-midpoint 128 | refined-grid 128 "
          "| refined-grid 256 | refined-grid-front 128 | hybrid-perfect/explicit 256 "
          "| shadowmap 2048 | smallest shadow map at least as good as refined 128 | as good as refined-grid 128 "
          "| silhouette |")
    print("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
    cell = lambda r: f"{err(r):.4f} ({ms(r):.1f})" if r else "-"
    for s in scenes:
        g = lambda m, n: rows.get((s, m, n))
        r128 = g(ref, 128)
        if not r128:
            continue
        sms = sorted(n for (sc, m, n) in rows if sc == s and m == "shadowmap")
        first = lambda r: next((n for n in sms if r and err(rows[(s, "shadowmap", n)]) <= err(r)), None)
        match, gmatch = first(r128), first(g(grid, 128))
        print(f"| {s} | {cell(r128)} | {cell(g(ref, 256))} | {cell(g('hybrid-refined-front/explicit', 128))} | "
              f"{cell(g('hybrid-refined-midpoint/explicit', 128))} | {cell(g(grid, 128))} | {cell(g(grid, 256))} | "
              f"{cell(g('hybrid-refined-grid-front/explicit', 128))} | {cell(g('hybrid-perfect/explicit', 256))} | "
              f"{cell(g('shadowmap', 2048))} | {match if match else 'none up to ' + str(max(sms))} | "
              f"{gmatch if gmatch else ('none up to ' + str(max(sms)) if g(grid, 128) else '-')} | "
              f"{cell(g('silhouette', 0))} |")

    print("\n### Silhouette refinement on the Pareto front (frame ms against error, every method and resolution)\n")
    print("| scene | refined cells on the front | front, fastest first |")
    print("|---|---|---|")
    on = onGrid = onAny = onVariant = 0
    for s in scenes:
        keys = [k for k in rows if k[0] == s]
        pts = [(ms(rows[k]), err(rows[k])) for k in keys]
        front = sorted(pareto(pts), key=lambda i: pts[i][0])
        label = lambda k: k[1] + (f" {k[2]}" if k[2] else "")
        refined = [label(keys[i]) for i in front if keys[i][1].startswith("hybrid-refined")]
        on += any(keys[i][1] == ref for i in front)
        onGrid += any(keys[i][1] == grid for i in front)
        onAny += any(keys[i][1] in (ref, grid) for i in front)
        onVariant += any(keys[i][1].startswith("hybrid-refined") for i in front)
        print(f"| {s} | {', '.join(refined) if refined else 'none'} | "
              + ", ".join(f"{label(keys[i])} ({pts[i][0]:.1f} ms, {pts[i][1]:.4f} %)" for i in front) + " |")
    print(f"\n{ref} is on the front of {on} of {len(scenes)} scenes, {grid} of {onGrid}, one of the two of {onAny}, a refined method of any capture of {onVariant}.")
    # The same count with frame times within NOISE of each other taken as equal: a cell leaves the
    # front only for one faster by more than that and no worse in error.
    # The snap's ablation keys (the same methods with the snap off) are left out of these counts;
    # then frame times within 5 % are taken as equal (a cell leaves the front only for one faster
    # by more than that and no worse in error).
    for slack in (1.0, 1.05):
        counts = {}
        for m in (ref, grid, "hybrid-refined/gpu"):
            counts[m] = []
            for s in scenes:
                keys = [k for k in rows if k[0] == s and "-nosnap/" not in k[1]]
                pts = [(ms(rows[k]), err(rows[k])) for k in keys]
                if any(keys[i][1] == m for i in pareto(pts, slack)):
                    counts[m].append(s)
        how = "strictly" if slack == 1.0 else f"frame times within {round((slack - 1) * 100)} % taken as equal"
        print(f"Without the -nosnap keys, {how}: "
              + "; ".join(f"{m} on {len(v)} of {len(scenes)} ({', '.join(v) if v else 'none'})" for m, v in counts.items())
              + ".")


if __name__ == "__main__":
    main()
