#!/bin/bash
# Command-line tests of the cycle-level model (rtl_model/, docs/cycle_model.md):
# cycle mode gives the same images and functional counters as functional mode
# on every scene of the corpus and in both architectures; configuration
# errors name the file and line; configs/default.ini is what the key table
# says; sampled mode stays within 2% of full cycle mode on every scene of the
# corpus at small scale (21 frames: frame sampling; the one-frame bench
# scenes: tile sampling).
. "$(dirname "$0")/lib_cli.sh"
: "${FRAGSIM:?}" "${SCENEGEN:?}"
ROOT=$(cd "$(dirname "$0")/.." && pwd)
SCENES="city norwich cathedrals forest garbage terrain demo textured bench8 bench32 textured_fp8 textured_fph32"

scene_trace() { # NAME [FRAMES] -> path of a small trace of that scene
    local t="$WORK/$1${2:+_$2}.trace" args=$1
    # the textured scene's ground with the fast-footprint filter (M = 8, hybrid M = 32)
    case $1 in
    textured_fp8) args="textured --filter footprint --budget 8" ;;
    textured_fph32) args="textured --filter footprint-hybrid --budget 32" ;;
    esac
    [ -f "$t" ] || "$SCENEGEN" $args --scale small ${2:+--frames $2} -o "$t" >/dev/null || return 1
    echo "$t"
}

# The statistics file without the cycle model's member.
strip_cycle() { awk '/^  "cycle": \{/ {skip = 1} !skip {print} skip && /^  \},$/ {skip = 0}' "$1"; }

identical() { # SCENE CONFIG
    local s=$1 cfg=$2 t
    t=$(scene_trace "$s") || fail "scenegen $s failed"
    local a="$WORK/f_$s" b="$WORK/c_$s"
    rm -rf "$a" "$b"
    "$FRAGSIM" replay --quiet --config "$cfg" --out "$a" "$t" 2>/dev/null || fail "$s: functional replay failed"
    "$FRAGSIM" replay --quiet --mode cycle --config "$cfg" --out "$b" --csv "$WORK/c_$s.csv" --draw-stats "$t" 2>/dev/null ||
        fail "$s: cycle replay failed"
    local n=0
    for p in "$a"/frame_*.png; do
        cmp -s "$p" "$b/$(basename "$p")" || fail "$s ($cfg): $(basename "$p") differs"
        n=$((n + 1))
    done
    [ $n -gt 0 ] || fail "$s: no frame"
    diff <(strip_cycle "$a/stats.json") <(strip_cycle "$b/stats.json") >/dev/null ||
        fail "$s ($cfg): functional counters differ"
    grep -q '"cycle": {' "$b/stats.json" || fail "$s: no cycle statistics"
    # cycles of the frames: positive, and the CSV has one row per frame; one
    # row per draw, as many as the total counts, whose cycles add up to at
    # most the total (frame-end drains come on top)
    local csv="$WORK/c_$s.csv"
    [ "$(grep -c '^frame,' "$csv")" -eq $n ] || fail "$s: CSV frame rows"
    awk -F, '$1 == "frame" && $7 <= 0 {bad = 1} END {exit bad}' "$csv" || fail "$s: a frame without cycles"
    awk -F, '$1 == "draw" {n++; c += $7} $1 == "total" {t = $7; d = $9} END {exit !(n == d && n > 0 && c <= t)}' "$csv" ||
        fail "$s: draw rows do not match the total"
}

test_cycle_identical_o2() { for s in $SCENES; do identical "$s" "$ROOT/configs/o2.ini"; done; }
test_cycle_identical_ir() { for s in $SCENES; do identical "$s" "$ROOT/configs/infinite_reality.ini"; done; }

