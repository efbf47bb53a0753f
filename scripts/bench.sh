#!/bin/bash
# `make bench`: the throughput benchmark.  Renders the same traces with the
# fragsim model, OSMesa llvmpipe (LP_NUM_THREADS=1) and OSMesa softpipe
# (GALLIUM_DRIVER=softpipe) in one run, prints fragments per second and the
# ratios; then the cycle-level model in functional, full cycle and sampled
# mode on the scene corpus; and regenerates docs/performance.md from the
# numbers it measured.
# Not a test: nothing here passes or fails on speed.
# BENCH_QUICK=1: one run each, the first 3 corpus programs, no softpipe, cycle
# or unused-unit sections, and the page goes to $OUT/performance.md (not docs/)
# unless BENCH_DOC says otherwise: a check that the script works, not numbers.
set -euo pipefail
BUILD=${1:-build}
QUICK=${BENCH_QUICK:-0}
if [ "$QUICK" = 1 ]; then REPEAT=1; fi
REPEAT=${REPEAT:-5}
OUT=${BENCH_OUT:-$BUILD/bench}
if [ "$QUICK" = 1 ]; then DOC=${BENCH_DOC:-$OUT/performance.md}; else DOC=${BENCH_DOC:-docs/performance.md}; fi
mkdir -p "$OUT"
json() { sed -nE -e "s/.*\"$2\": \"([^\"]*)\".*/\1/p" -e t -e "s/.*\"$2\": ([^,}]*).*/\1/p" <<<"$1"; }
# run_rss FILE CMD...: CMD's stdout, its peak resident set (KB, the whole
# process: the untimed first replay and the timed ones) into FILE.
run_rss() { local f=$1; shift; /usr/bin/time -f '%M' -o "$f" "$@"; }

