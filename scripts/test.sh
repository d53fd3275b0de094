#!/usr/bin/env bash
# The README's test command: installs what is missing, builds, and runs every test (the GUI
# tests under a virtual X server), then the hardening build (scripts/sanitize.sh: sanitized
# reader tests and a short run of every fuzz target; skipped with arguments for ctest or
# HLOD_SKIP_SANITIZE=1). Exit code 0 only when all tests pass.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
scripts/build.sh
# npm packages of the package validation tests (Khronos glTF validator, 3D Tiles runtime).
bash tests/web/install.sh
BUILD_DIR=${HLOD_BUILD_DIR:-build}
# Qt's OpenGL widgets need a real X server: Xvfb with Mesa's software rasteriser.
export LIBGL_ALWAYS_SOFTWARE=1
status=0
xvfb-run -a -s "-screen 0 1280x1024x24" \
  ctest --test-dir "$BUILD_DIR" --output-on-failure -j "$(nproc)" --timeout 900 "$@" || status=$?
if [ $# -eq 0 ] && [ -z "${HLOD_SKIP_SANITIZE:-}" ]; then
  scripts/sanitize.sh || status=1
fi
exit $status
