# Helpers for the shell-level tests (sourced).  Each test is a function;
# `run_test NAME` runs it and counts; `finish` prints the summary line.
set -u
PASS=0 FAIL=0 SKIP=0
WORK=$(mktemp -d)
trap 'rm -rf "$WORK"' EXIT
run_test() {
    local name=$1 out rc
    out=$("$name" 2>&1); rc=$?
    if [ $rc -eq 0 ]; then PASS=$((PASS + 1)); echo "ok   $name"
    elif [ $rc -eq 77 ]; then SKIP=$((SKIP + 1)); echo "SKIP $name: $(echo "$out" | tail -n 1)"
    else FAIL=$((FAIL + 1)); echo "FAIL $name"; echo "$out" | tail -n 30 | sed 's/^/    /'; fi
}
skip() { echo "$1"; exit 77; }
fail() { echo "$1"; exit 1; }
finish() { echo "$PASS passed, $FAIL failed, $SKIP skipped"; [ $FAIL -eq 0 ]; }

# A program linked against a sanitizer build's library (make sanitize's
# build-san) needs the same sanitizers, or its link fails on the runtime's
# symbols: the flags to add, empty for a plain build.
san_flags() { # BUILD_DIR
    if nm -A "$1/libfragsim_core.a" 2>/dev/null | grep -q ' U __asan_'; then
        echo "-fsanitize=address,undefined"
    fi
}
