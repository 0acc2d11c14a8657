#!/usr/bin/env python3
"""Runs every probe11 scene (docs/results/probe11/scenes) through build / check / validate (explicit 256² with
the 4 x 4 sub-grid, GPU 128², front and entry capture on every third, the 2048² map) one process at a
time, each under `timeout 120`; appends one JSON line per run to $OUT/runs.jsonl (OUT default
out/probe11). Usage: python3 docs/results/probe11/run.py [SCENE-NAME ...]"""
import glob, json, os, subprocess, sys, time
EXE = os.path.abspath(os.environ.get("SHADOWVOL", "build/apps/shadowvol"))
B = os.path.abspath(os.environ.get("OUT", "out/probe11"))
scenes = sorted(glob.glob(os.path.join(os.path.dirname(os.path.abspath(__file__)), "scenes", "*.json")))
for d in ("logs", "out", "rep", "repg", "repf", "repe", "repm"):
    os.makedirs(os.path.join(B, d), exist_ok=True)
only = sys.argv[1:]
log = open(B + "/runs.jsonl", "a")


def run(name, step, args):
    cmd = ["timeout", "120", EXE] + args
    t = time.time()
    p = subprocess.run(cmd, capture_output=True, text=True)
    wall = time.time() - t
    out = (p.stdout + p.stderr).strip().splitlines()
    with open("%s/logs/%s.%s.log" % (B, name, step), "w") as f:
        f.write("$ " + " ".join(cmd) + "\n" + p.stdout + "\n--- stderr\n" + p.stderr)
    rec = {"scene": name, "step": step, "cmd": " ".join("'%s'" % a if " " in a else a for a in cmd), "rc": p.returncode,
           "wall": round(wall, 2), "tail": out[-6:]}
    log.write(json.dumps(rec) + "\n"); log.flush()
    print("%-45s %-7s rc=%d %6.1fs  %s" % (name, step, p.returncode, wall, (out[-1] if out else "")[:110]), flush=True)
    return p.returncode


for i, s in enumerate(scenes):
    name = os.path.splitext(os.path.basename(s))[0]
    if only and name not in only:
        continue
    idx = int(name[:2])
    run(name, "build", ["build", "--scene", s, "--resolution", "128", "--refine", "6", "--refine-grid", "4", "--out", "%s/out/%s.ply" % (B, name)])
    if os.path.exists("%s/out/%s.ply" % (B, name)):
        run(name, "check", ["check", "%s/out/%s.ply" % (B, name)])
    rb = run(name, "explicit", ["validate", "--scene", s, "--resolution", "256", "--refine", "6", "--refine-grid", "4", "--volume", "explicit", "--report", "%s/rep/%s" % (B, name)])
    run(name, "gpu", ["validate", "--scene", s, "--resolution", "128", "--refine", "6", "--volume", "gpu", "--report", "%s/repg/%s" % (B, name)])
    if idx % 3 == 0:
        for cap, d in (("front", "repf"), ("entry", "repe")):
            run(name, cap, ["validate", "--scene", s, "--resolution", "256", "--refine", "6", "--refine-grid", "4", "--volume", "explicit", "--capture", cap, "--report", "%s/%s/%s" % (B, d, name)])
    if os.path.exists("%s/rep/%s/report.json" % (B, name)):
        run(name, "map2048", ["validate", "--scene", s, "--method", "shadowmap", "--resolution", "2048", "--report", "%s/repm/%s" % (B, name)])
