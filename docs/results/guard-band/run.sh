#!/bin/bash
# The volume map's guard band (light.h, kVolumeGuardTexels; README "Volume mesh"): two scenes whose
# given light window cuts a shadow, every volume at 64² and 256², `validate` at its defaults.
# Prints scene, resolution, variant, missed and false pixels against the exact shadows, the
# *border* errors and the verdict. Run from the repository root after building (about 25 s on a
# 2-core machine); EXE (default build/apps/shadowvol) runs another binary, e.g. one of commit
# 1466bae, before the band, for before.txt (README.md here). OUT (default out/guard-band).
set -e
exe=${EXE:-build/apps/shadowvol}
out=${OUT:-out/guard-band}
mkdir -p "$out"
for s in docs/results/probe20/scenes/dir_window_inside_plate.json docs/results/guard-band/scenes/*.json; do
  for r in 64 256; do
    for v in "--volume explicit" "--volume explicit --blur" "--volume explicit --refine 6" \
             "--volume explicit --refine 6 --refine-grid 4" "--volume gpu" "--volume gpu --refine 6"; do
      "$exe" validate --scene "$s" --resolution "$r" $v --report "$out/r" --json > "$out/v.json" 2>/dev/null || true
      python3 - "$out/v.json" "$(basename "$s" .json)" "$r" "$v" <<'PY'
import json, sys
j = json.load(open(sys.argv[1]))
m = j["againstExact"]["method"]
print(f"{sys.argv[2]} {sys.argv[3]} [{sys.argv[4]}]: missed {m['missedShadow']}, false {m['falseShadow']}, "
      f"border {j['errorCauses']['border']}, {'PASSED' if j['passed'] else 'FAILED'}")
PY
    done
  done
done