test_config_errors() {
    local t; t=$(scene_trace demo) || fail "scenegen failed"
    printf '[texture]\ncache_bytes = 4096\n\n[memory]\nno_such_key = 1\n' >"$WORK/unknown.ini"
    "$FRAGSIM" replay --mode cycle --config "$WORK/unknown.ini" --out "$WORK/o" "$t" 2>"$WORK/e"
    [ $? -eq 2 ] || fail "unknown key: expected exit 2"
    grep -q "unknown.ini:5: unknown key memory.no_such_key" "$WORK/e" || fail "unknown key: $(cat "$WORK/e")"
    printf '[memory]\nlatency = 3\nbytes_per_cycle = fast\n' >"$WORK/bad.ini"
    "$FRAGSIM" replay --mode cycle --config "$WORK/bad.ini" --out "$WORK/o" "$t" 2>"$WORK/e"
    [ $? -eq 2 ] || fail "bad value: expected exit 2"
    grep -q "bad.ini:3: memory.bytes_per_cycle: 'fast' is not an integer" "$WORK/e" || fail "bad value: $(cat "$WORK/e")"
    printf '[raster]\nboards = 65\n' >"$WORK/range.ini"
    "$FRAGSIM" replay --mode cycle --config "$WORK/range.ini" --out "$WORK/o" "$t" 2>"$WORK/e"
    [ $? -eq 2 ] || fail "out of range: expected exit 2"
    grep -q "range.ini:2: raster.boards: 65 is out of range \[1, 64\]" "$WORK/e" || fail "range: $(cat "$WORK/e")"
    printf '[memory]\nprefetch = maybe\n' >"$WORK/bool.ini"
    "$FRAGSIM" replay --mode cycle --config "$WORK/bool.ini" --out "$WORK/o" "$t" 2>"$WORK/e"
    grep -q "bool.ini:2: memory.prefetch: 'maybe' is not a boolean" "$WORK/e" || fail "bool: $(cat "$WORK/e")"
    "$FRAGSIM" replay --mode cycle --set fragment.interleave=3 --out "$WORK/o" "$t" 2>"$WORK/e"
    grep -q "fragment.interleave: 3 is not even" "$WORK/e" || fail "interleave: $(cat "$WORK/e")"
    "$FRAGSIM" replay --mode cycle --set texture.cache_ways=3 --out "$WORK/o" "$t" 2>"$WORK/e"
    grep -q "texture.cache_ways: 3 is not a power of two" "$WORK/e" || fail "ways: $(cat "$WORK/e")"
    "$FRAGSIM" replay --mode turbo --out "$WORK/o" "$t" 2>"$WORK/e"
    [ $? -eq 2 ] || fail "bad mode: expected exit 2"
    grep -q "expected functional, cycle or sampled" "$WORK/e" || fail "mode: $(cat "$WORK/e")"
}

test_default_ini() {
    "$FRAGSIM" config --defaults | cmp -s - "$ROOT/configs/default.ini" ||
        fail "configs/default.ini differs from \`fragsim config --defaults\`"
    local t; t=$(scene_trace demo) || fail "scenegen failed"
    # the defaults file reads back to the built-in defaults: same cycles.
    # --threads 1: the CLI's own default is 0 (the online CPUs), the
    # library's is 1, which default.ini holds (raster.threads).
    "$FRAGSIM" replay --quiet --mode cycle --threads 1 --out "$WORK/d1" "$t" 2>/dev/null || fail "replay failed"
    "$FRAGSIM" replay --quiet --mode cycle --config "$ROOT/configs/default.ini" --out "$WORK/d2" "$t" 2>/dev/null ||
        fail "replay with default.ini failed"
    diff "$WORK/d1/stats.json" "$WORK/d2/stats.json" >/dev/null || fail "default.ini is not the defaults"
}

# Every key of the machine configurations says where its value comes from
# (issue 21: sourced, or labelled assumed), in the comment above it; and
# docs/config.md's tables of them are current.
test_config_sources() {
    local ini
    for ini in "$ROOT/configs/o2.ini" "$ROOT/configs/infinite_reality.ini"; do
        # (keys right below one another share the comment above the first)
        awk '/^;/ { c = c " " $0; next }
             /^[a-z_]+ *=/ { if (c == "") c = last
                             if (c !~ /(source|assumed|chosen)/) { print FILENAME ": " $0; bad = 1 }
                             last = c; c = ""; next }
             { c = ""; last = "" }
             END { exit bad }' "$ini" || fail "a key without its source or 'assumed' above it"
        local name; name=$(basename "$ini")
        awk -v f="configs/$name" '$0 == "## " f ": where the values come from" { found = 1 } END { exit !found }' \
            "$ROOT/docs/config.md" || fail "docs/config.md has no table for $name (scripts/gen_docs.sh)"
        # each key's row carries the INI's value
        awk '/^\[/ { sec = substr($0, 2, index($0, "]") - 2) } /^[a-z_]+ *=/ { k = $0; sub(/ *=.*/, "", k)
             v = $0; sub(/^[^=]*= */, "", v); print "| " sec "." k " | " v " |" }' "$ini" >"$WORK/rows"
        while IFS= read -r row; do
            grep -qF "$row" "$ROOT/docs/config.md" || fail "docs/config.md is stale for $name: no row '$row'"
        done <"$WORK/rows"
    done
}

