#!/bin/bash
# Command-line tests of the cycle model's signals (docs/signals.md): the VCD
# of `fragsim replay --mode cycle --vcd` read by an independent reader
# (tests/vcd_check.py) and converted by GTKWave's vcd2fst, with every unit's
# busy and stalled cycles equal to the statistics and one frame_start pulse
# per frame; the frame window and the signal list; the outputs unchanged by
# --vcd; the one-line errors of the signal and GPIO options, each exit
# status 2 with nothing written.  This machine has no GPIO chips: the GPIO
# path is run here only up to the chip's open (a line in use, an offset out
# of range and the release on exit and signals are tested through a fake
# chip in tests/test_signals.c).
. "$(dirname "$0")/lib_cli.sh"
: "${FRAGSIM:?}" "${SCENEGEN:?}" "${FRAGSIM_BUILD:?}"
ROOT=$(cd "$(dirname "$0")/.." && pwd)
PY=/usr/bin/python3

scene() { # NAME -> a small trace of that scene
    local t="$WORK/$1.trace"
    [ -f "$t" ] || "$SCENEGEN" "$1" --scale small -o "$t" >/dev/null || return 1
    echo "$t"
}

# A GL_FRAGSIM_occlusion_unit workload (brief mode, 4 tiles): the Occlusion
# Engines and OccU Control at work (docs/studies/occlusion_workload.c).
occlusion_trace() {
    local t="$WORK/occlusion.trace" bin="$WORK/occlusion_workload"
    if [ ! -f "$t" ]; then
        ${CC:-cc} -std=c11 -D_POSIX_C_SOURCE=200809L -O1 $(san_flags "$FRAGSIM_BUILD") "$ROOT/docs/studies/occlusion_workload.c" -o "$bin" \
            -Wl,--whole-archive "$FRAGSIM_BUILD/libfragsim.a" -Wl,--no-whole-archive \
            $(pkg-config --libs osmesa snappy zlib inih jansson libgpiod) -lm || return 1
        "$bin" --test brief --tiles 4 -o "$t" >/dev/null || return 1
    fi
    echo "$t"
}

