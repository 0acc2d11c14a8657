#!/usr/bin/env python3
# Walk against rays: the error of hybrid-refined-walk[-front]/explicit over hybrid-refined[-front]/explicit
# per scene and resolution, from a bench results.csv with those methods (README "Silhouette refinement",
# "Crossings from the GPU's walk"). Usage: python3 scripts/walk_compare.py docs/results/walk
import csv,collections,math,statistics,sys
rows=list(csv.DictReader(open(sys.argv[1]+'/results.csv')))
d=collections.defaultdict(dict)
for r in rows: d[(r['scene'],r['resolution'])][r['method']]=r
M=['hybrid-perfect/explicit','hybrid-refined/explicit','hybrid-refined-walk/explicit','hybrid-refined-front/explicit','hybrid-refined-walk-front/explicit']
def e(m,k): return float(m[k]['error'])*100
res={}
worst=collections.defaultdict(list)
for cap,(a,b) in (('back',(1,2)),('front',(3,4))):
  for rs in ('128','256'):
    v=[]
    for (sc,r),m in d.items():
      if r!=rs: continue
      ra,wa=e(m,M[a]),e(m,M[b])
      if ra==0 and wa==0: continue
      x=wa/ra if ra>0 else float('inf'); v.append(x); worst[(cap,rs)].append((x,sc,ra,wa))
    print(f"{cap} {rs}: {len(v)} scenes, walk/rays error median {statistics.median(v):.2f}, within 1.2x on {sum(x<=1.2 for x in v)}, max {max(v):.2f}")
for k,v in worst.items():
  v.sort(reverse=True); print(k, ', '.join(f"{sc} {x:.2f}x ({ra:.3f} vs {wa:.3f} %)" for x,sc,ra,wa in v[:4]))
# Median pass times over the scenes (ms), rays against walk, back capture: the figures README quotes.
for res in ('128', '256'):
  for col in ('frame_ms', 'light_ms', 'build_ms'):
    pairs = [(float(m[M[1]][col]), float(m[M[2]][col])) for (sc, r), m in d.items() if r == res]
    print('%s %s back: rays median %.2f, walk median %.2f' % (col, res, statistics.median([a for a, b in pairs]),
                                                              statistics.median([b for a, b in pairs])))