test_stats_list() {
    "$FRAGSIM" stats --list >"$WORK/l" || fail "stats --list failed"
    for k in cycles fragment_busy occlusion_stalled texture_idle raster_fifo_hwm tex_cache_hit_permille query_latency; do
        grep -q "^ *$k " "$WORK/l" || fail "stats --list does not explain $k"
    done
}

test_sampled_error() {
    # Multi-frame scenes: frame sampling; the one-frame bench scenes: tile
    # sampling.  The oracle is full cycle mode.  Speed-ups are printed as a
    # report only (the machine is shared; docs/performance.md has the
    # measured table).
    for s in city norwich cathedrals forest garbage terrain demo textured bench8 bench32; do
        local t fr=21
        case $s in bench*) fr= ;; esac
        t=$(scene_trace "$s" $fr) || fail "scenegen $s failed"
        # The one-frame bench scenes at the benchmark's scale (100000
        # triangles, 0.1 s in cycle mode): at small scale a one-in-16 tile
        # sample holds a few dozen tiles, too few for 2%.
        case $s in bench*)
            t="$WORK/${s}_100000.trace"
            [ -f "$t" ] || "$SCENEGEN" "$s" --scale 100000 -o "$t" >/dev/null || fail "scenegen $s failed" ;;
        esac
        local full samp
        full=$("$FRAGSIM" bench --mode cycle --config "$ROOT/configs/o2.ini" "$t")
        samp=$("$FRAGSIM" bench --mode sampled --config "$ROOT/configs/o2.ini" "$t")
        local a b ta tb
        a=$(echo "$full" | sed -nE 's/.*"cycles": ([0-9]+).*/\1/p')
        b=$(echo "$samp" | sed -nE 's/.*"cycles": ([0-9]+).*/\1/p')
        ta=$(echo "$full" | sed -nE 's/.*"seconds": ([0-9.eE+-]+).*/\1/p')
        tb=$(echo "$samp" | sed -nE 's/.*"seconds": ([0-9.eE+-]+).*/\1/p')
        [ -n "$a" ] && [ -n "$b" ] || fail "$s: no cycles"
        # Going through the decoded calls alone (bench's ceiling column) is
        # a part of a cycle-mode replay, so it must take less time than the
        # whole; loading the trace is timed apart and takes some time.
        local td tl
        td=$(echo "$full" | sed -nE 's/.*"floor_seconds": ([0-9.eE+-]+).*/\1/p')
        tl=$(echo "$full" | sed -nE 's/.*"load_seconds": ([0-9.eE+-]+).*/\1/p')
        awk -v td="$td" -v ta="$ta" -v tl="$tl" 'BEGIN { exit !(td > 0 && td < ta && tl > 0) }' ||
            fail "$s: floor_seconds $td not within (0, $ta), the cycle-mode replay's seconds, or load_seconds $tl not > 0"
        awk -v s="$s" -v a="$a" -v b="$b" -v ta="$ta" -v tb="$tb" 'BEGIN {
            printf "    sampled %-10s error %+.2f%%, speed-up %.1fx (report only)\n", s, 100 * (b - a) / a, (tb > 0 ? ta / tb : 0) }'
        # Within its own estimate (a 95% interval) and, with sampling.max_error's
        # passes (default 2%), within 2%.
        local est
        est=$(echo "$samp" | sed -nE 's/.*"error_estimate": ([0-9.eE+-]+).*/\1/p')
        # bench32 (one frame: tile and draw sampling): +1.18% against an
        # estimate of 1.08% (tiles 1.04%, draws 0.31%), within 2% but just
        # outside its interval; the cause (the ratio estimator's variance
        # or a bias of the filled draws' line) is not measured yet.  Listed:
        # fails when bench32 comes within its estimate.
        if [ "$s" = bench32 ]; then
            awk -v a="$a" -v b="$b" -v m="$est" 'BEGIN { e = (b - a) / a; if (e < 0) e = -e; exit !(e > m && e <= 0.02) }' ||
                fail "bench32: sampled $b vs full $a, estimate $est: now within its estimate (take it off the known list) or beyond 2%"
            continue
        fi
        awk -v a="$a" -v b="$b" -v m="$est" 'BEGIN { e = (b - a) / a; if (e < 0) e = -e; exit !(e <= m && m <= 0.02) }' ||
            fail "$s: sampled $b vs full $a cycles: outside the estimate $est or the estimate above 2%"
        # textured, one pass (--max-error 0): tile sampling inside the
        # simulated frames is biased on this textured scene, -3.2%
        # (sampling.frame_tiles 2-16: -3% to -6.5%; 1: +0.09%), a bias no
        # estimate from the sample's variance shows; the passes of
        # --max-error 2 turn frame_tiles off.  Listed until the sampler's bias
        # is fixed (issue 24): fails when textured comes within 2% in one pass.
        if [ "$s" = textured ]; then
            b=$("$FRAGSIM" bench --mode sampled --max-error 0 --config "$ROOT/configs/o2.ini" "$t" |
                sed -nE 's/.*"cycles": ([0-9]+).*/\1/p')
            awk -v a="$a" -v b="$b" 'BEGIN { e = (b - a) / a; if (e < 0) e = -e; exit !(e > 0.02) }' ||
                fail "textured: one pass of sampled mode is now within 2% of full cycle mode: take it off the known list"
        fi
    done
}

