#!/bin/bash
# The shim driver (build/libfragsimGL.so): programs written for OSMesa
# (tests/programs/) built against -lOSMesa and against the shim, and the
# OSMesa build with the shim preloaded, must print the same numbers; a
# FRAGSIM_TRACE capture must dump with the right names, replay to the same
# image and counters, and pass `fragsim check`.
. "$(dirname "$0")/lib_cli.sh"
: "${FRAGSIM:?}" "${FRAGSIM_BUILD:?}"
ROOT=$(cd "$(dirname "$0")/.." && pwd)
SHIM="$FRAGSIM_BUILD/libfragsimGL.so"
CC=${CC:-cc}
# A sanitizer build's shim needs the sanitizer runtime loaded first: build
# the programs with the same sanitizers, and preload the runtime before it.
PROG_FLAGS="-std=c11 -O1 -g -Wall -Wextra -Werror"
PRELOAD="$SHIM"
if ldd "$SHIM" 2>/dev/null | grep -q libasan; then
    PROG_FLAGS="$PROG_FLAGS -fsanitize=address,undefined"
    PRELOAD="$(ldd "$SHIM" | awk '/libasan/ {print $3}') $SHIM"
fi

totals() { # STATS.json -> the lines of its "totals" block
    sed -n '/"totals": {/,/}/p' "$1" | sed '1d;$d'
}

build() { # PROGRAM -> $WORK/PROGRAM_osmesa and $WORK/PROGRAM_shim
    local src="$ROOT/tests/programs/$1.c"
    [ -f "$WORK/$1_shim" ] && return 0
    [ -f "$SHIM" ] || fail "no $SHIM (make shim)"
    $CC $PROG_FLAGS "$src" -o "$WORK/$1_osmesa" -lOSMesa || fail "$1: build against -lOSMesa failed"
    $CC $PROG_FLAGS "$src" -o "$WORK/$1_shim" -L"$FRAGSIM_BUILD" -lfragsimGL \
        -Wl,-rpath,"$FRAGSIM_BUILD" || fail "$1: build against the shim failed"
}

test_shim_exports_table_and_osmesa_api() {
    [ -f "$SHIM" ] || fail "no $SHIM"
    local syms; syms=$(nm -D --defined-only "$SHIM" | awk '{print $3}')
    for s in glBegin glVertex3f glGenQueries glBeginQuery glEndQuery glGetQueryObjectuiv \
             glScissors glOcclusionBuffers glRenderMode OSMesaCreateContext OSMesaCreateContextExt \
             OSMesaMakeCurrent OSMesaGetCurrentContext OSMesaGetDepthBuffer OSMesaGetColorBuffer \
             OSMesaGetProcAddress OSMesaDestroyContext OSMesaPixelStore; do
        echo "$syms" | grep -qx "$s" || fail "$s is not exported"
    done
    # Only GL and OSMesa names: the model's own symbols stay hidden.
    local other; other=$(echo "$syms" | grep -vE '^(gl|OSMesa)' | grep -vE '^(_init|_fini)$' || true)
    [ -z "$other" ] || fail "exports other symbols: $other"
    ! ldd "$SHIM" | grep -q OSMesa || fail "the shim links libOSMesa"
}

