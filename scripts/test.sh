#!/usr/bin/env bash
# Sets up, builds everything (library, CLI, tests, benchmarks) and runs the whole test suite.
# GL tests run headless on whatever EGL offers (Mesa's llvmpipe on machines without a GPU).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
bash scripts/fetch_meshes.sh
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build
ctest --test-dir build --output-on-failure --timeout 600
