#!/usr/bin/python3
import json, sys, glob, os
def sec(r):
    ae = r["againstExact"]["method"]; sc = r["stencilVsCount"]; m = r["meshChecks"]; p = r["pixels"]
    return (f"exSh={p['exactShadowed']:6d} vis={p['visible']:6d} miss={ae['missedShadow']:4d} false={ae['falseShadow']:4d} "
            f"stVsCnt={sc['disagree']}/{sc['pixels']} zfzp={r['zfailVsZpass']['disagree']} tri={m['triangles']} vol={m['volume']:.6g} valid={m['valid']} cnt={r.get('volumeCount')}")
for d in sys.argv[1:]:
    try: r = json.load(open(os.path.join(d, "report.json")))
    except Exception as e: print(d, "NO REPORT", e); continue
    n = os.path.basename(d)
    if "lights" in r:
        for L in r["lights"]: print(f"{n:16s} L{L['index']} {sec(L)} passed={r['passed']}")
    else: print(f"{n:16s} L0 {sec(r)} passed={r['passed']}")
    for w in r.get("sceneWarnings", []) + r.get("warnings", []): print("     W:", str(w)[:220])
