#!/bin/bash
# The layers (docs/architecture.md, "Layers"): each directory includes only
# headers of its own layer or below, and a private header (*_priv.h,
# *_internal.h) only from its own directory.  From the bottom up:
#   0 glext/                     the GL extension headers
#   1 pipeline/ units/           the functional pipeline and its units
#   2 rtl_model/                 the cycle-level model, observing layer 1
#   3 driver/                    traces, replay, display lists, the CLI, the shim
# (tests/ and traces/ sit above all of them and may include anything.)
# The functional pipeline knows nothing of timing (issue 18): no file under
# pipeline/ names the cycle model, sampled mode, its tile sample or charging
# (its vector variants are gone); it reports its work through
# pipeline/observer.h only.
# Includes against the order that are still to be removed are listed in
# tests/layers_pending.txt with the reason; a listed include that is gone
# fails too, so that the list only shrinks.
. "$(dirname "$0")/lib_cli.sh"
ROOT=$(cd "$(dirname "$0")/.." && pwd)

layer_of() {
    case "$1" in
    glext) echo 0 ;; pipeline | units) echo 1 ;; rtl_model) echo 2 ;; driver) echo 3 ;; *) echo 9 ;;
    esac
}

# Prints every include of root's layered files against the rules, one per
# line: "SRC -> HEADER (why)", paths relative to root.
violations() {
    local root=$1 f d inc tgt td
    for d in glext pipeline units rtl_model driver; do
        for f in "$root/$d"/*.c "$root/$d"/*.cpp "$root/$d"/*.h "$root/$d"/*.def; do
            [ -f "$f" ] || continue
            sed -nE 's/^[[:space:]]*#[[:space:]]*include[[:space:]]*"([^"]+)".*/\1/p' "$f" | while read -r inc; do
                tgt=$(realpath -m "$(dirname "$f")/$inc")
                tgt=${tgt#"$(realpath -m "$root")"/}
                td=${tgt%%/*}
                [ "$td" = "$tgt" ] && td=.
                if [ "$(layer_of "$td")" -gt "$(layer_of "$d")" ]; then
                    echo "$d/$(basename "$f") -> $tgt (upward: layer $(layer_of "$td") from $(layer_of "$d"))"
                elif [ "$td" != "$d" ] && [[ "$tgt" == *_priv.h || "$tgt" == *_internal.h ]]; then
                    echo "$d/$(basename "$f") -> $tgt (private header of another directory)"
                fi
            done
        done
    done
}

# The check itself on a tree: new violations fail, pending ones that are
# gone fail.  Prints what it found.
check_tree() {
    local root=$1 pending=$2
    violations "$root" | sed 's/ (.*//' | sort -u >"$WORK/found"
    grep -vE '^[[:space:]]*(#|$)' "$pending" | sed 's/[[:space:]]*#.*//' | sort -u >"$WORK/pending"
    local new gone
    new=$(comm -23 "$WORK/found" "$WORK/pending")
    gone=$(comm -13 "$WORK/found" "$WORK/pending")
    [ -z "$new" ] || echo "include against the layers: $new"
    [ -z "$gone" ] || echo "listed in tests/layers_pending.txt but no longer there (remove the line): $gone"
    [ -z "$new" ] && [ -z "$gone" ]
}

# Lines of root's pipeline/ that speak of timing (see the top).
TIMING_WORDS='\bcycles?\b|cycle[- ](level|model)|rtl_model|fs_cycle|fs_cyc_|sampled (mode|tile|quad|draw)|tile sampl|\bsampling\b|charg(e|ed|es|ing)\b'
timing_mentions() {
    grep -inE "$TIMING_WORDS" "$1"/pipeline/* 2>/dev/null | sed "s|^$1/||"
}

test_pipeline_names_no_timing() {
    local found
    found=$(timing_mentions "$ROOT")
    [ -z "$found" ] || fail "pipeline/ speaks of timing: $found"
}

test_pipeline_naming_the_cycle_model_fails() {
    local w
    for w in '/* the cycle model times it */' '/* in sampled mode */' '/* charged its area */' 'x = fs_cycle_draw(y);'; do
        rm -rf "$WORK/tree"
        copy_tree
        printf '%s\n' "$w" >>"$WORK/tree/pipeline/blend.c"
        [ -n "$(timing_mentions "$WORK/tree")" ] || fail "not caught: $w"
    done
}

# A copy of the layered directories (sources only) to break on purpose.
copy_tree() {
    local d
    for d in glext pipeline units rtl_model driver; do
        mkdir -p "$WORK/tree/$d"
        cp "$ROOT/$d"/*.[ch] "$ROOT/$d"/*.def "$WORK/tree/$d"/ 2>/dev/null
        cp "$ROOT/$d"/*.cpp "$WORK/tree/$d"/ 2>/dev/null
    done
    true
}

test_tree_follows_the_layers() {
    check_tree "$ROOT" "$ROOT/tests/layers_pending.txt"
}

# Each rule must be able to fail: one deliberately bad include per rule in a
# temporary copy.
expect_caught() {
    local file=$1 line=$2 want=$3
    rm -rf "$WORK/tree"
    copy_tree
    printf '%s\n' "$line" >>"$WORK/tree/$file"
    if check_tree "$WORK/tree" "$ROOT/tests/layers_pending.txt" >"$WORK/out"; then
        fail "not caught: $line in $file"
    fi
    grep -qF "$want" "$WORK/out" || fail "caught, but not named: $(cat "$WORK/out")"
}

test_unit_including_the_driver_fails() {
    expect_caught units/footprint_rom.c '#include "../driver/replay.h"' "units/footprint_rom.c -> driver/replay.h"
}

test_pipeline_including_the_cycle_model_fails() {
    expect_caught pipeline/blend.c '#include "../rtl_model/cycle_model.h"' "pipeline/blend.c -> rtl_model/cycle_model.h"
}

test_cycle_model_including_the_driver_fails() {
    expect_caught rtl_model/memory.c '#  include "../driver/trace.h"' "rtl_model/memory.c -> driver/trace.h"
}

test_private_header_of_another_directory_fails() {
    expect_caught driver/replay.c '#include "../pipeline/rasterizer_priv.h"' "driver/replay.c -> pipeline/rasterizer_priv.h"
}

test_fixed_pending_include_fails() {
    rm -rf "$WORK/tree"
    copy_tree
    printf 'units/footprint_rom.c -> driver/replay.h  # a line for a violation that is not there\n' \
        >"$WORK/pending_extra"
    cat "$ROOT/tests/layers_pending.txt" >>"$WORK/pending_extra"
    if check_tree "$WORK/tree" "$WORK/pending_extra" >"$WORK/out"; then
        fail "a pending line without its include passed"
    fi
    grep -qF "no longer there" "$WORK/out" || fail "not named: $(cat "$WORK/out")"
}

run_test test_tree_follows_the_layers
run_test test_pipeline_names_no_timing
run_test test_pipeline_naming_the_cycle_model_fails
run_test test_unit_including_the_driver_fails
run_test test_pipeline_including_the_cycle_model_fails
run_test test_cycle_model_including_the_driver_fails
run_test test_private_header_of_another_directory_fails
run_test test_fixed_pending_include_fails
finish
