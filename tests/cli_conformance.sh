#!/bin/bash
# `make conformance` inside the suite: every corpus trace against its
# independent references (tests/conformance/run.py prints "N passed, N failed",
# one per trace: exact, or on the expected-failure list with its reason).
set -u
ROOT=$(cd "$(dirname "$0")/.." && pwd)
BUILD=${FRAGSIM_BUILD:-$ROOT/build}
cd "$ROOT" && make -s --no-print-directory conformance-run BUILD="${BUILD#$ROOT/}"