vcd_matches() { # TRACE CONFIG [FIRST LAST]
    local t=$1 cfg=$2 n; n=$(basename "$t" .trace)_$(basename "$cfg" .ini)
    local range=(); [ $# -gt 2 ] && range=(--vcd-frames "$3-$4")
    "$FRAGSIM" replay --quiet --mode cycle --config "$cfg" --out "$WORK/o_$n" --stats "$WORK/$n.json" \
        --vcd "$WORK/$n.vcd" "${range[@]}" "$t" 2>"$WORK/$n.err" || fail "$n: replay failed: $(cat "$WORK/$n.err")"
    grep -q "out of order" "$WORK/$n.err" && fail "$n: $(grep "out of order" "$WORK/$n.err")"
    $PY "$ROOT/tests/vcd_check.py" "$WORK/$n.vcd" "$WORK/$n.json" "${@:3}" >"$WORK/$n.check" ||
        fail "$n: $(grep -v ' ok ' "$WORK/$n.check")"
    if command -v vcd2fst >/dev/null; then
        vcd2fst "$WORK/$n.vcd" "$WORK/$n.fst" >"$WORK/$n.fstlog" 2>&1 || fail "$n: vcd2fst: $(cat "$WORK/$n.fstlog")"
        [ -s "$WORK/$n.fst" ] || fail "$n: vcd2fst wrote nothing"
    fi
}

test_vcd_matches_statistics() {
    command -v vcd2fst >/dev/null || skip "no vcd2fst (Debian package gtkwave)"
    local t o
    o=$(occlusion_trace) || fail "occlusion workload failed"
    for cfg in o2 infinite_reality; do
        for t in "$(scene demo)" "$(scene textured)" "$o" \
            "$ROOT/tests/conformance/piglit/arb_occlusion_query-occlusion_query.trace"; do
            vcd_matches "$t" "$ROOT/configs/$cfg.ini"
        done
    done
    # the Occlusion Unit's signals were at work, and queries were seen
    grep -q 'occlusion_engines_busy cycles *ok (vcd [1-9]' "$WORK/occlusion_o2.check" ||
        fail "occlusion workload: no Occlusion Engine cycles"
    grep -q 'query_end pulses = queries *ok (vcd [1-9]' "$WORK/arb_occlusion_query-occlusion_query_o2.check" ||
        fail "query trace: no queries"
}

test_vcd_frames_window() {
    local t; t=$(scene textured) || fail "scenegen failed"
    vcd_matches "$t" "$ROOT/configs/o2.ini" 1 1
    grep -q 'frame_start pulses = frames *ok (vcd 1,' "$WORK/textured_o2.check" || fail "not one frame"
}

test_vcd_signal_list() {
    local t; t=$(scene demo) || fail "scenegen failed"
    "$FRAGSIM" replay --quiet --mode cycle --out "$WORK/sl" --vcd "$WORK/sl.vcd" --vcd-signals 'frame_start,raster_*' \
        "$t" 2>/dev/null || fail "replay failed"
    [ "$(grep -c '^\$var' "$WORK/sl.vcd")" -eq 4 ] || fail "expected 4 signals: $(grep '^\$var' "$WORK/sl.vcd")"
    grep -q ' raster_fifo \$end' "$WORK/sl.vcd" || fail "no raster_fifo"
}

# --vcd changes no image and no statistic.
test_vcd_keeps_outputs() {
    local t; t=$(scene textured) || fail "scenegen failed"
    "$FRAGSIM" replay --quiet --mode cycle --out "$WORK/a" "$t" 2>/dev/null || fail "replay failed"
    "$FRAGSIM" replay --quiet --mode cycle --out "$WORK/b" --vcd "$WORK/k.vcd" "$t" 2>/dev/null || fail "replay failed"
    for p in "$WORK"/a/*; do cmp -s "$p" "$WORK/b/$(basename "$p")" || fail "$(basename "$p") differs"; done
}

# Each mistake: exit status 2, one line naming it, no output directory, no VCD.
refused() { # EXPECTED-TEXT ARGS...
    local want=$1; shift
    local t; t=$(scene demo) || fail "scenegen failed"
    rm -rf "$WORK/never" "$WORK/never.vcd"
    "$FRAGSIM" replay --quiet --out "$WORK/never" "$@" "$t" >"$WORK/out" 2>"$WORK/err"
    local rc=$?
    [ $rc -eq 2 ] || fail "$*: exit $rc, not 2 ($(cat "$WORK/err"))"
    [ "$(wc -l <"$WORK/err")" -eq 1 ] || fail "$*: not one line: $(cat "$WORK/err")"
    grep -qF -- "$want" "$WORK/err" || fail "$*: '$(cat "$WORK/err")' does not say '$want'"
    [ ! -e "$WORK/never" ] && [ ! -e "$WORK/never.vcd" ] || fail "$*: something was written"
}

test_signal_errors() {
    refused "no GPIO chip 'fragsim-no-such-chip'" --mode cycle --gpio fragsim-no-such-chip
    refused "no GPIO chip 'fragsim-no-such-chip'" --mode cycle --vcd "$WORK/never.vcd" --gpio fragsim-no-such-chip \
        --gpio-map frame_start=2
    refused "unknown signal 'no_such'" --mode cycle --vcd "$WORK/never.vcd" --vcd-signals frame_start,no_such
    refused "--gpio-map: unknown signal 'bogus'" --mode cycle --gpio gpiochip0 --gpio-map bogus=1
    refused "--gpio-map: signal frame_start mapped twice" --mode cycle --gpio gpiochip0 \
        --gpio-map frame_start=0,frame_start=1
    refused "--gpio-map: line 1 mapped twice" --mode cycle --gpio gpiochip0 --gpio-map frame_start=1,query_done=1
    refused "--gpio-map given twice" --mode cycle --gpio gpiochip0 --gpio-map frame_start=0 --gpio-map query_done=1
    refused "--gpio-map '1=frame_start': expected SIGNAL=LINE" --mode cycle --gpio gpiochip0 --gpio-map 1=frame_start
    refused "--vcd needs --mode cycle" --vcd "$WORK/never.vcd"
    refused "--vcd needs --mode cycle" --mode sampled --vcd "$WORK/never.vcd"
    refused "--vcd-frames '3-1'" --mode cycle --vcd "$WORK/never.vcd" --vcd-frames 3-1
    refused "--gpio-map needs --gpio" --mode cycle --gpio-map frame_start=0
}

# The signal table is the one source of the list and of docs/signals.md's table.
test_signals_list() {
    "$FRAGSIM" signals --list >"$WORK/list" || fail "signals --list failed"
    for s in frame_start draw_start query_begin query_end occlusion_result occu_mode ctr_reloads raster_busy \
        texture_stalled fragment_fifo occlusion_busy occlusion_engines_busy occu_control_busy memory_busy; do
        grep -q "^$s " "$WORK/list" || fail "no $s in the list"
    done
    "$FRAGSIM" signals --list --markdown >"$WORK/md" || fail "signals --list --markdown failed"
    awk '/^<!-- signals: begin -->/ {on = 1; next} /^<!-- signals: end -->/ {on = 0} on' "$ROOT/docs/signals.md" |
        diff - "$WORK/md" >/dev/null || fail "docs/signals.md's table is not \`fragsim signals --list --markdown\` (make docs)"
    "$FRAGSIM" replay --help | grep -q -- "--vcd FILE" || fail "replay --help has no --vcd"
}

run_test test_vcd_matches_statistics
run_test test_vcd_frames_window
run_test test_vcd_signal_list
run_test test_vcd_keeps_outputs
run_test test_signal_errors
run_test test_signals_list
finish
