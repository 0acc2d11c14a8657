#!/usr/bin/env python3
"""Compares two refine_eval results.jsonl files (docs/results/exit-choice/run.sh): each run whose
wrong pixels (missed/false) changed, with whether it meets the 128² goal (at most the 2048² auto
map's error, docs/results/sharp-reference) before and after; then the totals.
Usage: python3 compare.py BASE.jsonl NEW.jsonl"""
import json
import sys


def load(path):
    return {(r["scene"], r["method"]): r for r in map(json.loads, open(path))}


base, new = load(sys.argv[1]), load(sys.argv[2])
maps = {r["scene"]: r["error"] for r in map(json.loads, open("docs/results/sharp-reference/results.jsonl"))
        if r["method"] == "shadowmap auto 2048"}
wrong = [0, 0]
meets = [0, 0]
for key in sorted(base):
    b, n = base[key], new[key]
    if b.get("error") is None or n.get("error") is None:
        print(key, "refused")
        continue
    wb, wn = b["missed"] + b["false"], n["missed"] + n["false"]
    wrong[0] += wb
    wrong[1] += wn
    goal = ""
    if key[1].endswith("128") and key[0] in maps:
        ok = [b["error"] <= maps[key[0]], n["error"] <= maps[key[0]]]
        meets[0] += ok[0]
        meets[1] += ok[1]
        goal = " 128² goal: %s -> %s" % tuple("met" if x else "missed" for x in ok)
    if wb != wn:
        print("%s %s: %d/%d -> %d/%d%s" % (key[0], key[1], b["missed"], b["false"], n["missed"], n["false"], goal))
print("wrong pixels over %d runs: %d -> %d; 128² goal met on %d -> %d scenes" % (len(base), wrong[0], wrong[1], meets[0], meets[1]))
