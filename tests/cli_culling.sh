#!/bin/bash
# The culling study's program (traces/culling/, issue 21): build/cullstudy on
# the model (the shim) and build/cullstudy-osmesa on libOSMesa, the four
# scenes of Table 3.1 at small scale, a few frames.  Culling with exact tests is conservative (Huettner 1999,
# sec. 3.1.6), so every method's images must equal DR's at tolerance 0, on
# both libraries; the query methods must make the same decisions and images
# on the model as on llvmpipe.
. "$(dirname "$0")/lib_cli.sh"
: "${FRAGSIM:?}" "${FRAGSIM_BUILD:?}"
SHIMBIN="$FRAGSIM_BUILD/cullstudy"
OSMBIN="$FRAGSIM_BUILD/cullstudy-osmesa"
FRAMES=3
SIZE=160x160

run_cull() { # BINARY NAME ARGS... -> $WORK/NAME
    local bin=$1 name=$2; shift 2
    [ -x "$bin" ] || fail "no $bin (make cullstudy)"
    "$bin" --frames $FRAMES --size $SIZE --out "$WORK/$name" "$@" >"$WORK/$name.out" 2>"$WORK/$name.err" ||
        fail "$name: exit $?: $(cat "$WORK/$name.err")"
}

same_images() { # DIR_A DIR_B
    for f in $(seq 0 $((FRAMES - 1))); do
        local n; n=$(printf 'frame_%04d.png' "$f")
        [ -f "$1/$n" ] && [ -f "$2/$n" ] || fail "missing $n in $1 or $2"
        "$FRAGSIM" diff "$1/$n" "$2/$n" >"$WORK/diff.txt" 2>&1 || fail "$2/$n differs from $1/$n: $(tail -n 3 "$WORK/diff.txt")"
    done
}

col_sum() { # CSV COLUMN_NAME -> the column's sum
    awk -F, -v c="$2" 'NR == 1 { for (i = 1; i <= NF; i++) if ($i == c) k = i; next } { s += $k } END { print s + 0 }' "$1"
}

SCENES="city cathedrals forest garbage"

# Every method and test, every scene (garbage: leaf-only tests, its default).
test_methods_identical_to_dr_on_the_model() {
    for sc in $SCENES; do
        run_cull "$SHIMBIN" "m_${sc}_dr" --scene "$sc" --method dr
        for spec in "vfc query" "vfc query --vfc-select" "vo query" "ac query" "cac query" "vo stencil" \
                    "vo hp" "vo brief" "vo query --vfc-select"; do
            set -- $spec
            run_cull "$SHIMBIN" "m_${sc}_$1_$2${3:-}" --scene "$sc" --method "$1" --test "$2" ${3:-}
            same_images "$WORK/m_${sc}_dr" "$WORK/m_${sc}_$1_$2${3:-}"
        done
    done
}

test_methods_identical_to_dr_on_osmesa() {
    for sc in $SCENES; do
        run_cull "$OSMBIN" "o_${sc}_dr" --scene "$sc" --method dr
        for spec in "vfc query" "vfc query --vfc-select" "vo query" "ac query" "cac query" "vo stencil"; do
            set -- $spec
            run_cull "$OSMBIN" "o_${sc}_$1_$2${3:-}" --scene "$sc" --method "$1" --test "$2" ${3:-}
            same_images "$WORK/o_${sc}_dr" "$WORK/o_${sc}_$1_$2${3:-}"
        done
    done
}

# The same decisions on both libraries, and the same images (every scene
# since glPushMatrix analyses the matrix it copies, as Mesa does:
# pipeline/matrix.c).
test_query_methods_model_equals_osmesa() {
    for sc in $SCENES; do
        for spec in "dr query" "vo query" "vo stencil" "vfc query --vfc-select"; do
            set -- $spec
            run_cull "$SHIMBIN" "s_${sc}_$1_$2${3:-}" --scene "$sc" --method "$1" --test "$2" ${3:-}
            run_cull "$OSMBIN" "l_${sc}_$1_$2${3:-}" --scene "$sc" --method "$1" --test "$2" ${3:-}
            diff "$WORK/l_${sc}_$1_$2${3:-}/culling.csv" "$WORK/s_${sc}_$1_$2${3:-}/culling.csv" >&2 ||
                fail "$sc $1 $2 ${3:-}: the model's culling decisions differ from llvmpipe's"
            same_images "$WORK/l_${sc}_$1_$2${3:-}" "$WORK/s_${sc}_$1_$2${3:-}"
        done
    done
}

