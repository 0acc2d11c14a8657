#!/usr/bin/env python3
"""Reads $OUT/runs.jsonl (OUT default out/probe11) and the report.json files run.py left; prints the
anomalies (non-zero exit, over 60 s, a mesh check not clean, stencil vs count below 99.99 %, a
non-finite value in a report, a FAILED verdict) and the refined-vs-2048-map comparison."""
import json, math, os, sys
B = os.path.abspath(os.environ.get("OUT", "out/probe11"))
runs = [json.loads(l) for l in open(sys.argv[1] if len(sys.argv) > 1 else B + "/runs.jsonl")]
DIRS = {"explicit": "rep", "gpu": "repg", "front": "repf", "entry": "repe", "map2048": "repm"}
anom = []
rep = {}
for r in runs:
    n, st = r["scene"], r["step"]
    if r["rc"] != 0:
        anom.append((n, st, "exit %d" % r["rc"], r["tail"][-1][:150] if r["tail"] else ""))
    if r["wall"] > 60:
        anom.append((n, st, "slow %.1fs" % r["wall"], ""))
    if st in DIRS:
        p = "%s/%s/%s/report.json" % (B, DIRS[st], n)
        if not os.path.exists(p):
            continue
        d = json.load(open(p))
        rep[(n, st)] = d
        mc = d.get("meshChecks") or {}
        if isinstance(mc, dict) and mc.get("notApplicable") is None:
            bad = {k: mc.get(k) for k in ("nonFiniteVertices", "boundaryEdges", "overusedEdges", "nonManifoldVertices", "degenerateTriangles", "badIndexTriangles", "isolatedVertices", "coincidentVertices") if mc.get(k)}
            if bad or (mc.get("outward") is False and mc.get("triangles")) or mc.get("closedManifold") is False:
                anom.append((n, st, "mesh check", "%s outward=%s" % (bad, mc.get("outward"))))
        sv = d.get("stencilVsCount") or {}
        if isinstance(sv, dict) and sv.get("fraction") is not None and sv["fraction"] < 0.9999:
            anom.append((n, st, "stencil vs count %.4f%%" % (100 * sv["fraction"]), "%d disagree" % sv.get("disagree", -1)))
        txt = json.dumps(d)
        if "NaN" in txt or "Infinity" in txt:
            anom.append((n, st, "non-finite in report", ""))
        if not d.get("passed"):
            anom.append((n, st, "FAILED", "; ".join(d.get("verdict", {}).get("failures", []))[:200]))
for a in anom:
    print("ANOM %-32s %-8s %-26s %s" % a)
print()
win = tot = 0
print("%-32s %10s %10s %10s %10s %10s %s" % ("scene", "expl256", "gpu128", "map2048", "front256", "entry256", "capture"))
for n in sorted({r["scene"] for r in runs}):
    e = lambda st: rep[(n, st)]["againstExact"]["method"]["errorFraction"] if (n, st) in rep else None
    f = lambda v: "-" if v is None else "%.4f%%" % (100 * v)
    x, m = e("explicit"), e("map2048")
    mark = ""
    if x is not None and m is not None:
        tot += 1
        if x <= m: win += 1
        else: mark = " <-- refined worse than 2048 map"
    cap = rep[(n, "explicit")]["options"]["capture"] if (n, "explicit") in rep else "-"
    print("%-32s %10s %10s %10s %10s %10s %s%s" % (n, f(x), f(e("gpu")), f(m), f(e("front")), f(e("entry")), cap, mark))
print("refined explicit 256 at most the 2048 map: %d of %d" % (win, tot))
print("runs: %d, scenes: %d, max wall %.1fs" % (len(runs), len({r['scene'] for r in runs}), max(r["wall"] for r in runs)))