test_boxes_same_numbers_as_osmesa() {
    build osmesa_boxes
    ldd "$WORK/osmesa_boxes_shim" | grep -q OSMesa && fail "the shim build links libOSMesa"
    "$WORK/osmesa_boxes_osmesa" >"$WORK/boxes_osmesa.txt" 2>"$WORK/e1" || fail "OSMesa run: $(cat "$WORK/e1")"
    "$WORK/osmesa_boxes_shim" >"$WORK/boxes_shim.txt" 2>"$WORK/e2" || fail "shim run: $(cat "$WORK/e2")"
    LD_PRELOAD="$PRELOAD" "$WORK/osmesa_boxes_osmesa" >"$WORK/boxes_preload.txt" 2>"$WORK/e3" \
        || fail "preloaded run: $(cat "$WORK/e3")"
    grep -q llvmpipe "$WORK/e1" || fail "OSMesa run did not use llvmpipe: $(cat "$WORK/e1")"
    grep -q fragsim "$WORK/e2" || fail "linked run did not use the model: $(cat "$WORK/e2")"
    grep -q fragsim "$WORK/e3" || fail "preloaded run did not use the model: $(cat "$WORK/e3")"
    grep -q "samples [1-9]" "$WORK/boxes_osmesa.txt" || fail "no visible samples: $(cat "$WORK/boxes_osmesa.txt")"
    diff "$WORK/boxes_osmesa.txt" "$WORK/boxes_shim.txt" || fail "linked against the shim: output differs"
    diff "$WORK/boxes_osmesa.txt" "$WORK/boxes_preload.txt" || fail "shim preloaded: output differs"
    echo "$(grep -c samples "$WORK/boxes_shim.txt") query results, colour and depth checksums identical"
}

# Issue 19's state program: test_state_table --print sets random state,
# pushes every attribute group (and the client groups), scrambles, pops and
# queries every GL 1.5 state variable, lights, materials and textures
# through plain gl* calls; on libOSMesa and with the shim preloaded it must
# print the same values and errors.
test_state_program_same_as_osmesa() {
    local p="$FRAGSIM_BUILD/tests/test_state_table"
    [ -x "$p" ] || fail "no $p"
    "$p" --print >"$WORK/state_osmesa.txt" 2>"$WORK/s1" || fail "OSMesa run: $(cat "$WORK/s1")"
    LD_PRELOAD="$PRELOAD" "$p" --print >"$WORK/state_shim.txt" 2>"$WORK/s2" || fail "preloaded run: $(cat "$WORK/s2")"
    grep -q 'renderer llvmpipe' "$WORK/s1" || fail "OSMesa run did not use llvmpipe: $(cat "$WORK/s1")"
    grep -q 'renderer fragsim' "$WORK/s2" || fail "preloaded run did not use the model: $(cat "$WORK/s2")"
    [ "$(wc -l <"$WORK/state_osmesa.txt")" -gt 100000 ] || fail "too few values: $(wc -l <"$WORK/state_osmesa.txt")"
    diff "$WORK/state_osmesa.txt" "$WORK/state_shim.txt" | head -20 >&2
    cmp -s "$WORK/state_osmesa.txt" "$WORK/state_shim.txt" || fail "the shim's state differs from libOSMesa's"
    echo "$(wc -l <"$WORK/state_shim.txt") values and errors identical"
}

test_api_same_as_osmesa() {
    build osmesa_api
    "$WORK/osmesa_api_osmesa" >"$WORK/api_osmesa.txt" 2>&1 || fail "OSMesa run failed"
    "$WORK/osmesa_api_shim" >"$WORK/api_shim.txt" 2>&1 || fail "shim run failed"
    # OSMesaGetColorBuffer: OSMesa hands out the pixels of the last flush,
    # the shim up-to-date ones (README); the rest must agree.
    diff <(grep -v '^unflushed' "$WORK/api_osmesa.txt") <(grep -v '^unflushed' "$WORK/api_shim.txt") \
        || fail "output differs"
    grep -qx "unflushed color buffer pixel: 128 64 0 255" "$WORK/api_shim.txt" \
        || fail "OSMesaGetColorBuffer did not give up-to-date pixels: $(grep unflushed "$WORK/api_shim.txt")"
}

