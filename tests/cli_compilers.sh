#!/bin/bash
# Determinism across compilers: fragsim built with clang must write the same
# traces, images and statistics as the gcc build under test.
. "$(dirname "$0")/lib_cli.sh"
: "${FRAGSIM:?}" "${SCENEGEN:?}"
ROOT=$(cd "$(dirname "$0")/.." && pwd)

test_gcc_and_clang_agree() {
    [ -n "${FRAGSIM_SKIP_COMPILER_TEST:-}" ] && skip "disabled for this build (FRAGSIM_SKIP_COMPILER_TEST)"
    command -v clang >/dev/null || skip "clang not installed"
    local other=build-clang
    make -C "$ROOT" -s -j2 BUILD=$other CC=clang $other/fragsim $other/scenegen >"$WORK/build.log" 2>&1 \
        || { tail -20 "$WORK/build.log"; fail "clang build failed"; }
    for s in city cathedrals terrain demo; do
        "$SCENEGEN" "$s" --scale small -o "$WORK/g_$s.trace" >/dev/null || fail "scenegen (gcc) $s"
        "$ROOT/$other/scenegen" "$s" --scale small -o "$WORK/c_$s.trace" >/dev/null || fail "scenegen (clang) $s"
        cmp -s "$WORK/g_$s.trace" "$WORK/c_$s.trace" || fail "$s: traces differ between compilers"
        "$FRAGSIM" replay --quiet --out "$WORK/g_$s" "$WORK/g_$s.trace" 2>/dev/null || fail "replay (gcc) $s"
        "$ROOT/$other/fragsim" replay --quiet --out "$WORK/c_$s" "$WORK/g_$s.trace" 2>/dev/null || fail "replay (clang) $s"
        for f in "$WORK/g_$s"/frame_*.png; do
            cmp -s "$f" "$WORK/c_$s/$(basename "$f")" || fail "$s: $(basename "$f") differs between compilers"
        done
        cmp -s "$WORK/g_$s/stats.json" "$WORK/c_$s/stats.json" || fail "$s: statistics differ between compilers"
    done
}
run_test test_gcc_and_clang_agree
finish
