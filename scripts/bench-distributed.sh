#!/usr/bin/env bash
# Distributed bake benchmark (docs/benchmarks.md, "Distributed bake on a farm"): the engine
# sample tiled 100 times (scripts/make-tiled-scene.py), built once unsharded and then, for each
# shard count N, as `hlod plan` + the N `hlod build --shard I/N` + the final `hlod build`, each
# with a fresh cache folder. Every process runs under /usr/bin/time (wall, user + system CPU,
# peak resident memory); the final package must be byte-identical to the unsharded one
# (diff -r). Writes OUT/summary.md and prints it.
#
# Usage: scripts/bench-distributed.sh [HLOD] [OUT] [SHARDS...]
#        (defaults: build/app/hlod, /tmp/hlod-bench-distributed, 4 8)
# Environment: HLOD_BENCH_CONCURRENT="4 ..." also runs these shard counts with all shards at
# once (as on a farm: shards that need the same proxy share it through the cache's claims;
# on a small machine their wall times mean little, their CPU times what each machine does);
# HLOD_BENCH_KEEP=1 keeps the runs already in OUT (unsharded, and each shard count and mode)
# instead of running them again, and only adds the missing ones to the summary.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
hlod="$(realpath "${1:-$here/../build/app/hlod}")"
out="${2:-/tmp/hlod-bench-distributed}"
shift $(($# > 2 ? 2 : $#))
shards=("$@")
[[ ${#shards[@]} -gt 0 ]] || shards=(4 8)
read -r -a concurrent <<<"${HLOD_BENCH_CONCURRENT:-}"
data="$here/../../shared/data/scenes"
mkdir -p "$out"
tiled="$out/engine-x100.glb"
[[ -f "$tiled" ]] || python3 "$here/make-tiled-scene.py" \
    "$data/engine-2cylinder/2CylinderEngine.glb" "$tiled" 100 >/dev/null

# measure NAME CMD...: runs CMD, keeps its stdout/stderr and "wall user sys peak_kb" in OUT/NAME.*
measure() {
    local name="$1"
    shift
    /usr/bin/time -f "%e %U %S %M" -o "$out/$name.time" "$@" >"$out/$name.out" 2>"$out/$name.err"
}

# sharded TAG N sequential|concurrent
sharded() {
    local tag="$1" n="$2" mode="$3" i
    if [[ "${HLOD_BENCH_KEEP:-0}" == 1 && -f "$out/identical-$tag" && -f "$out/run-$tag" ]]; then
        return
    fi
    echo "$n shards, $mode ..." >&2
    rm -rf "$out/cache-$tag" "$out/pkg-$tag"
    measure "plan-$tag" "$hlod" plan "$tiled" --shards "$n" --cache "$out/cache-$tag"
    for ((i = 0; i < n; i++)); do
        if [[ $mode == concurrent ]]; then
            measure "shard-$tag-$i" "$hlod" build --shard "$i/$n" --cache "$out/cache-$tag" &
        else
            measure "shard-$tag-$i" "$hlod" build --shard "$i/$n" --cache "$out/cache-$tag"
        fi
    done
    wait
    measure "final-$tag" "$hlod" build "$tiled" -o "$out/pkg-$tag" --cache "$out/cache-$tag"
    if diff -r "$out/pkg-1" "$out/pkg-$tag" >/dev/null; then
        echo identical >"$out/identical-$tag"
    else
        echo DIFFERENT >"$out/identical-$tag"
    fi
    echo "$n $mode" >"$out/run-$tag"
}

if [[ "${HLOD_BENCH_KEEP:-0}" != 1 || ! -f "$out/single.time" ]]; then
    echo "unsharded build ..." >&2
    rm -rf "$out/cache-1" "$out/pkg-1"
    measure single "$hlod" build "$tiled" -o "$out/pkg-1" --cache "$out/cache-1"
fi
tags=()
for n in "${shards[@]}"; do
    sharded "$n" "$n" sequential
    tags+=("$n")
done
for n in "${concurrent[@]}"; do
    sharded "c$n" "$n" concurrent
    tags+=("c$n")
done

python3 - "$out" "${tags[@]}" <<'PY' | tee "$out/summary.md"
import sys
out, tags = sys.argv[1], sys.argv[2:]
def t(name):
    wall, user, sys_, kb = open(f"{out}/{name}.time").read().split()[-4:]
    return float(wall), float(user) + float(sys_), int(kb) / 1024.0
single = t("single")
print(f"unsharded build: {single[0]:.0f} s wall, {single[1]:.0f} s CPU, peak {single[2]:.0f} MB\n")
print("| shards | plan CPU s | shards CPU s (sum) | largest shard CPU s | peak MB per shard (max) "
      "| final CPU s (wall s) | total CPU / unsharded | Amdahl speed-up, N machines | "
      "with the largest shard | package |")
print("|---|---|---|---|---|---|---|---|---|---|")
for tag in tags:
    n, mode = open(f"{out}/run-{tag}").read().split()
    n = int(n)
    plan, final = t(f"plan-{tag}"), t(f"final-{tag}")
    sh = [t(f"shard-{tag}-{i}") for i in range(n)]
    serial, parallel = plan[1] + final[1], sum(s[1] for s in sh)
    total = serial + parallel
    amdahl = single[1] / (serial + parallel / n)
    measured = single[1] / (serial + max(s[1] for s in sh))
    ident = open(f"{out}/identical-{tag}").read().strip()
    print(f"| {n} ({mode}) | {plan[1]:.1f} | {parallel:.0f} | {max(s[1] for s in sh):.0f} | "
          f"{max(s[2] for s in sh):.0f} | {final[1]:.1f} ({final[0]:.0f}) | "
          f"{total / single[1]:.3f} | {amdahl:.2f} (serial {serial / total:.1%}) | "
          f"{measured:.2f} | {ident} |")
print()
for tag in tags:
    n, mode = open(f"{out}/run-{tag}").read().split()
    row = ", ".join(f"{t(f'shard-{tag}-{i}')[1]:.0f} s / {t(f'shard-{tag}-{i}')[2]:.0f} MB"
                    for i in range(int(n)))
    print(f"- {n} shards ({mode}), CPU / peak memory per shard: {row}")
PY