# The study must cull: VFC drops houses behind the walker, and the occlusion
# tests drop hidden ones the frustum keeps (this path has some at frame 0).
test_culling_culls() {
    run_cull "$SHIMBIN" c_vfc --method vfc
    run_cull "$SHIMBIN" c_vo --method vo
    local dr=$((36 * FRAMES)) vfc vo occ
    vfc=$(col_sum "$WORK/c_vfc/culling.csv" objects_rendered)
    vo=$(col_sum "$WORK/c_vo/culling.csv" objects_rendered)
    occ=$(col_sum "$WORK/c_vo/culling.csv" occ_culled)
    [ "$(wc -l <"$WORK/c_vo/culling.csv")" -eq $((FRAMES + 1)) ] || fail "culling.csv: not one row per frame"
    [ "$vfc" -lt "$dr" ] || fail "VFC drew $vfc of $dr houses"
    [ "$vo" -lt "$vfc" ] && [ "$occ" -gt 0 ] || fail "V+O drew $vo houses (VFC $vfc), $occ nodes occluded"
}

# GL_BRIEF_OCCLUSION's NOHC is the query's count (both count the box's
# fragments passing the depth test), so the decisions are the same; VFC in
# selection mode culls in the static scenes, and the cathedrals' other copies and
# hidden bays are occluded; garbage tests at leaves only.
test_brief_selection_and_scenes() {
    for sc in $SCENES; do
        run_cull "$SHIMBIN" "b_${sc}_q" --scene "$sc" --method vo --test query
        run_cull "$SHIMBIN" "b_${sc}_b" --scene "$sc" --method vo --test brief
        diff <(cut -d, -f4- "$WORK/b_${sc}_q/culling.csv") <(cut -d, -f4- "$WORK/b_${sc}_b/culling.csv") >&2 ||
            fail "$sc: brief and query decide differently"
        [ "$sc" = garbage ] && continue # the orbit keeps the whole can in view
        run_cull "$SHIMBIN" "b_${sc}_sel" --scene "$sc" --method vfc --vfc-select
        [ "$(col_sum "$WORK/b_${sc}_sel/culling.csv" vfc_culled)" -gt 0 ] || fail "$sc: selection-mode VFC culled nothing"
    done
    [ "$(col_sum "$WORK/b_cathedrals_q/culling.csv" occ_culled)" -gt 0 ] || fail "cathedrals: nothing occluded"
    grep -q "occlusion tests at leaves only" "$WORK/b_garbage_q.out" || fail "garbage: $(cat "$WORK/b_garbage_q.out")"
}

# Node and leaf counts: one house per leaf gives 36 leaves; p-HBVO's trees are
# binary (sec. 3.1.5: "non-sloppy binary trees"), so 2 * 36 - 1 nodes.
test_hierarchy_counts() {
    for h in phbvo dbvs sgi; do
        run_cull "$SHIMBIN" "h_$h" --method vfc --hierarchy "$h" --frames 1
    done
    grep -qx "scene city (small): hierarchy p-HBVO: 71 nodes, 36 leaves, 36 objects" "$WORK/h_phbvo.out" ||
        fail "$(cat "$WORK/h_phbvo.out")"
    grep -qE "hierarchy D-BVS: [0-9]+ nodes, 36 leaves" "$WORK/h_dbvs.out" || fail "$(cat "$WORK/h_dbvs.out")"
    grep -qE "hierarchy SGI: [0-9]+ nodes, 36 leaves" "$WORK/h_sgi.out" || fail "$(cat "$WORK/h_sgi.out")"
    local line nodes leaves
    line=$("$SHIMBIN" --method dr --frames 1 --size 64x64 --leaf 2 --out "$WORK/h2")
    nodes=$(echo "$line" | sed -nE 's/.*: ([0-9]+) nodes, ([0-9]+) leaves.*/\1/p')
    leaves=$(echo "$line" | sed -nE 's/.*: ([0-9]+) nodes, ([0-9]+) leaves.*/\2/p')
    [ -n "$leaves" ] && [ "$leaves" -lt 36 ] && [ "$leaves" -ge 18 ] && [ "$nodes" -eq $((2 * leaves - 1)) ] ||
        fail "--leaf 2: $line"
}

# The cycles column: scripts/cullstudy_cycles.sh replays the shim's capture
# in the cycle model; the replay draws the program's images.
test_cycles_column_from_capture() {
    local root; root=$(cd "$(dirname "$0")/.." && pwd)
    "$root/scripts/cullstudy_cycles.sh" "$FRAGSIM_BUILD" "$root/configs/o2.ini" --out "$WORK/cyc" --frames 2 \
        --size 96x96 --method vo >"$WORK/cyc.log" 2>&1 || fail "cullstudy_cycles.sh: $(tail -n 5 "$WORK/cyc.log")"
    local bad; bad=$(awk -F, 'NR > 1 && !($NF ~ /^[1-9][0-9]*$/)' "$WORK/cyc/culling.csv")
    [ -z "$bad" ] && [ "$(wc -l <"$WORK/cyc/culling.csv")" -eq 3 ] || fail "cycles column: $(cat "$WORK/cyc/culling.csv")"
    for n in frame_0000.png frame_0001.png; do
        "$FRAGSIM" diff "$WORK/cyc/$n" "$WORK/cyc/cycle_frames/$n" >/dev/null || fail "the cycle replay's $n differs"
    done
}

