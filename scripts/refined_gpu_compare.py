#!/usr/bin/env python3
# The refined GPU volume against the refined explicit one (rays) and the unrefined GPU volume, from a
# bench results.csv with hybrid-perfect/gpu, hybrid-refined[-front]/gpu and hybrid-refined[-front]/explicit
# (README "The refined GPU volume"): error ratios per capture and map size, and frame and pass times.
# Usage: python3 scripts/refined_gpu_compare.py docs/results/refined-gpu
import csv, collections, statistics, sys
rows = list(csv.DictReader(open(sys.argv[1] + '/results.csv')))
d = collections.defaultdict(dict)
for r in rows: d[(r['scene'], r['resolution'])][r['method']] = r
def err(m, k): return float(m[k]['error']) * 100
def ms(m, k, col='frame_ms'): return float(m[k][col] or 0)
for cap, gpu, exp in (('back', 'hybrid-refined/gpu', 'hybrid-refined/explicit'),
                      ('front', 'hybrid-refined-front/gpu', 'hybrid-refined-front/explicit')):
  for res in ('128', '256'):
    v = []
    for (sc, r), m in d.items():
      if r != res or gpu not in m or exp not in m: continue
      a, b = err(m, exp), err(m, gpu)
      if a == 0 and b == 0: continue
      v.append((b / a if a > 0 else float('inf'), sc, a, b))
    v.sort(reverse=True)
    x = [t[0] for t in v]
    if not x: continue
    print(f"{cap} {res}: {len(v)} scenes, gpu/explicit error median {statistics.median(x):.2f}, "
          f"within 1.2x on {sum(t <= 1.2 for t in x)}, worst: " +
          ', '.join(f"{sc} {t:.2f}x ({a:.3f} vs {b:.3f} %)" for t, sc, a, b in v[:3]))
for res in ('128', '256'):
  for k in ('hybrid-perfect/gpu', 'hybrid-refined/gpu', 'hybrid-refined/explicit'):
    cells = [m for (sc, r), m in d.items() if r == res and k in m]
    if not cells: continue
    print(f"{res} {k}: medians over {len(cells)} scenes: frame {statistics.median(ms(m, k) for m in cells):.2f} ms, "
          + ', '.join(f"{c} {statistics.median(ms(m, k, c + '_ms') for m in cells):.2f}"
                      for c in ('light', 'resolve', 'crossings', 'volume', 'lighting')))
for sc in ('default',):
  for res in ('128', '256'):
    m = d.get((sc, res))
    if not m: continue
    u, g = ms(m, 'hybrid-perfect/gpu'), ms(m, 'hybrid-refined/gpu')
    print(f"{sc} {res}: unrefined GPU frame {u:.2f} ms, refined GPU {g:.2f} ms, ratio {g / u:.2f} "
          f"(refined: light {ms(m, 'hybrid-refined/gpu', 'light_ms'):.2f}, crossings {ms(m, 'hybrid-refined/gpu', 'crossings_ms'):.2f}, "
          f"volume {ms(m, 'hybrid-refined/gpu', 'volume_ms'):.2f}; unrefined: light {ms(m, 'hybrid-perfect/gpu', 'light_ms'):.2f}, "
          f"volume {ms(m, 'hybrid-perfect/gpu', 'volume_ms'):.2f})")
