#!/usr/bin/env bash
# Self-test of the package validation tooling, without the C++ exporter: installs the pinned npm
# devDependencies when needed, writes a hand-made 3D Tiles 1.1 sample package to a temp dir,
# validates its GLBs, checks that a broken GLB is rejected, and renders the sample in headless
# Chromium. Exits non-zero on the first failure.
#
# Usage: bash tests/web/selftest.sh [--keep]   (--keep leaves the temp dir with render.png)
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
cd "$here"

bash "$here/install.sh"

tmp="$(mktemp -d)"
if [[ "${1:-}" == "--keep" ]]; then
  trap 'echo "selftest: kept $tmp"' EXIT
else
  trap 'rm -rf "$tmp"' EXIT
fi

node make-sample-tileset.mjs "$tmp/pkg"

echo "selftest: validate-glb on the sample"
node validate-glb.mjs "$tmp/pkg"

echo "selftest: validate-glb must reject a truncated GLB"
mkdir -p "$tmp/broken"
head -c -16 "$tmp/pkg/a.glb" >"$tmp/broken/a.glb"
if node validate-glb.mjs "$tmp/broken" >"$tmp/broken.log" 2>&1; then
  cat "$tmp/broken.log"
  echo "selftest: FAIL: validate-glb accepted a truncated GLB" >&2
  exit 1
fi
grep -q GLB_UNEXPECTED_END_OF_CHUNK_DATA "$tmp/broken.log"

echo "selftest: render-tileset on the sample"
node render-tileset.mjs "$tmp/pkg" "$tmp/render.png" | tee "$tmp/render.json"

# The sample must refine: root proxy plus both children loaded, the two children visible.
node -e '
  const r = JSON.parse(require("fs").readFileSync(process.argv[1], "utf8"));
  if (r.tilesLoaded !== 3 || r.stats.visible !== 2) {
    console.error(`selftest: FAIL: expected 3 tiles loaded and 2 visible, got ${r.tilesLoaded} and ${r.stats.visible}`);
    process.exit(1);
  }' "$tmp/render.json"

echo "selftest: OK"
