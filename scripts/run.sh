#!/usr/bin/env bash
# The README's main command: installs what is missing, builds, and opens the editor on the
# embedded sample scene (or on the files given). Without a display it says how to use the CLI.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
scripts/build.sh
BUILD_DIR=${HLOD_BUILD_DIR:-build}
if [ -z "${DISPLAY:-}" ] && [ -z "${WAYLAND_DISPLAY:-}" ]; then
  cat <<MSG
hlod-studio needs a display, and none is set (DISPLAY/WAYLAND_DISPLAY are empty).
Use the command-line tool instead, for example:
  $BUILD_DIR/app/hlod info                       # the embedded sample scene
  $BUILD_DIR/app/hlod info ../shared/data/scenes/godot-room/room.glb
  $BUILD_DIR/app/hlod cluster --volume aabb --k 1 --json
  $BUILD_DIR/app/hlod --help
or run the editor on a virtual display:
  xvfb-run -a -s "-screen 0 1280x1024x24" $BUILD_DIR/app/hlod-studio --screenshot studio.png
MSG
  exec "$BUILD_DIR/app/hlod" info
fi
exec "$BUILD_DIR/app/hlod-studio" "$@"
