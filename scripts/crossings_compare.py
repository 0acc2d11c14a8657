#!/usr/bin/env python3
# The refined GPU volume's error against the explicit volume refined by Embree's rays, per scene,
# capture (back, front) and map size (128^2, 256^2), measured by `shadowvol validate` (the same
# misclassified fraction as the bench's error column; deterministic, no timing). Prints per cell
# the two errors and their ratio, then per capture and size the median ratio, how many cells are
# within 1.2x (issue 15's goal) and the worst. Cells where both are exactly 0 are left out.
# Usage: python3 scripts/crossings_compare.py [--crossings gpu-rays|gpu-walk] [--refine K]
#            [--shadowvol build/apps/shadowvol] [--out DIR] SCENE.json...
import argparse, json, os, statistics, subprocess, sys

ap = argparse.ArgumentParser()
ap.add_argument('--crossings', default='gpu-rays')
ap.add_argument('--refine', type=int, default=6)
ap.add_argument('--shadowvol', default='build/apps/shadowvol')
ap.add_argument('--out', default='out/crossings-compare')
ap.add_argument('scenes', nargs='+')
a = ap.parse_args()

def error(scene, capture, res, volume):
    name = os.path.splitext(os.path.basename(scene))[0]
    report = os.path.join(a.out, f'{name}-{capture}-{res}-{volume}')
    cmd = [a.shadowvol, 'validate', '--scene', scene, '--resolution', str(res), '--capture', capture,
           '--refine', str(a.refine), '--volume', volume, '--report', report]
    if volume == 'gpu': cmd += ['--crossings', a.crossings]
    subprocess.run(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)  # exit 3 (inaccurate) is a result
    with open(os.path.join(report, 'report.json')) as f:
        return 100.0 * json.load(f)['againstExact']['method']['errorFraction']

cells = {}
for scene in a.scenes:
    for capture in ('back', 'front'):
        for res in (128, 256):
            g, e = error(scene, capture, res, 'gpu'), error(scene, capture, res, 'explicit')
            cells[(os.path.basename(scene), capture, res)] = (g, e)
            print(f'{os.path.basename(scene)} {capture} {res}: gpu {g:.4f} %, explicit {e:.4f} %', flush=True)
print(f'# {a.crossings}, K = {a.refine}: gpu / explicit error')
for capture in ('back', 'front'):
    for res in (128, 256):
        v = sorted(((g / e if e > 0 else float('inf'), s, g, e) for (s, c, r), (g, e) in cells.items()
                    if c == capture and r == res and not (g == 0 and e == 0)), reverse=True)
        if not v: continue
        print(f'{capture} {res}: {len(v)} scenes, median {statistics.median(t[0] for t in v):.2f}, '
              f'within 1.2x on {sum(t[0] <= 1.2 for t in v)}, worst: ' +
              ', '.join(f'{s} {t:.2f}x ({g:.4f} vs {e:.4f} %)' for t, s, g, e in v[:3]))