test_capture_dump_replay_check() {
    build osmesa_boxes
    FRAGSIM_TRACE="$WORK/boxes.trace" FRAGSIM_STATS="$WORK/boxes_stats.json" \
        "$WORK/osmesa_boxes_shim" "$WORK/boxes.ppm" >"$WORK/cap.txt" 2>"$WORK/e" || fail "capture run: $(cat "$WORK/e")"
    [ -s "$WORK/boxes.trace" ] || fail "no trace written"
    "$WORK/osmesa_boxes_shim" >"$WORK/nocap.txt" 2>/dev/null
    diff "$WORK/nocap.txt" "$WORK/cap.txt" || fail "capturing changed the output"
    if command -v apitrace >/dev/null; then
        apitrace dump --color=never "$WORK/boxes.trace" >"$WORK/dump" 2>"$WORK/e" || fail "apitrace dump: $(cat "$WORK/e")"
        for call in "glGenQueries(n = 10" "glBeginQuery(target = GL_SAMPLES_PASSED" "glEndQuery(target = GL_SAMPLES_PASSED)" \
                    "glGetQueryObjectuiv(id = 1, pname = GL_QUERY_RESULT_AVAILABLE, params = &1)" \
                    "glGetQueryObjectuiv(id = 3, pname = GL_QUERY_RESULT, params = &" "glLightfv(light = GL_LIGHT0"; do
            grep -qF "$call" "$WORK/dump" || fail "apitrace dump lacks $call"
        done
    else
        echo "apitrace not installed: dump not checked"
    fi
    "$FRAGSIM" replay --quiet --out "$WORK/rep" "$WORK/boxes.trace" || fail "replay failed"
    local last; last=$(ls "$WORK"/rep/frame_*.png | tail -n 1)
    [ "$(ls "$WORK"/rep/frame_*.png | wc -l)" -eq 3 ] || fail "expected 3 frames (2 glFinish and the calls after them)"
    "$FRAGSIM" diff "$WORK/boxes.ppm" "$last" >"$WORK/d" || fail "replayed image differs: $(cat "$WORK/d")"
    totals "$WORK/boxes_stats.json" >"$WORK/t_shim"
    totals "$WORK/rep/stats.json" >"$WORK/t_replay"
    [ "$(wc -l <"$WORK/t_shim")" -gt 20 ] || fail "no counters from FRAGSIM_STATS: $(cat "$WORK/boxes_stats.json")"
    diff "$WORK/t_shim" "$WORK/t_replay" || fail "counters of the shim run and of the replay differ"
    local printed; printed=$(sed -nE 's/.* samples ([0-9]+) .*/\1/p' "$WORK/cap.txt" | awk '{s += $1} END {print s}')
    grep -qE "^ *\"query_samples\": $printed,?\$" "$WORK/t_replay" \
        || fail "query_samples is not the sum of the printed counts ($printed)"
    echo "$(wc -l <"$WORK/t_shim") counters identical; query_samples $printed"
    "$FRAGSIM" check --quiet --out "$WORK/chk" "$WORK/boxes.trace" >"$WORK/c.log" 2>&1 \
        || { cat "$WORK/c.log"; fail "fragsim check of the capture failed"; }
    cat "$WORK/c.log"
    # the shim's capture decodes and replays alike through both trace parsers
    FS_PARSER_TRACES="$WORK/boxes.trace" "${FRAGSIM_BUILD:-$ROOT/build}/tests/test_trace_parsers" named_traces \
        >"$WORK/p.log" 2>&1 || { cat "$WORK/p.log"; fail "the trace parsers differ on the capture"; }
    grep -q "^ok   named_traces" "$WORK/p.log" || fail "named_traces did not run: $(cat "$WORK/p.log")"
}

# A capture path that cannot be written: one clear message, and the program
# runs on and prints what it prints without capture.
test_capture_to_unwritable_path() {
    build osmesa_boxes
    "$WORK/osmesa_boxes_shim" >"$WORK/plain.txt" 2>/dev/null || fail "plain run failed"
    FRAGSIM_TRACE="$WORK/no/such/dir/x.trace" "$WORK/osmesa_boxes_shim" >"$WORK/bad.txt" 2>"$WORK/e" \
        || fail "the program failed: $(cat "$WORK/e")"
    grep -q "FRAGSIM_TRACE: not capturing" "$WORK/e" || fail "no message: $(cat "$WORK/e")"
    grep -q "no/such/dir/x.trace" "$WORK/e" || fail "message does not name the path: $(cat "$WORK/e")"
    diff "$WORK/plain.txt" "$WORK/bad.txt" || fail "output changed"
}

