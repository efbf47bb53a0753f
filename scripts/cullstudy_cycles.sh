#!/bin/bash
# Fills culling.csv's cycles column: the shim runs fragsim's functional model
# only, so cullstudy is run with FRAGSIM_TRACE (the shim records every call),
# the capture is replayed in the cycle-level model with CONFIG, and each
# frame's cycles (the replay's statistics: cycle.frames[i].cycles; one frame
# per glFinish) go into the row of that frame.
#   scripts/cullstudy_cycles.sh [BUILD] CONFIG.ini --out DIR [cullstudy options]
set -euo pipefail
BUILD=build
if [ $# -gt 0 ] && [ -d "$1" ]; then BUILD=$1; shift; fi
[ $# -ge 1 ] || { echo "usage: $0 [BUILD] CONFIG.ini --out DIR [cullstudy options]" >&2; exit 2; }
CONFIG=$1; shift
[ -f "$CONFIG" ] || { echo "$0: no config $CONFIG" >&2; exit 2; }
OUT=out/cullstudy
args=("$@")
for ((i = 0; i + 1 < ${#args[@]}; i++)); do [ "${args[$i]}" = --out ] && OUT=${args[$((i + 1))]}; done
mkdir -p "$OUT"
FRAGSIM_TRACE="$OUT/cullstudy.trace" "$BUILD/cullstudy" --out "$OUT" "$@"
"$BUILD/fragsim" replay --mode cycle --config "$CONFIG" --stats "$OUT/cycles.json" --out "$OUT/cycle_frames" \
    "$OUT/cullstudy.trace" >&2
/usr/bin/python3 - "$OUT/culling.csv" "$OUT/cycles.json" <<'PY'
import csv, json, sys
rows = list(csv.DictReader(open(sys.argv[1])))
frames = json.load(open(sys.argv[2]))["cycle"]["frames"]
if len(frames) < len(rows):
    sys.exit("cullstudy_cycles: %d frames replayed for %d rows" % (len(frames), len(rows)))
for r, f in zip(rows, frames):
    r["cycles"] = f["cycles"]
with open(sys.argv[1], "w", newline="") as fh:
    w = csv.DictWriter(fh, fieldnames=list(rows[0].keys()), lineterminator="\n")
    w.writeheader()
    w.writerows(rows)
PY