# ---- the conformance corpus's real programs (tests/conformance/programs) ----
# fragsim bench --engine osmesa is the llvmpipe side: fragsim's trace decoder
# (outside the timed part: load_seconds) feeding libOSMesa from C, so no
# python replay overhead is timed.  LP_NUM_THREADS=1 and llvmpipe's default.
progs=(tests/conformance/programs/*.trace)
if [ "$QUICK" = 1 ]; then progs=("${progs[@]:0:3}"); fi
prows=()
logsum1=0 logsumN=0 nprog=0
for trace in "${progs[@]}" bench8 bench32; do
    case $trace in bench*) name=$trace; trace="$OUT/$name.trace"
        "$BUILD/scenegen" "$name" --scale paper -o "$trace" >/dev/null ;;
        *) name=$(basename "$trace" .trace) ;; esac
    m1=$(run_rss "$OUT/rss_m1" "$BUILD/fragsim" bench --engine model --threads 1 --repeat "$REPEAT" "$trace")
    m=$(run_rss "$OUT/rss_m" "$BUILD/fragsim" bench --engine model --repeat "$REPEAT" "$trace")
    l1=$(LP_NUM_THREADS=1 run_rss "$OUT/rss_1" "$BUILD/fragsim" bench --engine osmesa --repeat "$REPEAT" "$trace")
    lN=$(run_rss "$OUT/rss_n" "$BUILD/fragsim" bench --engine osmesa --repeat "$REPEAT" "$trace")
    row=$(awk -v s="$name" -v fr="$(json "$m" frames)" -v r="$REPEAT" -v tm="$(json "$m" seconds)" \
        -v tm1="$(json "$m1" seconds)" -v t1="$(json "$l1" seconds)" -v tn="$(json "$lN" seconds)" \
        -v mm="$(tail -n 1 "$OUT/rss_m")" -v m1="$(tail -n 1 "$OUT/rss_1")" -v mn="$(tail -n 1 "$OUT/rss_n")" 'BEGIN {
        printf "| %s | %d | %.4f | %.4f | %.4f | %.4f | %.2f | %.2f | %.1f | %.1f | %.1f |", s, fr / r, tm1 / r, tm / r,
            t1 / r, tn / r, tm1 / t1, tm / tn, mm / 1024, m1 / 1024, mn / 1024 }')
    prows+=("$row")
    echo "$row"
    read -r a b < <(awk -v tm="$(json "$m" seconds)" -v tm1="$(json "$m1" seconds)" -v t1="$(json "$l1" seconds)" \
        -v tn="$(json "$lN" seconds)" 'BEGIN { print log(tm1 / t1), log(tm / tn) }')
    logsum1=$(awk -v x="$logsum1" -v y="$a" 'BEGIN { print x + y }')
    logsumN=$(awk -v x="$logsumN" -v y="$b" 'BEGIN { print x + y }')
    nprog=$((nprog + 1))
done
geo=$(awk -v a="$logsum1" -v b="$logsumN" -v n="$nprog" 'BEGIN { printf "fragsim 1 thread %.2f x llvmpipe 1 thread, fragsim default threads %.2f x llvmpipe default threads", exp(a / n), exp(b / n) }')
echo "geometric mean of fragsim / llvmpipe time over $nprog traces: $geo"

rows=() crows=() unused="not measured (BENCH_QUICK=1)"
llvm='{"renderer": "not run"}' soft=$llvm
[ "$QUICK" = 1 ] || for scene in bench8 bench32; do
    trace="$OUT/$scene.trace"
    "$BUILD/scenegen" "$scene" --scale paper -o "$trace" >/dev/null
    model=$("$BUILD/fragsim" bench --engine model --repeat "$REPEAT" "$trace")
    llvm=$(LP_NUM_THREADS=1 "$BUILD/fragsim" bench --engine osmesa --repeat "$REPEAT" "$trace")
    soft=$(GALLIUM_DRIVER=softpipe "$BUILD/fragsim" bench --engine osmesa --repeat "$REPEAT" "$trace")
    frags=$(json "$model" fragments)
    tm=$(json "$model" seconds); tl=$(json "$llvm" seconds); ts=$(json "$soft" seconds)
    row=$(awk -v s="$scene" -v f="$frags" -v tm="$tm" -v tl="$tl" -v ts="$ts" 'BEGIN {
        printf "| %s | %.0f | %.1f | %.1f | %.1f | %.2f | %.1f |", s, f / '"$REPEAT"',
            f / tm / 1e6, f / tl / 1e6, f / ts / 1e6, tl / tm, ts / tm }')
    rows+=("$row")
    echo "$row"
done
# ---- the cycle-level model: functional vs full cycle vs sampled mode ----
# CYCLE_REPEAT runs each, configs/o2.ini ("cycles" in bench's JSON is per
# run; seconds, frames and fragments add up over the runs).  city at paper scale (the
# requirement: >= 10 M simulated cycles per second), the other scenes at
# CYCLE_SCALE triangles per frame (512x512) to keep the run short; every
# scene but the one-frame bench traces with CYCLE_FRAMES frames.
CYCLE_REPEAT=${CYCLE_REPEAT:-3}
CYCLE_SCALE=${CYCLE_SCALE:-100000}
CYCLE_FRAMES=${CYCLE_FRAMES:-20}
CFG=configs/o2.ini
[ "$QUICK" = 1 ] || for scene in city norwich cathedrals forest garbage terrain demo textured bench8 bench32; do
    trace="$OUT/cycle_$scene.trace"
    case $scene in city) scale=paper ;; demo|textured) scale=small ;; *) scale=$CYCLE_SCALE ;; esac
    frames=(); case $scene in bench*) ;; *) frames=(--frames "$CYCLE_FRAMES") ;; esac
    "$BUILD/scenegen" "$scene" --scale "$scale" "${frames[@]}" -o "$trace" >/dev/null
    fun=$("$BUILD/fragsim" bench --mode functional --config "$CFG" --repeat "$CYCLE_REPEAT" "$trace")
    cyc=$("$BUILD/fragsim" bench --mode cycle --config "$CFG" --repeat "$CYCLE_REPEAT" "$trace")
    smp=$("$BUILD/fragsim" bench --mode sampled --config "$CFG" --repeat "$CYCLE_REPEAT" "$trace")
    row=$(awk -v s="$scene" -v sc="$scale" -v fr="$(json "$cyc" frames)" -v r="$CYCLE_REPEAT" \
        -v tf="$(json "$fun" seconds)" -v tc="$(json "$cyc" seconds)" -v ts="$(json "$smp" seconds)" \
        -v cc="$(json "$cyc" cycles)" -v cs="$(json "$smp" cycles)" -v fg="$(json "$cyc" fragments)" \
        -v ee="$(json "$smp" error_estimate)" -v td="$(json "$smp" floor_seconds)" -v tl="$(json "$smp" load_seconds)" 'BEGIN {
        printf "| %s | %s | %d | %.3f | %.3f | %.3f | %.3f | %.3f | %.0f | %.1f | %.1f | %.1f | %.1f | %.0f | %.1f | %+.2f%% | %.2f%% |", s, sc, fr / r, tf / r, tc / r, ts / r, tl / r, td / r,
            cc, cc * r / tc / 1e6, fg / tf / 1e6, fg / tc / 1e6, tc / ts, tc / td, (tc + tl) / (ts + tl), 100 * (cs - cc) / cc, 100 * ee }')
    crows+=("$row")
    echo "$row"
done
# What an unused unit costs: city (no texturing, Occlusion Unit idle) in cycle
# mode with and without texture units and Occlusion Units; best of 5 each,
# interleaved so that load on the machine hits both alike.
if [ "$QUICK" != 1 ]; then
trace="$OUT/cycle_city.trace"
{ cat "$CFG"; printf '[texture]\npresent = false\n[occlusion]\npresent = false\n'; } >"$OUT/o2_without.ini"
best_with=999999 best_without=999999
for i in 1 2 3 4 5; do
    a=$(json "$("$BUILD/fragsim" bench --mode cycle --config "$CFG" "$trace")" seconds)
    b=$(json "$("$BUILD/fragsim" bench --mode cycle --config "$OUT/o2_without.ini" "$trace")" seconds)
    best_with=$(awk -v x="$a" -v y="$best_with" 'BEGIN { print (x < y ? x : y) }')
    best_without=$(awk -v x="$b" -v y="$best_without" 'BEGIN { print (x < y ? x : y) }')
done
unused=$(awk -v a="$best_with" -v b="$best_without" 'BEGIN { printf "%.3f s with, %.3f s without: %+.1f%%", a, b, 100 * (a - b) / b }')
echo "unused units: $unused"
fi

llvm_name=$(json "$llvm" renderer)
soft_name=$(json "$soft" renderer)
cpu=$(sed -nE 's/^model name\s*: (.*)/\1/p' /proc/cpuinfo | head -n 1)
{
    echo "# Performance"
    echo
    echo "Generated by \`make bench\` (scripts/bench.sh); do not edit by hand."
    echo "Each trace is replayed $REPEAT times per engine, in separate processes, on one core"
    echo "of: ${cpu:-unknown CPU}.  Fragments are those the model's rasterizer generates (the"
    echo "same work for every engine); rates are fragments per second of replay time."
    echo
    echo "## Real programs: the conformance corpus against llvmpipe"
    echo
    echo "\`fragsim bench --engine model|osmesa --repeat $REPEAT\` on each program trace of"
    echo "tests/conformance/programs and on bench8/bench32; seconds per run, of the replay from the"
    echo "decoded calls (decoding is outside, the same C decoder for both engines, so no Python"
    echo "replayer overhead).  llvmpipe through libOSMesa with LP_NUM_THREADS=1 and with its"
    echo "default thread count ($(nproc) CPUs here).  Ratio: fragsim time / llvmpipe time (above 1:"
    echo "fragsim slower).  Peak memory: maximum resident set of the whole process"
    echo "(/usr/bin/time), the untimed first replay included.  fragsim 1T: \`--threads 1\`;"
    echo "fragsim: its default (\`--threads 0\`, the online CPUs; docs/architecture.md, Threads)."
    echo
    echo "| trace | frames | fragsim 1T s | fragsim s | llvmpipe 1T s | llvmpipe s | fragsim 1T / llvmpipe 1T | fragsim / llvmpipe | fragsim MB | llvmpipe 1T MB | llvmpipe MB |"
    echo "|---|---|---|---|---|---|---|---|---|---|---|"
    printf '%s\n' "${prows[@]}"
    echo
    echo "Geometric mean over the $nprog traces: $geo."
    echo
    echo "## Synthetic throughput: fragsim, llvmpipe and softpipe"
    echo
    echo "| trace | fragments per frame | fragsim M frag/s | llvmpipe M frag/s | softpipe M frag/s | fragsim / llvmpipe | fragsim / softpipe |"
    echo "|---|---|---|---|---|---|---|"
    printf '%s\n' "${rows[@]}"
    echo
    echo "llvmpipe: \`$llvm_name\` with LP_NUM_THREADS=1; softpipe: \`$soft_name\`."
    echo "bench8 and bench32 are ~100,000 triangles of ~8 and ~32 pixels at 1024x1024"
    echo "(\`scenegen --list\`)."
    echo
    echo "## Cycle-level model: functional, full cycle and sampled mode"
    echo
    echo "\`fragsim bench --mode functional|cycle|sampled --config $CFG\` per trace, one process each,"
    echo "$CYCLE_REPEAT run(s); times are per run.  Full cycle mode runs the functional model and the"
    echo "timing model (same images and counters as functional mode); sampled mode (default"
    echo "\`[sampling]\` keys) simulates one frame in sampling.frames plus the last of the 20-frame"
    echo "traces, rasterizing one screen tile in sampling.frame_tiles of them, and one tile in"
    echo "sampling.tiles of the one-frame traces, and estimates the rest without rendering it"
    echo "(docs/cycle_model.md).  Error: sampled mode's total cycles"
    echo "against full cycle mode's; estimate: the error sampled mode reports for itself."
    echo "Times are of the replay from the decoded calls.  Load s: opening the trace, which"
    echo "decodes and validates it and keeps the decoded calls, the same for every mode and"
    echo "not in the other times (\`load_seconds\`); floor s: going through the decoded calls"
    echo "without executing them (\`floor_seconds\`); ceiling: cycle s / floor s, the speed-up"
    echo "a sampled mode that simulated nothing would reach; with load: the speed-up of the"
    echo "whole replay, load included, (cycle s + load s) / (sampled s + load s)."
    echo
    echo "| trace | scale | frames | functional s | cycle s | sampled s | load s | floor s | cycles | M cycles/s (cycle) | M frag/s (functional) | M frag/s (cycle) | sampled speed-up | ceiling | speed-up with load | sampled error | error estimate |"
    echo "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"
    printf '%s\n' "${crows[@]}"
    echo
    echo "An unused unit (city has no texturing and leaves the Occlusion Unit idle), cycle mode with"
    echo "texture units and Occlusion Units against a configuration without them (texture.present,"
    echo "occlusion.present = false), best of 5: $unused."
} >"$DOC"
echo "wrote $DOC"