# GL errors: the same codes as OSMesa, and FRAGSIM_STATS lists each with the
# number of the program's GL call that raised it (from 0), as the program's
# comments number them; the glCallList's error is raised by its list.
test_shim_errors_listed_by_call() {
    build osmesa_errors
    "$WORK/osmesa_errors_osmesa" >"$WORK/err_osmesa.txt" 2>/dev/null || fail "OSMesa run failed"
    FRAGSIM_STATS="$WORK/err_stats.json" "$WORK/osmesa_errors_shim" >"$WORK/err_shim.txt" 2>/dev/null ||
        fail "shim run failed"
    diff "$WORK/err_osmesa.txt" "$WORK/err_shim.txt" || fail "glGetError differs from OSMesa's"
    grep -q '0x0500' "$WORK/err_osmesa.txt" || fail "OSMesa raised no GL_INVALID_ENUM: $(cat "$WORK/err_osmesa.txt")"
    cat >"$WORK/err_want.txt" <<'EOF2'
errors_total 4
1 glEnable GL_INVALID_ENUM
7 glCallList GL_INVALID_VALUE
9 glPopMatrix GL_STACK_UNDERFLOW
12 glEnable GL_INVALID_OPERATION
EOF2
    /usr/bin/python3 - "$WORK/err_stats.json" >"$WORK/err_got.txt" <<'PY' || fail "FRAGSIM_STATS is not JSON"
import json, sys
d = json.load(open(sys.argv[1]))
print("errors_total", d["errors_total"])
for e in d["errors"]:
    print(e["call"], e["command"], e["error"])
PY
    diff "$WORK/err_want.txt" "$WORK/err_got.txt" || fail "errors list differs"
}

# FRAGSIM_TRACE_GPIO=CHIP:LINE gates the capture on an input line
# (docs/signals.md).  No GPIO chip here: a chip that does not exist gives one
# message naming it, nothing is captured, the program runs on unchanged.
test_capture_gate_missing_chip() {
    build osmesa_boxes
    "$WORK/osmesa_boxes_shim" >"$WORK/plain.txt" 2>/dev/null || fail "plain run failed"
    FRAGSIM_TRACE="$WORK/gated.trace" FRAGSIM_TRACE_GPIO=fragsim-no-such-chip:0 "$WORK/osmesa_boxes_shim" \
        >"$WORK/gated.txt" 2>"$WORK/e" || fail "the program failed: $(cat "$WORK/e")"
    grep -q "FRAGSIM_TRACE_GPIO: not capturing.*no GPIO chip 'fragsim-no-such-chip'" "$WORK/e" ||
        fail "no message naming the chip: $(cat "$WORK/e")"
    [ ! -e "$WORK/gated.trace" ] || fail "a trace was written"
    diff "$WORK/plain.txt" "$WORK/gated.txt" || fail "the gate changed the output"
    FRAGSIM_TRACE="$WORK/gated.trace" FRAGSIM_TRACE_GPIO=nocolon "$WORK/osmesa_boxes_shim" >/dev/null 2>"$WORK/e"
    grep -q "FRAGSIM_TRACE_GPIO: expected CHIP:LINE" "$WORK/e" || fail "no message for a bad value: $(cat "$WORK/e")"
}

for t in test_shim_exports_table_and_osmesa_api test_boxes_same_numbers_as_osmesa test_api_same_as_osmesa \
         test_state_program_same_as_osmesa \
         test_shim_errors_listed_by_call \
         test_capture_dump_replay_check test_capture_to_unwritable_path test_capture_gate_missing_chip; do
    run_test "$t"
done
finish
