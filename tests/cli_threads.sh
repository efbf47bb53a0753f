#!/bin/bash
# Threaded functional replay (pipeline/raster_threads.h, issue 23): images
# and the statistics file of every corpus program trace and every bundled
# scene are identical for --threads 1, 2 and 4 (the statistics file differs
# only in its config's raster.threads, which is left out of the
# comparison); cycle mode gives the same cycle totals with --threads 1 and
# 4 (it runs on one thread either way); bad --threads values are refused.
. "$(dirname "$0")/lib_cli.sh"
: "${FRAGSIM:?}" "${SCENEGEN:?}"
ROOT=$(cd "$(dirname "$0")/.." && pwd)
PY=/usr/bin/python3

# The statistics file without config.raster.threads, as canonical JSON.
stats_of() { # FILE
    "$PY" -c 'import json,sys; d=json.load(open(sys.argv[1])); d.get("config",{}).pop("raster.threads",None); print(json.dumps(d,sort_keys=True,indent=0))' "$1"
}

# Replays TRACE with 1, 2 and 4 threads (extra options after it); fails
# on any image or statistic that differs from one thread's.
same_for_threads() { # NAME TRACE [OPTIONS...]
    local name=$1 trace=$2; shift 2
    local n
    for n in 1 2 4; do
        "$FRAGSIM" replay --quiet --threads $n "$@" --out "$WORK/$name.$n" "$trace" >/dev/null 2>"$WORK/$name.$n.err" ||
            fail "$name: replay --threads $n failed: $(tail -n 3 "$WORK/$name.$n.err")"
        (cd "$WORK/$name.$n" && md5sum *.png) >"$WORK/$name.$n.md5"
        stats_of "$WORK/$name.$n/stats.json" >"$WORK/$name.$n.json"
    done
    [ -s "$WORK/$name.1.md5" ] || fail "$name: no image"
    for n in 2 4; do
        cmp -s "$WORK/$name.1.md5" "$WORK/$name.$n.md5" ||
            fail "$name: images differ with --threads $n: $(diff "$WORK/$name.1.md5" "$WORK/$name.$n.md5" | head -n 4)"
        cmp -s "$WORK/$name.1.json" "$WORK/$name.$n.json" ||
            fail "$name: statistics differ with --threads $n: $(diff "$WORK/$name.1.json" "$WORK/$name.$n.json" | head -n 6)"
    done
    rm -rf "$WORK/$name".*
}

test_program_traces() {
    local t n=0
    # THREADS_QUICK=1 (make tsan): five traces, the sanitizer being slow.
    if [ "${THREADS_QUICK:-0}" = 1 ]; then
        for t in atlantis glblur polyhedra winduprobot cage; do
            same_for_threads "$t" "$ROOT/tests/conformance/programs/$t.trace" || return 1
        done
        return 0
    fi
    for t in "$ROOT"/tests/conformance/programs/*.trace; do
        same_for_threads "$(basename "$t" .trace)" "$t" || return 1
        n=$((n + 1))
    done
    [ $n -ge 30 ] || fail "only $n program traces"
}

test_scenes() {
    local s all="city norwich cathedrals forest garbage terrain demo textured bench32"
    [ "${THREADS_QUICK:-0}" = 1 ] && all="demo textured"
    for s in $all; do
        "$SCENEGEN" "$s" --scale small -o "$WORK/$s.trace" >/dev/null || fail "scenegen $s"
        same_for_threads "$s" "$WORK/$s.trace" || return 1
    done
    # The footprint filter stays on one thread (its ROMs are made lazily).
    "$SCENEGEN" textured --scale small --filter footprint -o "$WORK/fp.trace" >/dev/null || fail "scenegen footprint"
    same_for_threads fp "$WORK/fp.trace"
}

test_cycle_mode() {
    "$SCENEGEN" demo --scale small -o "$WORK/d.trace" >/dev/null || fail "scenegen demo"
    same_for_threads cycle "$WORK/d.trace" --mode cycle --config "$ROOT/configs/o2.ini"
}

test_bad_threads() {
    local v
    for v in -1 9 x 2x ""; do
        "$FRAGSIM" replay --threads "$v" --out "$WORK/bad" "$ROOT/tests/conformance/programs/glxgears.trace" 2>"$WORK/e"
        [ $? -eq 2 ] || fail "--threads '$v' must exit 2"
        grep -q -- "--threads" "$WORK/e" || fail "message for '$v': $(cat "$WORK/e")"
    done
    "$FRAGSIM" replay --set raster.threads=9 --out "$WORK/bad" "$ROOT/tests/conformance/programs/glxgears.trace" 2>/dev/null
    [ $? -ne 0 ] || fail "raster.threads=9 accepted"
}

run_test test_bad_threads
run_test test_cycle_mode
run_test test_scenes
run_test test_program_traces
finish
