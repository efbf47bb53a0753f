#!/bin/bash
# make sampling-study (scripts/sampling_study.py, issue 24) in its quick mode:
# every row of the doc must agree with the JSON it was made from, and the
# JSON's errors with a recount from `fragsim bench` itself (cycle and sampled
# mode run again here on one trace), the plot must be a PNG.
. "$(dirname "$0")/lib_cli.sh"
: "${FRAGSIM:?}" "${FRAGSIM_BUILD:?}"
ROOT=$(cd "$(dirname "$0")/.." && pwd)

test_quick_study_reads_back() {
    command -v gnuplot >/dev/null || skip "no gnuplot"
    OUT="$WORK/s" DOC="$WORK/s.md" PLOT="$WORK/s.png" QUICK=1 MIN_SECONDS=0 BUILD="$FRAGSIM_BUILD" \
        /usr/bin/python3 "$ROOT/scripts/sampling_study.py" >"$WORK/log" 2>&1 || fail "study failed: $(tail -n 5 "$WORK/log")"
    [ "$(head -c 4 "$WORK/s.png" | od -An -c | tr -d ' ')" = "211PNG" ] || fail "plot is not a PNG"
    /usr/bin/python3 - "$WORK" "$FRAGSIM" "$ROOT" <<'PY' || exit 1
import json, subprocess, sys
work, fragsim, root = sys.argv[1:4]
rows = json.load(open(work + '/s/sampling.json'))
doc = open(work + '/s.md').read()
assert len(rows) == 2 * 5, 'expected 5 traces x 2 configs, got %d rows' % len(rows)
for r in rows:
    line = '| %s | %s | %d | %d |' % (r['trace'], r['config'], r['frames'], r['cycles'])
    assert line in doc, 'row missing from the doc: ' + line
    err = '%+.2f%%' % (100 * (r['sampled_cycles'] - r['cycles']) / r['cycles'])
    assert err in doc.split(line, 1)[1].split('\n', 1)[0], 'error of %s %s is not %s' % (r['trace'], r['config'], err)
# The recount: atlantis on O2, straight from fragsim bench.
tr = root + '/tests/conformance/programs/atlantis.trace'
def bench(mode):
    out = subprocess.run([fragsim, 'bench', '--mode', mode, '--config', root + '/configs/o2.ini', '--repeat', '1', tr],
                         capture_output=True, text=True, check=True).stdout
    return json.loads(out.strip().splitlines()[-1])
full, smp = bench('cycle'), bench('sampled')
r = [r for r in rows if r['trace'] == 'atlantis' and r['config'] == 'O2'][0]
assert r['cycles'] == full['cycles'] and r['sampled_cycles'] == smp['cycles'], (r, full, smp)
assert abs(r['estimate'] - smp['error_estimate']) < 1e-12
assert r['frames'] == 4, r['frames']
PY
}

test_bad_build_dir_is_a_clear_error() {
    BUILD="$WORK/nowhere" OUT="$WORK/n" DOC="$WORK/n.md" PLOT="$WORK/n.png" /usr/bin/python3 "$ROOT/scripts/sampling_study.py" >"$WORK/log" 2>&1 &&
        fail "ran without a build"
    grep -q "not built" "$WORK/log" || fail "unclear error: $(cat "$WORK/log")"
}

run_test test_quick_study_reads_back
run_test test_bad_build_dir_is_a_clear_error
finish
