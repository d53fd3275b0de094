#!/usr/bin/env bash
# Package size benchmark (issue 18): builds the package of every shared scene and of the engine
# tiled 105 times (scripts/make-tiled-scene.py) with the given `hlod` binary at its defaults
# (no proxy cache, no DLOD row, 2 threads) and prints, per scene, the package's bytes on disk
# (allocated blocks: st_blocks x 512 summed over its files, what `du` counts), its file count,
# the source's bytes on disk (scene file plus the files it references, as `hlod build --json`
# of a binary that reports it gives them) and their ratio.
#
# Usage: scripts/measure-packages.sh HLOD OUTDIR [hlod build flags...]
#   e.g. scripts/measure-packages.sh build/app/hlod /tmp/pkgs
#        scripts/measure-packages.sh build/app/hlod /tmp/plain --compression none
# A binary older than issue 18 has no source figure: pass SOURCE_FROM=NEWER_HLOD to take the
# source's bytes from another binary's report.
set -euo pipefail
hlod=$(realpath "$1")
out=$2
shift 2
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
data="${HLOD_TEST_DATA_DIR:-$here/../../shared/data}/scenes"
mkdir -p "$out"
tiled="$out/engine-x105.glb"
[[ -f "$tiled" ]] || python3 "$here/make-tiled-scene.py" \
    "$data/engine-2cylinder/2CylinderEngine.glb" "$tiled" 105 >/dev/null
declare -a names=(as1-assembly cg57-cruiser engine-2cylinder godot-room occt-kitchen torcs-spring
                  engine-x105)
declare -A args=(
    [as1-assembly]="$data/as1-assembly"
    [cg57-cruiser]="$data/cg57-cruiser/CG-57.ac"
    [engine-2cylinder]="$data/engine-2cylinder/2CylinderEngine.glb"
    [godot-room]="$data/godot-room/room.glb"
    [occt-kitchen]="$data/occt-kitchen --brep-unit 0.01"
    [torcs-spring]="$data/torcs-spring/spring.acc"
    [engine-x105]="$tiled")
printf "%-18s %14s %7s %14s %8s\n" scene "package (B)" files "source (B)" ratio
for n in "${names[@]}"; do
    pkg="$out/$n"
    # shellcheck disable=SC2086
    "$hlod" build ${args[$n]} -o "$pkg" --no-cache --no-dlod --threads 2 --json "$@" \
        >"$out/$n.json" 2>"$out/$n.err"
    bytes=$(find "$pkg" -type f -printf "%b\n" | awk '{s += $1} END {printf "%d", s * 512}')
    files=$(find "$pkg" -type f | wc -l)
    src_json="$out/$n.json"
    if [[ -n "${SOURCE_FROM:-}" ]]; then
        # shellcheck disable=SC2086
        "$SOURCE_FROM" build ${args[$n]} -o "$out/.src-$n" --no-cache --no-dlod --threads 2 \
            --json >"$out/$n.src.json" 2>/dev/null
        rm -rf "$out/.src-$n"
        src_json="$out/$n.src.json"
    fi
    source=$(python3 -c "import json,sys; print(json.load(open(sys.argv[1])).get('source', {}).get('bytes_on_disk', ''))" "$src_json" 2>/dev/null || true)
    ratio=""
    [[ -n "$source" ]] && ratio=$(python3 -c "print(f'{$bytes / $source:.2f}x')")
    printf "%-18s %14d %7d %14s %8s\n" "$n" "$bytes" "$files" "$source" "$ratio"
done
