#!/usr/bin/env bash
# Configures (once) and builds HLOD Studio into ./build with Ninja and ccache.
# Usage: scripts/build.sh [extra cmake --build args]
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD_DIR=${HLOD_BUILD_DIR:-build}
if [ ! -f "$BUILD_DIR/build.ninja" ]; then
  cmake -S . -B "$BUILD_DIR" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
        -DHLOD_TEST_DATA_DIR="$(cd .. && pwd)/shared/data" >/dev/null
fi
cmake --build "$BUILD_DIR" -j "$(nproc)" "$@"
