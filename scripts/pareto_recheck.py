#!/usr/bin/env python3
"""Re-measures a sweep's Pareto question for one method with its rivals interleaved.

A sweep measures its cells one after another, a scene's methods in a fixed order over minutes, so a
slow drift of the machine (the camera pass, the same work in every hybrid method, took 18 to 27 ms
on the bunny within one sweep on 2026-12-04) moves whole methods against each other. Errors are
deterministic; only times need re-measuring. For each scene of results.csv this script asks whether
METHOD is on the front (frame ms against error): for its resolutions, in the order of the sweep's
time ratio to the fastest cell at least as accurate, it takes that cell of METHOD and up to four
rivals (the other methods' cells at least as accurate, fastest first, those within 1.4x of the
fastest by the sweep's times) and measures them again with `shadowvol bench`, one cell per run,
ROUNDS rounds, the order rotated each round. The cell is on the front when its median over the
rounds is below every rival's median. A resolution of METHOD with no rival at least as accurate is
on the front without measuring. Two candidate resolutions at most per scene. The methods named by
--exclude are not rivals (by default the ablation keys of the snap and of the depth source: the same
method with the snap off, or its depth map always ray-cast or always from the light pass).
METHOD may name several methods, comma-separated (variants of one volume, such as its depth map from
the light pass or from rays): each scene's candidates are then the cells of any of them, and none
of them is a rival of another.

    python3 scripts/pareto_recheck.py out/sweep-snap/results.csv --out out/pareto-recheck
"""
import argparse
import csv
import os
import statistics
import subprocess
import sys


def load(path):
    rows = {}
    with open(path) as f:
        for r in csv.DictReader(f):
            rows[(r["scene"], r["method"], int(r["resolution"]))] = r
    return rows


def bench(shadowvol, scene_file, method, resolution, out, args):
    """One cell's median frame ms from a fresh bench run."""
    cmd = [shadowvol, "bench", "--scenes", scene_file, "--methods", method, "--resolutions",
           str(resolution if resolution else 64), "--size", args.size, "--repeat", str(args.repeat),
           "--warmup", "1", "--out", out]
    subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    with open(os.path.join(out, "results.csv")) as f:
        cells = list(csv.DictReader(f))
    if len(cells) != 1:
        sys.exit(f"{out}/results.csv: expected one cell, found {len(cells)}")
    return float(cells[0]["frame_ms"])


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("results")
    p.add_argument("--method", default="hybrid-refined/explicit",
                   help="the method, or several (comma-separated) whose cells are candidates and not rivals")
    p.add_argument("--rounds", type=int, default=3)
    p.add_argument("--repeat", type=int, default=5)
    p.add_argument("--size", default="640x480")
    p.add_argument("--scenes-dir", default="data/scenes")
    p.add_argument("--shadowvol", default="build/apps/shadowvol")
    p.add_argument("--out", required=True)
    p.add_argument("--exclude", default="hybrid-refined-nosnap/explicit,hybrid-refined-nosnap/gpu,"
                                        "hybrid-refined-raycast/explicit,hybrid-refined-lightpass/explicit",
                   help="methods that are not rivals (comma-separated; default: the ablation keys of the snap and "
                        "of the depth source, the same method with the snap off or its map from one source)")
    args = p.parse_args()
    rows = load(args.results)
    ms = lambda r: float(r["frame_ms"])
    err = lambda r: float(r["error"])
    label = lambda k: k[1] + (f" {k[2]}" if k[2] else "")
    scenes = list(dict.fromkeys(k[0] for k in rows))
    excluded = set(m for m in args.exclude.split(",") if m)
    methods = set(m for m in args.method.split(",") if m)
    on = []
    print(f"| scene | {args.method} | rivals at least as accurate (median ms over {args.rounds} interleaved rounds) | on the front |")
    print("|---|---|---|---|")
    for s in scenes:
        cells = [k for k in rows if k[0] == s and k[1] not in excluded]
        mine = [k for k in cells if k[1] in methods]
        if not mine:
            continue
        candidates = []
        for k in mine:
            rivals = sorted((c for c in cells if c[1] not in methods and err(rows[c]) <= err(rows[k])),
                            key=lambda c: ms(rows[c]))
            ratio = ms(rows[k]) / ms(rows[rivals[0]]) if rivals else 0.0
            candidates.append((ratio, k, rivals))
        candidates.sort(key=lambda c: (c[0], c[1][2]))
        verdict = False
        for ratio, k, rivals in candidates[:2]:
            if not rivals:
                verdict = True
                print(f"| {s} | {label(k)} ({err(rows[k]) * 100:.4f} %) | none | yes (most accurate) |", flush=True)
                break
            fastest = ms(rows[rivals[0]])
            rivals = [c for c in rivals if ms(rows[c]) <= 1.4 * fastest][:4]
            measured = {c: [] for c in [k] + rivals}
            order = [k] + rivals
            for r in range(args.rounds):
                turn = order[r % len(order):] + order[:r % len(order)]
                for c in turn:
                    # A folder per candidate, round and cell: bench resumes a folder that has the cell.
                    out = os.path.join(args.out, s, f"candidate{k[2]}", f"round{r}", c[1].replace("/", "_") + f"-{c[2]}")
                    measured[c].append(bench(args.shadowvol, os.path.join(args.scenes_dir, s + ".json"), c[1], c[2],
                                             out, args))
            med = {c: statistics.median(v) for c, v in measured.items()}
            wins = all(med[k] < med[c] for c in rivals)
            print(f"| {s} | {label(k)} ({err(rows[k]) * 100:.4f} %, {med[k]:.1f} ms) | "
                  + ", ".join(f"{label(c)} ({err(rows[c]) * 100:.4f} %, {med[c]:.1f} ms)" for c in rivals)
                  + f" | {'yes' if wins else 'no'} |", flush=True)
            if wins:
                verdict = True
                break
        on += [s] if verdict else []
    print(f"\n{args.method} on the front of {len(on)} of {len(scenes)} scenes when re-measured: {', '.join(on)}.")


if __name__ == "__main__":
    main()
