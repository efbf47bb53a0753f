#!/bin/sh
# `make run`: generate the demo trace, replay it on the model, and say where
# the image and the statistics are.
set -e
BUILD=${1:-build}
OUT=${OUT:-out/demo}
"$BUILD/scenegen" demo -o "$BUILD/demo.trace"
"$BUILD/fragsim" replay --quiet --out "$OUT" "$BUILD/demo.trace"
echo
echo "demo trace:  $BUILD/demo.trace"
echo "image:       $OUT/frame_0000.png"
echo "statistics:  $OUT/stats.json"
