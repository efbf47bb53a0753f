#!/bin/bash
# `make fuzz`: coverage-guided fuzzing under ASan + UBSan with clang's
# libFuzzer, of two harnesses in turn (tests/fuzz/README.md):
#  - fuzz_trace: trace files through the reader, the replayer and the model;
#    seeds are the decompressed streams of small traces (two OSMesa programs
#    captured through the shim, tiny scenegen scenes);
#  - fuzz_gl: sequences of GL calls with arbitrary arguments into fs_submit.
# FUZZ_SECONDS (default 150) bounds each; the corpora persist in $FB/corpus*,
# and a crash or hang is written to $FB/crash-* (or timeout-*, leak-*).
set -euo pipefail
B=${1:-build}
FB=${2:-build-fuzz}
SECONDS_MAX=${FUZZ_SECONDS:-150}
LIBS="$(pkg-config --libs snappy zlib inih jansson libgpiod) -lm"
CFLAGS_F="-std=c11 -D_POSIX_C_SOURCE=200809L -g -O1 -Wall -Wextra -Werror -fno-omit-frame-pointer"

clang $CFLAGS_F -fsanitize=fuzzer,address,undefined -fno-sanitize-recover=undefined \
    tests/fuzz/fuzz_trace.c -Wl,--whole-archive "$FB/libfragsim.a" -Wl,--no-whole-archive $LIBS \
    -o "$FB/fuzz_trace"
clang $CFLAGS_F -fsanitize=fuzzer,address,undefined -fno-sanitize-recover=undefined \
    tests/fuzz/fuzz_gl.c -Wl,--whole-archive "$FB/libfragsim.a" -Wl,--no-whole-archive $LIBS \
    -o "$FB/fuzz_gl"
cc $CFLAGS_F tests/fuzz/unpack_trace.c $(pkg-config --libs snappy) -o "$FB/unpack_trace"

seeds="$FB/seeds"
mkdir -p "$seeds" "$FB/corpus" "$FB/corpus_gl"
if [ -z "$(ls -A "$seeds")" ]; then
    tmp=$(mktemp -d)
    trap 'rm -rf "$tmp"' EXIT
    for p in osmesa_boxes osmesa_api; do
        cc -std=c11 -O1 "tests/programs/$p.c" -o "$tmp/$p" -L"$B" -lfragsimGL -Wl,-rpath,"$PWD/$B"
        (cd "$tmp" && FRAGSIM_TRACE="$tmp/$p.trace" "./$p" "$tmp/$p.ppm" >/dev/null 2>&1) || true
    done
    "$B/scenegen" bench8 --scale 100 --frames 2 --size 32x32 -o "$tmp/bench8.trace" >/dev/null
    "$B/scenegen" demo --scale 100 --frames 1 --size 32x32 -o "$tmp/demo.trace" >/dev/null
    "$B/scenegen" textured --scale 100 --frames 1 --size 32x32 -o "$tmp/textured.trace" >/dev/null
    for t in "$tmp"/*.trace; do
        [ -s "$t" ] || continue
        "$FB/unpack_trace" "$t" > "$seeds/$(basename "$t" .trace).raw"
        # The container itself as a seed too (the "at" path of the harness),
        # when it is small.
        [ "$(stat -c %s "$t")" -le 65536 ] && cp "$t" "$seeds/$(basename "$t" .trace).at"
    done
fi
export ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1
opts=(-max_total_time="$SECONDS_MAX" -timeout=20 -rss_limit_mb=4096 -artifact_prefix="$FB/" -print_final_stats=1)
run_trace() {
    echo "fuzz_trace: $SECONDS_MAX s; seeds $(ls "$seeds" | wc -l), corpus $(ls "$FB/corpus" | wc -l) inputs"
    "$FB/fuzz_trace" "${opts[@]}" -max_len=262144 "$FB/corpus" "$seeds"
}
run_gl() {
    echo "fuzz_gl: $SECONDS_MAX s; corpus $(ls "$FB/corpus_gl" | wc -l) inputs"
    "$FB/fuzz_gl" "${opts[@]}" -max_len=8192 "$FB/corpus_gl"
}
# FUZZ_PARALLEL=1 runs both harnesses at once (one core each), their output
# in $FB/fuzz_trace.log and $FB/fuzz_gl.log; either failing fails the run.
if [ "${FUZZ_PARALLEL:-0}" = 1 ]; then
    run_trace > "$FB/fuzz_trace.log" 2>&1 & pt=$!
    run_gl > "$FB/fuzz_gl.log" 2>&1 & pg=$!
    rc=0; wait $pt || rc=1; wait $pg || rc=1
    tail -n 12 "$FB/fuzz_trace.log" "$FB/fuzz_gl.log"
    exit $rc
fi
run_trace
run_gl
