#!/usr/bin/env bash
# The GL checks for a machine with a real GPU (or any other EGL driver): the GL context it gets,
# the default scene rendered and validated with every GPU volume, the GL test executables, the
# refined GPU frame's cost ratio (scripts/refined_gpu_ratio.sh) and a short `shadowvol bench`.
# Each step has its own time limit and the run goes on past a failing step; the summary at the
# end names each step's exit status. Everything lands in OUT_DIR (logs, gtest XML, images,
# bench/results.csv and bench/report.md).
#
# Usage: bash scripts/gpu_check.sh [BIN_DIR] [OUT_DIR]
#   BIN_DIR  holds shadowvol, tests_gl, tests_validate and tests_bench (default: the build tree,
#            build/apps and build/tests); the tests find data/ through the source folder they
#            were built in (SV_SOURCE_DIR), so run them from that checkout or a link to it.
#   OUT_DIR  default out/gpu-check
# Environment: GPU_CHECK_BENCH_SCENES, GPU_CHECK_BENCH_RES, GPU_CHECK_PAIRS override the bench's
# scenes, resolutions and the number of frame pairs for the cost ratio.
set -u
cd "$(dirname "$0")/.."
BIN=${1:-}
OUT=${2:-out/gpu-check}
mkdir -p "$OUT"
if [ -n "$BIN" ]; then
  SV=$BIN/shadowvol; TESTS=$BIN
else
  SV=build/apps/shadowvol; TESTS=build/tests
fi
SUMMARY=$OUT/summary.txt
: >"$SUMMARY"

# step NAME SECONDS COMMAND...: runs COMMAND with a limit, its output in OUT/NAME.log.
step() {
  local name=$1 limit=$2
  shift 2
  local t0=$SECONDS
  timeout --kill-after=10 "$limit" "$@" >"$OUT/$name.log" 2>&1
  local rc=$?
  printf '%-22s rc %3d  %4d s\n' "$name" "$rc" "$((SECONDS - t0))" | tee -a "$SUMMARY"
  return 0
}

scene=data/scenes/default.json
step context 60 "$SV" -v render --scene "$scene" --resolution 256 --frames 21 --out "$OUT/default.png" \
  --stencil "$OUT/default-stencil.png"
for v in "gpu" "gpu --refine 6" "gpu --refine 6 --crossings gpu-walk" "explicit --refine 6" "gpu --count zfail"; do
  tag=validate-$(echo "$v" | tr ' ' '_' | tr -d '-')
  # shellcheck disable=SC2086
  step "$tag" 120 "$SV" validate --scene "$scene" --resolution 256 --volume $v --report "$OUT/$tag"
done
step tests_gl 300 "$TESTS/tests_gl" --gtest_output="xml:$OUT/tests_gl.xml"
step refined_ratio 240 bash scripts/refined_gpu_ratio.sh "${GPU_CHECK_PAIRS:-7}" "$SV"
step refined_walk_ratio 240 bash scripts/refined_gpu_ratio.sh "${GPU_CHECK_PAIRS:-7}" "$SV" "--refine 4 --crossings gpu-walk"
# shellcheck disable=SC2086
step bench 300 "$SV" bench \
  --scenes ${GPU_CHECK_BENCH_SCENES:-default data/scenes/bunny.json data/scenes/armadillo.json data/scenes/fandisk.json data/scenes/hemisphere-grazing.json} \
  --methods shadowmap hybrid-perfect/gpu hybrid-refined/gpu hybrid-refined-front/gpu hybrid-refined-walk/gpu hybrid-refined/explicit silhouette \
  --resolutions ${GPU_CHECK_BENCH_RES:-128 256 512 1024 2048} --size 640x480 --repeat 5 --warmup 1 --out "$OUT/bench"
step tests_validate 300 "$TESTS/tests_validate" --gtest_output="xml:$OUT/tests_validate.xml"
step tests_bench 240 "$TESTS/tests_bench" --gtest_output="xml:$OUT/tests_bench.xml"
echo "gpu_check: done; summary in $SUMMARY"
