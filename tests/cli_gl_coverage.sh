#!/bin/bash
# docs/gl_coverage.md (scripts/gl_coverage.py, `make gl-coverage`): every GL
# 1.0-1.5 core entry point of the system headers (484) with its status in
# this build.  Fails when the committed page is stale, when an entry point
# that is not executed (missing from libfragsimGL.so or an "unsupported"
# stub) is not in tests/gl_coverage_pending.txt, and when a listed one is
# executed: the list only shrinks (issue 19).  Each check is shown to fail.
. "$(dirname "$0")/lib_cli.sh"
ROOT=$(cd "$(dirname "$0")/.." && pwd)
BUILD=${FRAGSIM_BUILD:-$ROOT/build}
GEN="/usr/bin/python3 $ROOT/scripts/gl_coverage.py --build $BUILD"

test_coverage_page_is_current() {
    [ -e "$BUILD/libfragsimGL.so" ] || skip "no $BUILD/libfragsimGL.so"
    $GEN --out "$BUILD/gl_coverage.md" --check "$ROOT/docs/gl_coverage.md" \
        --pending "$ROOT/tests/gl_coverage_pending.txt" || fail "see above"
    grep -q '^\*\*484 entry points' "$BUILD/gl_coverage.md" || fail "not 484 entry points"
}

test_stale_page_fails() {
    [ -e "$BUILD/libfragsimGL.so" ] || skip "no $BUILD/libfragsimGL.so"
    sed 's/| executed |$/| missing |/' "$ROOT/docs/gl_coverage.md" >"$WORK/stale.md"
    cmp -s "$WORK/stale.md" "$ROOT/docs/gl_coverage.md" && fail "the edit changed nothing"
    if $GEN --out "$WORK/gen.md" --check "$WORK/stale.md" >"$WORK/out"; then
        fail "a stale page passed"
    fi
    grep -q "is stale" "$WORK/out" || fail "not named: $(cat "$WORK/out")"
}

test_unlisted_missing_entry_point_fails() {
    [ -e "$BUILD/libfragsimGL.so" ] || skip "no $BUILD/libfragsimGL.so"
    first=$(grep -vE '^[[:space:]]*(#|$)' "$ROOT/tests/gl_coverage_pending.txt" | head -n 1 | awk '{print $1}')
    [ -n "$first" ] || skip "nothing pending"
    grep -vE "^$first[[:space:]]" "$ROOT/tests/gl_coverage_pending.txt" >"$WORK/pending"
    if $GEN --out "$WORK/gen.md" --pending "$WORK/pending" >"$WORK/out"; then
        fail "$first left out of the list passed"
    fi
    grep -q "^$first is .* and not in" "$WORK/out" || fail "not named: $(cat "$WORK/out")"
}

test_listed_executed_entry_point_fails() {
    [ -e "$BUILD/libfragsimGL.so" ] || skip "no $BUILD/libfragsimGL.so"
    { cat "$ROOT/tests/gl_coverage_pending.txt"; echo "glVertex3f  # executed: must fail"; } >"$WORK/pending"
    if $GEN --out "$WORK/gen.md" --pending "$WORK/pending" >"$WORK/out"; then
        fail "an executed entry point on the list passed"
    fi
    grep -q "glVertex3f is executed now" "$WORK/out" || fail "not named: $(cat "$WORK/out")"
}

run_test test_coverage_page_is_current
run_test test_stale_page_fails
run_test test_unlisted_missing_entry_point_fails
run_test test_listed_executed_entry_point_fails
finish
