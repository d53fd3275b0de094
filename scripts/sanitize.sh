#!/usr/bin/env bash
# The hardening build (issue 22): clang-14 with AddressSanitizer + UndefinedBehaviorSanitizer
# over the readers' share of the pipeline (fuzz/ReaderSources.cmake), the libFuzzer targets and
# the sanitized reader tests, in $HLOD_FUZZ_BUILD_DIR (default build-fuzz, ccache reused).
# Usage: scripts/sanitize.sh                 build, then run the sanitized tests and every fuzz
#                                           target for $HLOD_FUZZ_CI_SECONDS (default 8) each:
#                                           what CI runs (scripts/test.sh)
#        scripts/sanitize.sh --build-only [NINJA TARGETS...]
set -euo pipefail
cd "$(dirname "$0")/.."
# HLOD_FUZZ_ALL=1: the whole pipeline (for the project fuzz target), default folder
# build-fuzz-all; scripts/fuzz.sh sets it.
if [ -n "${HLOD_FUZZ_ALL:-}" ]; then
  BUILD=${HLOD_FUZZ_BUILD_DIR:-build-fuzz-all}
  ALL=ON
else
  BUILD=${HLOD_FUZZ_BUILD_DIR:-build-fuzz}
  ALL=OFF
fi
DATA=${HLOD_TEST_DATA_DIR:-$(cd .. && pwd)/shared/data}

for tool in clang++-14 clang-14; do
  if ! command -v $tool >/dev/null; then
    echo "sanitize.sh: $tool is missing (scripts/install-deps.sh installs clang-14)" >&2
    exit 1
  fi
done
if [ ! -f "$BUILD/build.ninja" ]; then
  cmake -S . -B "$BUILD" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
        -DCMAKE_C_COMPILER=clang-14 -DCMAKE_CXX_COMPILER=clang++-14 \
        -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -gline-tables-only" \
        -DCMAKE_C_FLAGS_RELWITHDEBINFO="-O1" \
        -DHLOD_FUZZ=ON -DHLOD_FUZZ_ALL_SOURCES=$ALL -DHLOD_TEST_DATA_DIR="$DATA" >/dev/null
fi
if [ "${1:-}" = --build-only ]; then
  shift
  cmake --build "$BUILD" -j "$(nproc)" ${1:+--target "$@"}
  exit 0
fi
cmake --build "$BUILD" -j "$(nproc)"
ASAN_OPTIONS=detect_leaks=0 ctest --test-dir "$BUILD" --output-on-failure -j "$(nproc)" \
  --timeout 600
