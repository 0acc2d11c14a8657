#!/usr/bin/env python3
# Tampered copies of b2/results.csv (a finished bench) for `bench --report-only` (writes csv/NAME/results.csv)
import os, shutil
src = open('b2/results.csv').read().splitlines()
hdr, rows = src[0], src[1:]
def mk(name, lines):
    os.makedirs(f'csv/{name}', exist_ok=True); open(f'csv/{name}/results.csv', 'w').write('\n'.join(lines) + '\n')
def setf(row, idx, val):
    f = row.split(','); f[idx-1] = val; return ','.join(f)
for tok in ['nan', 'NaN', 'inf', '-inf', 'Infinity', '1e308', '1e309', '-1', '-0', '0x10', ' 5', '5 ', '1e-320', '']:
    n = tok.strip().replace('-', 'm').replace('.', '_') or 'empty'
    mk(f'frame_{n}', [hdr, setf(rows[0], 11, tok)] + rows[1:])
    mk(f'error_{n}', [hdr, setf(rows[0], 29, tok)] + rows[1:])
mk('all_error_zero', [hdr] + [setf(r, 29, '0') for r in rows])
mk('all_frame_zero', [hdr] + [setf(setf(setf(r, 11, '0'), 12, '0'), 13, '0') for r in rows])
mk('min_gt_max', [hdr, setf(setf(rows[0], 12, '200'), 13, '1')] + rows[1:])
mk('res_huge', [hdr, setf(rows[0], 6, '99999999999')] + rows[1:])
mk('res_zero', [hdr, setf(rows[0], 6, '0')] + rows[1:])
mk('pixels_zero', [hdr, setf(rows[0], 28, '0')] + rows[1:])
mk('scene_quote', [hdr, setf(rows[0], 1, '"tr,ee"')] + rows[1:])
mk('scene_html', [hdr, setf(rows[0], 1, '<script>x</script>&')] + rows[1:])
mk('many_rows', [hdr] + [setf(rows[0], 6, str(64 + i)) for i in range(200000)])
mk('many_methods', [hdr] + [setf(rows[0], 3, f'm{i}') for i in range(2000)])
mk('many_scenes', [hdr] + [setf(rows[0], 1, f's{i}') for i in range(3000)])
mk('dup_rows', [hdr] + rows + rows)
mk('only_header', [hdr])
mk('extra_col', [hdr, rows[0] + ',5'] + rows[1:])
mk('crlf', [hdr + '\r'] + [r + '\r' for r in rows])
