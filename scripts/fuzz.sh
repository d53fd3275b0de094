#!/usr/bin/env bash
# Builds the libFuzzer targets (clang-14, ASan + UBSan; fuzz/CMakeLists.txt) and runs them.
# Usage: scripts/fuzz.sh [TARGET|all] [SECONDS]     (default: all, 60 seconds per target)
#   TARGET: gltf scene camera_path project proxy_cache package
# Each run starts from a working corpus in $BUILD/corpus/TARGET seeded with fuzz/seeds/TARGET
# (checked in: packages, projects, glTF from the tests), fuzz/regressions/TARGET, the seeds
# fuzz/make_seeds.cpp generates, and (gltf) the small glTF/GLB files of ../shared/data; the
# corpus grows across runs. A finding is written to $BUILD/artifacts/TARGET/ and makes the script exit 1:
# fix it, then check the input in under fuzz/regressions/TARGET/ (FuzzRegressionTest replays it).
# Builds in build-fuzz-all (the whole pipeline, sanitized: the project target needs the graph
# and every step). Environment: HLOD_FUZZ_BUILD_DIR (another build folder), HLOD_FUZZ_NO_BUILD=1
# (use it as is: ctest of scripts/sanitize.sh's CI build, which has all targets but project),
# HLOD_FUZZ_JOBS (parallel workers, 1), HLOD_FUZZ_LOG (append the summary lines to this file).
set -euo pipefail
cd "$(dirname "$0")/.."
ROOT=$(pwd)
TARGETS=(gltf scene camera_path project proxy_cache package)
WHICH=${1:-all}
SECONDS_PER_TARGET=${2:-60}
export HLOD_FUZZ_ALL=1
BUILD=${HLOD_FUZZ_BUILD_DIR:-build-fuzz-all}
export HLOD_FUZZ_BUILD_DIR=$BUILD
DATA=${HLOD_TEST_DATA_DIR:-$(cd .. && pwd)/shared/data}

if [ "$WHICH" != all ] && [[ ! " ${TARGETS[*]} " =~ " $WHICH " ]]; then
  echo "fuzz.sh: unknown target '$WHICH' (one of: ${TARGETS[*]} all)" >&2
  exit 2
fi
[ "$WHICH" = all ] && RUN=("${TARGETS[@]}") || RUN=("$WHICH")

[ -n "${HLOD_FUZZ_NO_BUILD:-}" ] || scripts/sanitize.sh --build-only make_seeds "${RUN[@]/#/fuzz_}"
ASAN_OPTIONS=detect_leaks=0 "$BUILD/fuzz/make_seeds" "$BUILD/generated-seeds"

max_len_for() {
  case "$1" in
    package) echo 262144 ;; # whole folders: the AS1 seed is ~70 KB
    gltf) echo 131072 ;;
    *) echo 65536 ;;
  esac
}

dict_for() {
  case "$1" in
    gltf) echo fuzz/dicts/gltf.dict ;;
    package) echo fuzz/dicts/package.dict ;;
    camera_path | project) echo fuzz/dicts/json.dict ;;
    *) echo "" ;;
  esac
}

seed() {
  local t=$1 corpus=$BUILD/corpus/$1
  mkdir -p "$corpus"
  for d in fuzz/seeds/$t fuzz/regressions/$t "$BUILD/generated-seeds/$t"; do
    [ -d "$d" ] && find "$d" -maxdepth 1 -type f ! -name '*.md' -exec cp -n {} "$corpus"/ \;
  done
  if [ "$t" = gltf ] && [ -d "$DATA/robustness" ]; then
    # Small real files only: libFuzzer mutates inputs up to -max_len bytes.
    find "$DATA/robustness" -type f \( -iname '*.gltf' -o -iname '*.glb' \) -size -64k \
      -exec sh -c 'cp -n "$1" "$2/data-$(basename "$(dirname "$1")")-$(basename "$1")"' _ {} "$corpus" \;
  fi
  return 0
}

status=0
for t in "${RUN[@]}"; do
  seed "$t"
  mkdir -p "$BUILD/artifacts/$t"
  dict=$(dict_for "$t")
  args=("$BUILD/corpus/$t" -max_total_time="$SECONDS_PER_TARGET" -timeout=20 -rss_limit_mb=2560
        -malloc_limit_mb=2048 -max_len="$(max_len_for "$t")" -print_final_stats=1 -close_fd_mask=1
        -artifact_prefix="$BUILD/artifacts/$t/")
  [ -n "$dict" ] && args+=(-dict="$dict")
  jobs=${HLOD_FUZZ_JOBS:-1}
  [ "$jobs" -gt 1 ] && args+=(-fork="$jobs" -ignore_crashes=0)
  log=$BUILD/fuzz-$t.log
  echo "fuzz.sh: $t for ${SECONDS_PER_TARGET}s (log: $log)" >&2
  set +e
  started=$(date +%s)
  HLOD_FUZZ_TMP=$BUILD/tmp ASAN_OPTIONS=detect_leaks=0:abort_on_error=1 \
    UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
    "$BUILD/fuzz/fuzz_$t" "${args[@]}" >"$log" 2>&1
  rc=$?
  elapsed=$(($(date +%s) - started))
  set -e
  execs=$(grep -a -o 'stat::number_of_executed_units: *[0-9]*' "$log" | grep -o '[0-9]*$' | tail -1 || true)
  cov=$(grep -a -o 'cov: [0-9]*' "$log" | tail -1 | grep -o '[0-9]*' || true)
  ft=$(grep -a -o 'ft: [0-9]*' "$log" | tail -1 | grep -o '[0-9]*' || true)
  corpus=$(find "$BUILD/corpus/$t" -type f | wc -l)
  line="$t: ${elapsed}s, ${execs:-?} executions, coverage ${cov:-?} edges / ${ft:-?} features, corpus $corpus, exit $rc"
  echo "fuzz.sh: $line" >&2
  [ -n "${HLOD_FUZZ_LOG:-}" ] && echo "$line" >>"$HLOD_FUZZ_LOG"
  if [ $rc -ne 0 ]; then
    echo "fuzz.sh: $t found a problem; input in $BUILD/artifacts/$t/, last lines of the log:" >&2
    grep -a -E 'ERROR|SUMMARY|exception|inconsistent|Test unit written' "$log" | head -20 >&2 || true
    status=1
  fi
done
exit $status
