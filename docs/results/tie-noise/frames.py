#!/usr/bin/env python3
"""Driver of run.sh (docs/results/tie-noise): jittered frames of each closed-mesh scene, the
silhouette volume and the refined volume validated in each, a table of wrong pixels per frame.

  python3 frames.py EXE OUT "FLAGS" SCENE.json ...

A scene counts when scripts/closed_scenes.py calls it closed (every mesh a closed 2-manifold),
judged on its unmoved frame's silhouette run, as docs/results/error-places/run.sh does. Stdlib only.
"""
import concurrent.futures
import json
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
FRAMES = 5


def validate(exe, scene, report, options):
    if os.path.exists(report):
        return
    run = subprocess.run([exe, "validate", "--scene", scene, "--report", report + ".d", "--json", *options],
                         capture_output=True, text=True)
    subprocess.run(["rm", "-rf", report + ".d"])
    if run.stdout:
        with open(report + ".tmp", "w") as f:
            f.write(run.stdout)
        os.replace(report + ".tmp", report)
    else:
        sys.stderr.write(f"{scene}: no report ({run.stderr.strip()[:200]})\n")


def wrong(report):
    try:
        m = json.load(open(report))["againstExact"]["method"]
    except (OSError, ValueError, KeyError):
        return None
    return m["missedShadow"] + m["falseShadow"], m["errorFraction"]


def run_all(exe, jobs):
    with concurrent.futures.ThreadPoolExecutor(2) as pool:
        for f in [pool.submit(validate, exe, *job) for job in jobs]:
            f.result()


def main():
    exe, out, flags, scenes = sys.argv[1], sys.argv[2], sys.argv[3].split(), sys.argv[4:]
    os.makedirs(f"{out}/scenes", exist_ok=True)
    names = {}
    for s in scenes:
        n = os.path.basename(s)[:-len(".json")]
        names[n] = s
        subprocess.run([sys.executable, f"{HERE}/jitter.py", s, f"{out}/scenes"], check=True, capture_output=True)
    run_all(exe, [(f"{out}/scenes/{n}-j{k}.json", f"{out}/{n}-j{k}-silhouette.json", ["--method", "silhouette"])
                  for n in names for k in range(FRAMES)])
    with open(f"{out}/silhouette.jsonl", "w") as f:
        for n in names:
            w = wrong(f"{out}/{n}-j0-silhouette.json")
            if w:
                f.write(json.dumps({"scene": n, "method": "silhouette", "error": w[1]}) + "\n")
    closed = subprocess.run([sys.executable, f"{HERE}/../../../scripts/closed_scenes.py", exe,
                             f"{out}/silhouette.jsonl", *scenes], capture_output=True, text=True, check=True)
    closed = [n for n in closed.stdout.strip().split(",") if n]
    run_all(exe, [(f"{out}/scenes/{n}-j{k}.json", f"{out}/{n}-j{k}-refined.json", flags)
                  for n in closed for k in range(FRAMES)])
    print("| scene | silhouette, per frame | refined, per frame | silhouette sum | refined sum | frames within 1.5x | sum within 1.5x |")
    print("|---|---|---|---:|---:|---:|---|")
    totals = {"scenes": 0, "frames": 0, "framesOk": 0, "sumOk": 0, "sil": 0, "ref": 0, "firstOk": 0}
    for n in closed:
        s = [wrong(f"{out}/{n}-j{k}-silhouette.json") for k in range(FRAMES)]
        r = [wrong(f"{out}/{n}-j{k}-refined.json") for k in range(FRAMES)]
        if None in s or None in r:
            print(f"| {n} | missing report | | | | | |")
            continue
        ok = [rk[1] <= 1.5 * sk[1] for sk, rk in zip(s, r)]
        ss, rs = sum(x[0] for x in s), sum(x[0] for x in r)
        sum_ok = rs <= 1.5 * ss
        totals["scenes"] += 1
        totals["frames"] += FRAMES
        totals["framesOk"] += sum(ok)
        totals["sumOk"] += sum_ok
        totals["firstOk"] += ok[0]
        totals["sil"] += ss
        totals["ref"] += rs
        print(f"| {n} | {' '.join(str(x[0]) for x in s)} | {' '.join(str(x[0]) for x in r)} | {ss} | {rs} | "
              f"{sum(ok)} of {FRAMES} | {'yes' if sum_ok else 'no'} |")
    t = totals
    print(f"\n{t['scenes']} scenes: the unmoved frame within 1.5x on {t['firstOk']}; {t['framesOk']} of {t['frames']} "
          f"frames within 1.5x; the five frames' sum within 1.5x on {t['sumOk']} of {t['scenes']}; "
          f"wrong pixels over all frames: silhouette {t['sil']}, refined {t['ref']}")


if __name__ == "__main__":
    main()
