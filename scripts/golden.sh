#!/bin/bash
# `make golden`: the only way tests/golden/*.png change.  Each scene's small
# trace is first checked against OSMesa (the independent reason a golden
# image is right); only then are its frames stored.
set -euo pipefail
BUILD=${1:-build}
DIR=tests/golden
SCENES=${SCENES:-"city norwich cathedrals forest garbage terrain demo textured"}
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
mkdir -p "$DIR"
for s in $SCENES; do
    "$BUILD/scenegen" "$s" --scale small -o "$TMP/$s.trace" >/dev/null
    # At check's default tolerance, 0: every bundled scene is identical to
    # llvmpipe's (docs/check.md).
    LP_NUM_THREADS=1 "$BUILD/fragsim" check --quiet --out "$TMP/check_$s" "$TMP/$s.trace" >/dev/null 2>&1 || { echo "golden: $s does not pass fragsim check; nothing stored" >&2; exit 1; }
    "$BUILD/fragsim" replay --quiet --out "$TMP/$s" "$TMP/$s.trace" 2>/dev/null
    rm -f "$DIR/$s"_*.png
    for f in "$TMP/$s"/frame_*.png; do cp "$f" "$DIR/${s}_$(basename "$f" .png | sed 's/frame_//').png"; done
    echo "golden: $s ($(ls "$TMP/$s"/frame_*.png | wc -l) frames, checked against OSMesa)"
done