test_max_error() {
    # sampling.max_error (--max-error P): a scene whose first pass reports
    # more than P is replayed with denser sampling; the statistics say so,
    # the final estimate is within P and the error within the estimate
    # (oracle: full cycle mode).  A bound sampling cannot meet ends in full
    # simulation, said on stderr and in the JSON, with full mode's cycles.
    local t; t=$(scene_trace forest 21) || fail "scenegen failed"
    local cfg="$ROOT/configs/o2.ini"
    "$FRAGSIM" replay --mode cycle --config "$cfg" --out "$WORK/me_full" "$t" >/dev/null 2>&1 || fail "cycle mode failed"
    for p in 0 2 0.01; do
        "$FRAGSIM" replay --mode sampled --max-error $p --config "$cfg" --out "$WORK/me_$p" "$t" >/dev/null \
            2>"$WORK/me_$p.err" || fail "--max-error $p failed: $(cat "$WORK/me_$p.err")"
    done
    /usr/bin/python3 - "$WORK" <<'PY' || fail "--max-error: the statistics do not hold"
import json, sys
w = sys.argv[1]
full = json.load(open(w + '/me_full/stats.json'))['cycle']['totals']['cycles']
one, two, tiny = (json.load(open('%s/me_%s/stats.json' % (w, p)))['cycle'] for p in ("0", "2", "0.01"))
err = lambda c: abs(c['totals']['cycles'] - full) / full
assert not one['max_error']['resampled'] and len(one['max_error']['passes']) == 1, one['max_error']
assert one['error_estimate'] > 0.02, ('the first pass must be above 2%% for this test', one['error_estimate'])
m = two['max_error']
assert m['resampled'] and m['met'] and not m['cannot_by_sampling'] and m['bound'] == 0.02, m
assert m['passes'][0]['error_estimate'] > 0.02 and two['error_estimate'] <= 0.02, m
assert err(two) <= two['error_estimate'], (err(two), two['error_estimate'])
assert err(one) <= one['error_estimate'], (err(one), one['error_estimate'])
m = tiny['max_error']
assert m['cannot_by_sampling'] and m['met'] and tiny['totals']['cycles'] == full, (m, tiny['totals']['cycles'], full)
PY
    grep -q "passes, estimates" "$WORK/me_2.err" || fail "--max-error 2: no passes line: $(cat "$WORK/me_2.err")"
    grep -q "cannot meet --max-error 0.01% by sampling: simulated in full" "$WORK/me_0.01.err" ||
        fail "--max-error 0.01: did not say it cannot: $(cat "$WORK/me_0.01.err")"
    for bad in -1 101 x 2%; do
        "$FRAGSIM" replay --mode sampled --max-error "$bad" --out "$WORK/me_bad" "$t" >/dev/null 2>"$WORK/e" &&
            fail "--max-error $bad accepted"
        grep -q "expected a percentage" "$WORK/e" || fail "--max-error $bad: $(cat "$WORK/e")"
    done
}

