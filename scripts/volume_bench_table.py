#!/usr/bin/env python3
"""Markdown table of a bench_volume_builder JSON run (--benchmark_format=json, with
--benchmark_repetitions): per benchmark the median over the repetitions of build ms, floor ms and
their ratio (each repetition's ratio is build / floor measured in the same iterations)."""
import collections
import json
import statistics
import sys


def main(path):
    runs = collections.defaultdict(list)
    for b in json.load(open(path))["benchmarks"]:
        # BM_BuildVolume only (BM_RefineVolume has no floor; README "Silhouette refinement").
        if b.get("run_type") == "iteration" and b["run_name"].startswith("BM_BuildVolume/"):
            runs[b["run_name"]].append(b)
    print("| map | res | triangulation | blur | buffers | build ms | floor ms | ratio | MB | triangles | cap before -> after | flipped |")
    print("|---|---:|---|---|---|---:|---:|---:|---:|---:|---:|---:|")
    for name, bs in runs.items():
        args = dict(part.split(":") for part in name.split("/")[1:] if ":" in part)
        med = lambda key: statistics.median(b[key] for b in bs)
        b0 = bs[0]
        print("| %s | %s^2 | %s | %s | %s | %.2f | %.2f | %.2f | %.1f | %d | %d -> %d | %.1f %% |" % (
            "back" if args["back"] == "1" else "front", args["res"],
            "perfect" if args["perfect"] == "1" else "fixed", "on" if args["blur"] == "1" else "off",
            "reused" if args.get("reuse") == "1" else "fresh", med("build_ms"), med("floor_ms"), med("ratio"),
            b0["MB"], b0["tris"], b0["cap_before"], b0["cap_after"], 100.0 * b0["flipped"]))
    print("\n%d benchmarks, %d repetitions each (median shown)" % (len(runs), min(len(b) for b in runs.values())))


if __name__ == "__main__":
    main(sys.argv[1])
