#!/bin/bash
# Shows that the work tree's fragsim outputs what REV's does, bit for bit:
#   scripts/compare_outputs.sh [REV]      (default HEAD)
# Builds REV in a temporary worktree and the work tree in build-compare/,
# records both (scripts/record_outputs.sh) and diffs them; exit 1 on any
# difference.  Takes a few minutes.
set -euo pipefail
REV=${1:-HEAD}
ROOT=$(cd "$(dirname "$0")/.." && pwd)
W=$(mktemp -d)
trap 'git -C "$ROOT" worktree remove --force "$W/src" >/dev/null 2>&1 || true; rm -rf "$W"' EXIT
git -C "$ROOT" worktree add --detach "$W/src" "$REV" >/dev/null
make -C "$W/src" -j2 BUILD=build all >/dev/null
CB=${COMPARE_BUILD:-build-compare}   # one per person working in this tree
case $CB in /*) ;; *) CB=$ROOT/$CB ;; esac   # relative to the tree, or absolute
make -C "$ROOT" -j2 BUILD="$CB" all >/dev/null
"$ROOT/scripts/record_outputs.sh" "$W/src/build" "$W/old"
"$ROOT/scripts/record_outputs.sh" "$CB" "$W/new"
if diff -r "$W/old/run" "$W/new/run" > "$W/diff.txt"; then
    echo "compare_outputs: identical to $REV ($(ls "$W/new/run" | wc -l) runs)"
else
    head -n 60 "$W/diff.txt"
    echo "compare_outputs: differing files:"
    diff -rq "$W/old/run" "$W/new/run" | sed "s|$W/||g"
    echo "compare_outputs: differs from $REV" >&2
    exit 1
fi
