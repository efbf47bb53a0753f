#!/bin/bash
# Records what a build of fragsim outputs, so that a refactoring can be shown
# to change nothing:  scripts/record_outputs.sh BUILD OUTDIR
# For every scene generator (small scale), the bench traces (reduced), the
# conformance corpus's program traces and tests/data traces, in functional,
# full-cycle and sampled mode with configs/o2.ini and configs/infinite_reality.ini:
# the MD5 of every frame image and the statistics file with the trace's path
# taken out.  Compare two records with `diff -r`; scripts/compare_outputs.sh
# does both for a parent commit and the work tree.
set -euo pipefail
B=$1 OUT=$2
ROOT=$(cd "$(dirname "$0")/.." && pwd)
mkdir -p "$OUT/traces"
T="$OUT/traces"
for s in city norwich cathedrals forest garbage terrain demo textured; do
    "$B/scenegen" "$s" --scale small -o "$T/$s.trace" >/dev/null
done
for s in bench8 bench32; do
    "$B/scenegen" "$s" --scale 20000 -o "$T/$s.trace" >/dev/null
done
traces=("$T"/*.trace "$ROOT"/tests/conformance/programs/*.trace)
for t in "${traces[@]}"; do
    n=$(basename "$t" .trace)
    for mode in functional cycle sampled; do
        for cfg in o2 infinite_reality; do
            [ "$mode" = functional ] && [ "$cfg" = infinite_reality ] && continue
            d="$OUT/run/$n.$mode.$cfg"
            mkdir -p "$d"
            "$B/fragsim" replay --quiet --mode "$mode" --config "$ROOT/configs/$cfg.ini" \
                --out "$d" --stats "$d/stats.json" "$t" >"$d/log" 2>&1 || echo "exit $?" >>"$d/log"
            (cd "$d" && md5sum frame_*.png 2>/dev/null > images.md5; rm -f frame_*.png)
            /usr/bin/python3 - "$d/stats.json" <<'PY'
import json, sys
p = sys.argv[1]
try:
    d = json.load(open(p))
except (OSError, ValueError):
    sys.exit(0)
d.pop('trace', None)
json.dump(d, open(p, 'w'), indent=1, sort_keys=True)
PY
            # paths and the run's speed (", 8.2 M cycles/s") differ from run to run
            sed -i -e '/statistics in\|images in/d' -e 's/, [0-9.]* M cycles\/s$//' "$d/log"
        done
    done
done
echo "recorded ${#traces[@]} traces into $OUT/run"
