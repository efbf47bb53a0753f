#!/bin/bash
# Runs the whole suite: every C test binary in BUILD/tests and every
# tests/cli_*.sh script, each with a time limit, and prints one closing line
# "N passed, N failed, N skipped" summed over all of them.
set -u
BUILD=${1:-build}
ROOT=$(cd "$(dirname "$0")/.." && pwd)
cd "$ROOT"
export FRAGSIM="$ROOT/$BUILD/fragsim" SCENEGEN="$ROOT/$BUILD/scenegen" FRAGSIM_BUILD="$ROOT/$BUILD"
# llvmpipe is the reference; one thread keeps OSMesa deterministic and light.
export LP_NUM_THREADS=${LP_NUM_THREADS:-1}
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
passed=0 failed=0 skipped=0 broken=()
run_one() {
    local name=$1; shift
    local log="$TMP/$(basename "$name").log"
    # The conformance corpus makes its references on a first run: 30 minutes.
    local limit=${TEST_TIMEOUT:-600}
    case "$name" in cli_conformance.sh) limit=${CONFORMANCE_TIMEOUT:-1800};; esac
    timeout "$limit" "$@" >"$log" 2>&1
    local rc=$?
    local line
    line=$(grep -E '^[0-9]+ passed, [0-9]+ failed' "$log" | tail -n 1)
    if [ -n "$line" ]; then
        local p f s
        p=$(echo "$line" | sed -E 's/^([0-9]+) passed.*/\1/')
        f=$(echo "$line" | sed -E 's/^[0-9]+ passed, ([0-9]+) failed.*/\1/')
        s=$(echo "$line" | sed -nE 's/.*, ([0-9]+) skipped.*/\1/p')
        passed=$((passed + p)); failed=$((failed + f)); skipped=$((skipped + ${s:-0}))
        if [ "$rc" -ne 0 ] && [ "$f" -eq 0 ]; then failed=$((failed + 1)); fi
    else
        # No summary: the binary crashed or timed out before finishing.
        failed=$((failed + 1))
    fi
    if [ "$rc" -ne 0 ]; then
        broken+=("$name")
        echo "---- $name (exit $rc) ----"
        tail -n 40 "$log"
    else
        printf '%-32s %s\n' "$name" "${line:-}"
    fi
    grep -E '^SKIP' "$log" | sed 's/^/    /'
}
for t in "$BUILD"/tests/test_*; do
    [ -x "$t" ] || continue
    case "$t" in *.o|*.d) continue;; esac
    run_one "$(basename "$t")" "$t"
done
for s in tests/cli_*.sh; do
    [ -f "$s" ] || continue
    run_one "$(basename "$s")" bash "$s"
done
if [ ${#broken[@]} -gt 0 ]; then echo "failing: ${broken[*]}"; fi
echo "$passed passed, $failed failed, $skipped skipped"
[ "$failed" -eq 0 ]