# The seeds' city workloads on norwich (issue 21, item 5): occluder shadows
# (a cull map read back) and the view-cell PVS (per-object NOHC counts) draw
# DR's images on both libraries, decide the same on both, and cull.
test_seed_methods_on_norwich() {
    local lib m
    for lib in "$SHIMBIN:s" "$OSMBIN:l"; do
        run_cull "${lib%%:*}" "n_${lib##*:}_dr" --scene norwich --method dr
        for m in shadow pvs; do
            run_cull "${lib%%:*}" "n_${lib##*:}_$m" --scene norwich --method $m --cull-map 160
            same_images "$WORK/n_${lib##*:}_dr" "$WORK/n_${lib##*:}_$m"
        done
    done
    for m in dr shadow pvs; do
        diff "$WORK/n_l_$m/culling.csv" "$WORK/n_s_$m/culling.csv" >&2 || fail "norwich $m: the model decides differently"
        same_images "$WORK/n_l_$m" "$WORK/n_s_$m"
    done
    [ "$(col_sum "$WORK/n_s_shadow/culling.csv" occ_culled)" -gt 0 ] || fail "shadow: nothing under a shadow"
    [ "$(col_sum "$WORK/n_s_pvs/culling.csv" occ_culled)" -gt 0 ] || fail "pvs: nothing outside the PVS"
    grep -q "^shadow: 160 x 160 cull map" "$WORK/n_s_shadow.out" || fail "shadow: $(cat "$WORK/n_s_shadow.out")"
    grep -qE "^pvs: .* [1-9][0-9]* sample views" "$WORK/n_s_pvs.out" || fail "pvs: $(cat "$WORK/n_s_pvs.out")"
    local out
    out=$("$SHIMBIN" --scene cathedrals --method shadow --frames 1 --size 64x64 --out "$WORK/x3" 2>&1)
    [ $? -eq 2 ] && echo "$out" | grep -q "has no occluders" || fail "shadow on cathedrals: $out"
    out=$("$SHIMBIN" --scene garbage --method pvs --frames 1 --size 64x64 --out "$WORK/x4" 2>&1)
    [ $? -eq 2 ] && echo "$out" | grep -q "needs a static scene" || fail "pvs on garbage: $out"
    out=$("$SHIMBIN" --scene norwich --method shadow --frames 1 --size 64x64 --out "$WORK/x5" 2>&1)
    [ $? -eq 2 ] && echo "$out" | grep -q "larger than the 64x64 buffer" || fail "--cull-map 256 in 64x64: $out"
    "$SHIMBIN" --cull-map 7 >/dev/null 2>&1; [ $? -eq 2 ] || fail "--cull-map 7: not exit 2"
    "$SHIMBIN" --pvs-samples some >/dev/null 2>&1; [ $? -eq 2 ] || fail "--pvs-samples some: not exit 2"
}

# What is not there says so, with exit 2 and nothing drawn.
test_unavailable_and_bad_options() {
    local out
    out=$("$OSMBIN" --test hp --frames 1 --out "$WORK/x1" 2>&1); [ $? -eq 2 ] || fail "hp on libOSMesa: not exit 2"
    echo "$out" | grep -q "does not offer GL_HP_occlusion_test" || fail "hp: $out"
    out=$("$OSMBIN" --test brief --frames 1 --out "$WORK/x2" 2>&1); [ $? -eq 2 ] || fail "brief on libOSMesa: not exit 2"
    echo "$out" | grep -q "does not offer GL_FRAGSIM_occlusion_unit" || fail "brief: $out"
    out=$("$SHIMBIN" --scene moon 2>&1); [ $? -eq 2 ] || fail "--scene moon: not exit 2"
    echo "$out" | grep -q "city, norwich, cathedrals, forest and garbage" || fail "--scene moon: $out"
    "$SHIMBIN" --method xyz >/dev/null 2>&1; [ $? -eq 2 ] || fail "--method xyz: not exit 2"
    "$SHIMBIN" --size 0x5 >/dev/null 2>&1; [ $? -eq 2 ] || fail "--size 0x5: not exit 2"
    "$SHIMBIN" --frames >/dev/null 2>&1; [ $? -eq 2 ] || fail "--frames without a value: not exit 2"
    [ ! -e "$WORK/x1" ] && [ ! -e "$WORK/x2" ] || fail "an output directory was made"
}

for t in test_methods_identical_to_dr_on_the_model test_methods_identical_to_dr_on_osmesa \
         test_query_methods_model_equals_osmesa test_brief_selection_and_scenes test_culling_culls \
         test_hierarchy_counts test_seed_methods_on_norwich \
         test_cycles_column_from_capture test_unavailable_and_bad_options; do
    run_test "$t"
done
finish
