#!/bin/bash
# Golden images: every small scene must replay bit-exactly to the images in
# tests/golden, which `make golden` stores only after they passed
# `fragsim check` against OSMesa.
. "$(dirname "$0")/lib_cli.sh"
: "${FRAGSIM:?}" "${SCENEGEN:?}"
GOLDEN="$(cd "$(dirname "$0")" && pwd)/golden"

test_golden_images() {
    ls "$GOLDEN"/*.png >/dev/null 2>&1 || skip "no golden images (run make golden)"
    local scenes; scenes=$(ls "$GOLDEN"/*.png | xargs -n1 basename | sed -E 's/_[0-9]+\.png$//' | sort -u)
    for s in $scenes; do
        "$SCENEGEN" "$s" --scale small -o "$WORK/$s.trace" >/dev/null || fail "scenegen $s"
        "$FRAGSIM" replay --quiet --out "$WORK/$s" "$WORK/$s.trace" || fail "replay $s"
        for g in "$GOLDEN/${s}"_*.png; do
            local n; n=$(basename "$g" .png | sed -E 's/.*_([0-9]+)$/\1/')
            "$FRAGSIM" diff "$g" "$WORK/$s/frame_$n.png" >"$WORK/d" 2>&1 \
                || fail "$s frame $n differs from its golden image: $(cat "$WORK/d")"
        done
    done
}
run_test test_golden_images
finish