test_bench_repetitions_start_fresh() {
    # A trimmed capture need not restore the state it found (rubik ends with
    # its matrices pushed): every repetition of bench replays on a fresh
    # context, so --repeat 3 gives replay's cycles and three times its
    # fragments.  The oracle is `fragsim replay` of the same trace.
    local t="$ROOT/tests/conformance/programs/rubik.trace" one three a b fr
    [ -f "$t" ] || skip "no rubik trace"
    "$FRAGSIM" replay --mode cycle --config "$ROOT/configs/o2.ini" --out "$WORK/rb" --csv "$WORK/rb.csv" "$t" \
        >/dev/null 2>&1 || fail "replay failed"
    a=$(awk -F, 'NR == 1 { for (i = 1; i <= NF; i++) if ($i == "cycles") k = i } $1 == "total" { print $k }' "$WORK/rb.csv")
    fr=$(/usr/bin/python3 -c "import json; print(json.load(open('$WORK/rb/stats.json'))['totals']['fragments_generated'])")
    three=$("$FRAGSIM" bench --mode cycle --config "$ROOT/configs/o2.ini" --repeat 3 "$t") || fail "bench failed"
    b=$(echo "$three" | sed -nE 's/.*"cycles": ([0-9]+).*/\1/p')
    [ "$b" = "$a" ] || fail "bench --repeat 3: $b cycles, replay: $a"
    echo "$three" | grep -q "\"fragments\": $((3 * fr))," || fail "bench --repeat 3: not 3 x $fr fragments: $three"
}

test_short_trace_simulated_in_full() {
    # A 4-frame capture is too short to sample (docs/cycle_model.md): sampled
    # mode says so on stderr and in the statistics, and its cycles are full
    # cycle mode's; a 21-frame scene is sampled (the key false).
    local t="$ROOT/tests/conformance/programs/rubik.trace" a b
    [ -f "$t" ] || skip "no rubik trace"
    for m in cycle sampled; do
        "$FRAGSIM" replay --mode $m --config "$ROOT/configs/o2.ini" --out "$WORK/st_$m" --csv "$WORK/st_$m.csv" "$t" \
            >/dev/null 2>"$WORK/st_$m.err" || fail "replay --mode $m failed"
    done
    grep -q "too few to sample" "$WORK/st_sampled.err" || fail "sampled mode did not say: $(cat "$WORK/st_sampled.err")"
    a=$(awk -F, '$1 == "total" { print $7 }' "$WORK/st_cycle.csv")
    b=$(awk -F, '$1 == "total" { print $7 }' "$WORK/st_sampled.csv")
    [ -n "$a" ] && [ "$a" = "$b" ] || fail "sampled $b cycles, full $a"
    /usr/bin/python3 -c "import json, sys; sys.exit(json.load(open('$WORK/st_sampled/stats.json'))['cycle']['too_short_to_sample'] is not True)" ||
        fail "stats.json: too_short_to_sample is not true"
    local long; long=$(scene_trace cathedrals 21) || fail "scenegen failed"
    "$FRAGSIM" replay --mode sampled --config "$ROOT/configs/o2.ini" --out "$WORK/st_long" "$long" >/dev/null 2>&1 ||
        fail "replay of the scene failed"
    /usr/bin/python3 -c "import json, sys; sys.exit(json.load(open('$WORK/st_long/stats.json'))['cycle']['too_short_to_sample'] is not False)" ||
        fail "stats.json of a 21-frame scene: too_short_to_sample is not false"
}

run_test test_cycle_identical_o2
run_test test_cycle_identical_ir
run_test test_config_errors
run_test test_default_ini
run_test test_config_sources
run_test test_stats_list
run_test test_sampled_error
run_test test_max_error
run_test test_bench_repetitions_start_fresh
run_test test_short_trace_simulated_in_full
finish
