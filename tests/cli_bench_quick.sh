#!/bin/bash
# BENCH_QUICK=1 scripts/bench.sh: the corpus benchmark runs end to end and its
# page reads back (every trace a row of positive numbers, a geometric mean).
# Not timed: nothing here passes or fails on speed.
. "$(dirname "$0")/lib_cli.sh"
: "${FRAGSIM:?}" "${SCENEGEN:?}"
ROOT=$(cd "$(dirname "$0")/.." && pwd)
BUILD=${FRAGSIM_BUILD:-$(dirname "$FRAGSIM")}

test_bench_quick() {
    (cd "$ROOT" && BENCH_QUICK=1 BENCH_OUT="$WORK/bench" BENCH_DOC="$WORK/perf.md" \
        scripts/bench.sh "$BUILD") >"$WORK/log" 2>&1 || { tail -20 "$WORK/log"; fail "bench.sh failed"; }
    [ -s "$WORK/perf.md" ] || fail "no page written"
    # 3 corpus programs + bench8 + bench32, each with 10 positive numbers
    local rows
    rows=$(awk -F'|' '/^\| [a-z0-9]+ \| [0-9]+ \| [0-9.]+ \| / && NF == 13 {
        ok = 1; for (i = 3; i <= 12; i++) if ($i + 0 <= 0) ok = 0; if (ok) n++ } END { print n + 0 }' "$WORK/perf.md")
    [ "$rows" = 5 ] || { cat "$WORK/perf.md"; fail "expected 5 corpus rows with positive numbers, got $rows"; }
    grep -qE '^Geometric mean over the 5 traces: fragsim 1 thread [0-9.]+ x llvmpipe 1 thread, fragsim default threads [0-9.]+ x llvmpipe default threads\.$' \
        "$WORK/perf.md" || fail "no geometric mean line"
    grep -q 'glxgears\|antinspect' "$WORK/perf.md" || fail "no corpus program named"
}
run_test test_bench_quick
finish
