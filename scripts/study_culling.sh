#!/bin/bash
# `make study-culling`: the culling experiments of Huettner 1999, sec. 3.1.9
# (Tables 3.2-3.4, Figs. 3.8-3.11) rerun in simulated cycles (issue 21,
# item 6).  Every run is build/cullstudy (the model, through the shim) at
# 650x650 along the scene's path, captured with FRAGSIM_TRACE and replayed
# in the cycle model with three configurations: configs/o2.ini, the same
# with the O2's geometry rate the dissertation measured (O2_TRI_CYCLES, see
# below), and configs/infinite_reality.ini; scripts/study_culling.py then
# writes docs/studies/culling.md and its plots.
#   FRAMES (default 10)  frames along each path (the dissertation: about 100)
#   SCALE (default paper), JOBS (default 2), STUDY_OUT (default out/study-culling)
# Large outputs (captures, frames, statistics) stay in STUDY_OUT (git-ignored).
set -euo pipefail
BUILD=${1:-build}
FRAMES=${FRAMES:-10}
SCALE=${SCALE:-paper}
JOBS=${JOBS:-2}
OUT=${STUDY_OUT:-out/study-culling}
DOC=${STUDY_DOC:-docs/studies/culling.md}
FIG=${STUDY_FIG:-docs/studies}
for b in "$BUILD/cullstudy" "$BUILD/fragsim"; do
    [ -x "$b" ] || { echo "study_culling: no $b (make all)" >&2; exit 2; }
done
command -v parallel >/dev/null || { echo "study_culling: needs GNU parallel (apt-get install parallel)" >&2; exit 2; }
rm -rf "$OUT"
mkdir -p "$OUT"
# The O2 draws with its CPU doing the geometry (configs/o2.ini: "assumed"
# 6 cycles a vertex, 4 a triangle).  Huettner 1999, sec. 3.1.9, measured
# the city on the O2: V+O at "almost two frames per second", "a speed-up of
# about eight against view-frustum culling only", so VFC only at about
# 0.25 fps, while VFC culled "3.9% up to 39.9%" of the 1,056,280 triangles
# (78% drawn at the middle of that range): 824,000 triangles in 4 s, 206,000
# a second, 320 cycles of the 66 MHz clock per triangle.
O2_TRI_CYCLES=${O2_TRI_CYCLES:-320}

# One run: SCENE METHOD HIERARCHY -> OUT/SCENE/METHOD-HIERARCHY/{culling.csv,o2.json,ir.json}.
# VFC goes through GL selection mode, as the dissertation's (sec. 3.1.6);
# occlusion tests are GL 1.5 queries (NOHC).
run_one() {
    local scene=$1 method=$2 hier=$3 dir="$OUT/$1/$2-$3"
    mkdir -p "$dir"
    local sel=(); [ "$method" != dr ] && sel=(--vfc-select)
    FRAGSIM_TRACE="$dir/capture.trace" "$BUILD/cullstudy" --scene "$scene" --scale "$SCALE" --method "$method" \
        --hierarchy "$hier" --frames "$FRAMES" --size 650x650 "${sel[@]}" --out "$dir" >"$dir/cullstudy.log"
    local c
    for c in o2 o2_h99 infinite_reality; do
        local ini=configs/$c.ini set=()
        [ "$c" = o2_h99 ] && ini=configs/o2.ini set=(--set "setup.cycles_per_triangle=$O2_TRI_CYCLES")
        "$BUILD/fragsim" replay --mode cycle --config "$ini" "${set[@]}" --stats "$dir/$c.json" --out "$dir/frames_$c" \
            "$dir/capture.trace" >/dev/null 2>"$dir/replay_$c.log"
        rm -rf "$dir/frames_$c"
    done
    rm -f "$dir/capture.trace" "$dir"/frame_*.png
}
export -f run_one
export BUILD FRAMES SCALE OUT O2_TRI_CYCLES

{
    for s in cathedrals city forest garbage; do
        for m in dr vfc vo; do echo "$s $m phbvo"; done
    done
    echo "forest ac phbvo"
    for m in dr vfc shadow pvs; do echo "norwich $m phbvo"; done # the seeds' city workloads (item 5)
    for s in cathedrals city; do
        for h in dbvs sgi; do
            for m in vfc vo; do echo "$s $m $h"; done
        done
    done
} >"$OUT/jobs.txt"
t0=$(date +%s)
parallel -j "$JOBS" --colsep ' ' --halt now,fail=1 run_one {1} {2} {3} <"$OUT/jobs.txt"
t1=$(date +%s)
# The children's user + system seconds (bash's times: the second line).
# times must run in this shell: inside $(...) it reports the subshell's
# children, which are none.
times >"$OUT/times.txt"
cpu=$(tail -n 1 "$OUT/times.txt" | awk '{ n = 0; for (i = 1; i <= 2; i++) { split($i, p, /[ms]/); n += p[1] * 60 + p[2] } printf "%d", n }')
/usr/bin/python3 scripts/study_culling.py --out "$OUT" --doc "$DOC" --fig "$FIG" --frames "$FRAMES" \
    --scale "$SCALE" --seconds $((t1 - t0)) --cpu-seconds "$cpu" --jobs "$JOBS" --o2-tri-cycles "$O2_TRI_CYCLES"
echo "study_culling: $DOC regenerated in $((t1 - t0)) s ($(wc -l <"$OUT/jobs.txt") runs, $FRAMES frames each)"
