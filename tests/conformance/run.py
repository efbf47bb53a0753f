#!/usr/bin/python3
"""The conformance corpus: every trace in tests/conformance/{piglit,programs}/
replayed on fragsim and compared, snapshot by snapshot, with references that
do not come from fragsim.

  run.py [--build DIR] [--only REGEX] [--jobs N] [--update-md5] [--update-expected]
         [--doc FILE]

Per trace:
 1. Snapshot calls, from `apitrace dump` (apitrace's numbering): every frame
    end (glXSwapBuffers / eglSwapBuffers); for traces without swaps (piglit
    with -auto reads pixels instead), every glReadPixels that follows a
    drawing call, at most MAX_SNAPSHOTS, else the last call.
 2. Two references at those calls: glretrace (apitrace's replayer on llvmpipe
    under Xvfb) and osmesa_replay.py (apitrace pickle -> libOSMesa, llvmpipe).
    A reference counts where both agree, or where glretrace's image is shown
    invalid by one of the mechanical tests in glretrace_invalid() (each with
    its reason); otherwise that snapshot has no reference.  References are
    cached in BUILD/conformance/ and their MD5 (of the RGB pixels, top row
    first) is checked against the committed TRACE.md5: a different Mesa shows
    up as "reference changed", not as a fragsim failure.
 3. fragsim replay --snapshot CALLS: each snapshot compared with its reference
    at tolerance 0 ("within 1" is counted separately).
A trace is bit-exact when it has at least one valid reference and every
snapshot with one is identical.  tests/conformance/expected_failures.txt lists
the traces known not to be exact, each with a reason; the run fails when a
trace not listed there is not exact, and when a listed one has become exact
(so the list shrinks as fragsim improves).  docs/conformance.md is rewritten
from the results.
"""
import argparse
import concurrent.futures
import hashlib
import json
import os
import re
import shutil
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, HERE)
import pngio  # noqa: E402

KINDS = ('piglit', 'programs')
MAX_SNAPSHOTS = 32
SWAPS = {'glXSwapBuffers', 'eglSwapBuffers', 'eglSwapBuffersWithDamageKHR',
         'eglSwapBuffersWithDamageEXT', 'wglSwapBuffers'}
DRAWS = {'glClear', 'glEnd', 'glDrawArrays', 'glDrawElements', 'glDrawRangeElements',
         'glMultiDrawArrays', 'glMultiDrawElements', 'glCallList', 'glCallLists', 'glBitmap',
         'glDrawPixels', 'glCopyPixels', 'glAccum', 'glRectf', 'glRecti', 'glRectd', 'glRects',
         'glRectfv', 'glRectiv', 'glRectdv', 'glRectsv', 'glEvalMesh1', 'glEvalMesh2',
         'glDrawArraysEXT', 'glMultiDrawArraysEXT', 'glDrawRangeElementsEXT'}
CALL_RE = re.compile(r'^(\d+) (?:@\d+ )?([A-Za-z_][A-Za-z0-9_]*)\(')


def md5(data):
    return hashlib.md5(data).hexdigest()


def file_md5(path):
    with open(path, 'rb') as f:
        return md5(f.read())


def trace_calls(trace):
    out = subprocess.run(['apitrace', 'dump', '--color=never', trace], check=True,
                         stdout=subprocess.PIPE, stderr=subprocess.DEVNULL).stdout
    calls = []
    for line in out.decode('utf-8', 'replace').splitlines():
        m = CALL_RE.match(line)
        if m:
            calls.append((int(m.group(1)), m.group(2)))
    return calls


def snapshot_calls(calls):
    swaps = [no for no, name in calls if name in SWAPS]
    if swaps:
        return swaps[:MAX_SNAPSHOTS]
    picks, drawn = [], False
    for no, name in calls:
        if name in DRAWS:
            drawn = True
        elif name == 'glReadPixels' and drawn:
            picks.append(no)
            drawn = False
    if not picks:
        gl = [no for no, name in calls if name.startswith('gl') and not name.startswith('glX')]
        picks = gl[-1:]
    if len(picks) > MAX_SNAPSHOTS:   # evenly spread, keeping the last
        step = len(picks) / MAX_SNAPSHOTS
        picks = [picks[min(len(picks) - 1, int((i + 1) * step) - 1)] for i in range(MAX_SNAPSHOTS)]
    return picks


def run(cmd, log, env=None, timeout=600):
    with open(log, 'wb') as f:
        try:
            return subprocess.run(cmd, stdout=f, stderr=subprocess.STDOUT, env=env,
                                  timeout=timeout).returncode
        except subprocess.TimeoutExpired:
            f.write(b'\ntimed out\n')
            return -1


def load(path):
    try:
        return pngio.read_png(path)
    except (OSError, ValueError):
        return None


def diff(a, b):
    """(pixels differing, largest channel difference); a, b: (w, h, rgb)."""
    if a[:2] != b[:2]:
        return a[0] * a[1], 255
    if a[2] == b[2]:
        return 0, 0
    n, worst = 0, 0
    pa, pb = a[2], b[2]
    for i in range(0, len(pa), 3):
        if pa[i:i + 3] != pb[i:i + 3]:
            n += 1
            worst = max(worst, abs(pa[i] - pb[i]), abs(pa[i + 1] - pb[i + 1]), abs(pa[i + 2] - pb[i + 2]))
    return n, worst


def corner_equal(a, b, size):
    """a and b equal within the bottom-left size x size pixels (PNG rows are top first)."""
    w, h = a[0], a[1]
    for y in range(max(0, h - size), h):
        row = slice(y * w * 3, (y * w + min(size, w)) * 3)
        if a[2][row] != b[2][row]:
            return False
    return True


def glretrace_invalid(gl, om, first):
    """Why glretrace's snapshot is no reference, when a mechanical test shows it
    (shared/reference-notes.md, measured on this Mesa and apitrace 11), else None."""
    if gl is None:
        return 'glretrace wrote no snapshot at this call'
    if gl[:2] != om[:2]:
        return 'glretrace drawable %dx%d, the trace\'s window %dx%d' % (gl[0], gl[1], om[0], om[1])
    if corner_equal(gl, om, 32) and not corner_equal(gl, om, max(gl[0], gl[1])):
        return 'glretrace drew into its initial 32x32 drawable (it resizes the window later)'
    if first and gl[2].count(0) == len(gl[2]):
        return 'glretrace\'s first snapshot on Xvfb is black (the window is not mapped yet)'
    return None


class Trace:
    def __init__(self, kind, path, build):
        self.kind, self.path = kind, path
        self.name = os.path.basename(path)[:-len('.trace')]
        self.dir = os.path.join(build, 'conformance', kind, self.name)
        self.md5_path = path[:-len('.trace')] + '.md5'


def references(t, fragsim_env):
    """Generates (or reuses) both references; returns {call: (rgb image, source)} and notes."""
    os.makedirs(t.dir, exist_ok=True)
    stamp = os.path.join(t.dir, 'refs.stamp')
    # A new trace, replayer or snapshot rule makes new references.
    key = ' '.join([file_md5(t.path), file_md5(os.path.join(HERE, 'osmesa_replay.py')),
                    md5(repr((MAX_SNAPSHOTS, sorted(SWAPS), sorted(DRAWS))).encode())])
    calls_file = os.path.join(t.dir, 'calls.txt')
    gl_dir, om_dir = os.path.join(t.dir, 'glretrace'), os.path.join(t.dir, 'osmesa')
    cached = os.path.exists(stamp) and open(stamp).read().strip() == key
    if cached:
        with open(calls_file) as f:
            snaps = [int(x) for x in f.read().split()]
    else:
        snaps = snapshot_calls(trace_calls(t.path))
        for d in (gl_dir, om_dir):
            shutil.rmtree(d, ignore_errors=True)
            os.makedirs(d)
        callset = ','.join(str(c) for c in snaps)
        env = dict(os.environ, LP_NUM_THREADS='1')
        run(['glretrace', '-s', gl_dir + '/', '-S', callset, t.path],
            os.path.join(t.dir, 'glretrace.log'), env=env)
        env['PYOPENGL_PLATFORM'] = 'osmesa'
        run(['/usr/bin/python3', os.path.join(HERE, 'osmesa_replay.py'), t.path, om_dir, callset],
            os.path.join(t.dir, 'osmesa.log'), env=env)
        with open(calls_file, 'w') as f:
            f.write('\n'.join(str(c) for c in snaps) + '\n')
        with open(stamp, 'w') as f:
            f.write(key + '\n')
    refs, notes = {}, {}
    for i, c in enumerate(snaps):
        om = load(os.path.join(om_dir, '%010d.png' % c))
        gl = load(os.path.join(gl_dir, '%010d.png' % c))
        if om is None:
            notes[c] = 'no reference: the OSMesa replayer wrote no snapshot'
            continue
        if gl is not None and gl == om:
            refs[c] = (om, 'both')
            continue
        why = glretrace_invalid(gl, om, i == 0)
        if why:
            refs[c] = (om, 'osmesa (%s)' % why)
        else:
            n, _ = diff(gl, om)
            notes[c] = 'no reference: glretrace and the OSMesa replayer differ in %d pixels' % n
    return snaps, refs, notes


def read_md5(path):
    out = {}
    if os.path.exists(path):
        with open(path) as f:
            for line in f:
                parts = line.split(None, 2)
                if len(parts) >= 2 and parts[0].isdigit():
                    out[int(parts[0])] = parts[1]
    return out


def check(t, args):
    r = {'kind': t.kind, 'name': t.name}
    snaps, refs, notes = references(t, None)
    committed = read_md5(t.md5_path)
    if args.update_md5:
        with open(t.md5_path, 'w') as f:
            f.write('# call  md5 of the reference RGB pixels (top row first)  source\n')
            for c in snaps:
                if c in refs:
                    f.write('%d %s %s\n' % (c, md5(refs[c][0][2]), refs[c][1]))
        committed = read_md5(t.md5_path)
    # Only committed references count: a snapshot whose reference has no
    # committed MD5 (e.g. one whose validity changed) is reported, not compared;
    # one whose MD5 differs is "reference changed" (a different Mesa or apitrace).
    r['no_md5_file'] = not os.path.exists(t.md5_path)
    changed = [c for c in refs if c in committed and committed[c] != md5(refs[c][0][2])]
    r['uncommitted'] = sorted(c for c in refs if c not in committed)
    refs = {c: v for c, v in refs.items() if c in committed and c not in changed}
    fs_dir = os.path.join(t.dir, 'fragsim')
    shutil.rmtree(fs_dir, ignore_errors=True)
    os.makedirs(fs_dir)
    stats_path = os.path.join(fs_dir, 'stats.json')
    rc = run([args.fragsim, 'replay', '--quiet', '--snapshot', ','.join(str(c) for c in snaps),
              '--out', fs_dir, '--stats', stats_path, t.path], os.path.join(t.dir, 'fragsim.log'))
    stats = {}
    try:
        with open(stats_path) as f:
            stats = json.load(f)
    except (OSError, ValueError):
        pass
    r['fragsim_rc'] = rc
    r['errors'] = stats.get('totals', {}).get('gl_errors', 0)
    r['error_list'] = stats.get('errors', [])[:5]
    # What fragsim did not execute: modelled-feature gaps, and calls it skipped
    # as unknown or unsafe (queries of GL >= 3 that change nothing are left out
    # of the list: glGetStringi, glGetFramebufferAttachmentParameteriv).
    uns = dict(stats.get('unsupported', {}))
    for name, v in stats.get('skipped_trace_calls', {}).items():
        if isinstance(v, dict) and v.get('reason') in ('unknown', 'unsafe') and \
                name not in ('glGetStringi', 'glGetFramebufferAttachmentParameteriv'):
            uns[name] = v.get('count', 1)
    r['unsupported'] = uns
    r['fragsim_error'] = ''
    if rc != 0:
        with open(os.path.join(t.dir, 'fragsim.log'), errors='replace') as f:
            lines = [x.strip() for x in f if x.startswith('fragsim:')]
        r['fragsim_error'] = (lines[0] if lines else '').replace(t.path, os.path.basename(t.path))
    r['snapshots'] = len(snaps)
    r['refs'] = len(refs)
    r['ref_sources'] = sorted({s for _, s in refs.values()})
    r['notes'] = sorted(set(notes.values()))
    r['changed'] = sorted(changed)
    exact = within1 = 0
    worst = 0
    first_bad = None
    for c in snaps:
        if c not in refs:
            continue
        img = load(os.path.join(fs_dir, '%010d.png' % c))
        if img is None:
            n, mx = refs[c][0][0] * refs[c][0][1], 255
        else:
            n, mx = diff(img, refs[c][0])
        if n == 0:
            exact += 1
        elif mx <= 1:
            within1 += 1
        if n and first_bad is None:
            first_bad = c
        worst = max(worst, n)
    r.update(exact=exact, within1=within1, worst=worst, first_bad=first_bad)
    r['bit_exact'] = bool(refs) and exact == len(refs) and rc == 0
    return r


def load_expected(path):
    out = {}
    if os.path.exists(path):
        with open(path) as f:
            for line in f:
                line = line.rstrip('\n')
                if line and not line.startswith('#'):
                    name, _, reason = line.partition('\t')
                    out[name.strip()] = reason.strip()
    return out


def auto_reason(r):
    if r['refs'] == 0:
        return 'no valid reference: ' + '; '.join(r['notes'])
    parts = []
    if r['unsupported']:
        names = sorted(r['unsupported'], key=lambda k: -r['unsupported'][k])
        parts.append('unsupported: ' + ', '.join(names[:6]) + (' ...' if len(names) > 6 else ''))
    if r['fragsim_rc'] != 0:
        parts.append('fragsim exits with %d (%s)' % (r['fragsim_rc'], r['fragsim_error'][:160]))
    parts.append('%d of %d snapshots differ (worst %d pixels, first at call %s)'
                 % (r['refs'] - r['exact'], r['refs'], r['worst'], r['first_bad']))
    return '; '.join(parts)


def write_doc(path, results, expected):
    exact = [r for r in results if r['bit_exact']]
    lines = ['# Conformance: real programs as the oracle', '',
             'Generated by `make conformance` (tests/conformance/run.py); do not edit.', '',
             '**%d of %d traces bit-exact** (%d piglit, %d programs).' % (
                 len(exact), len(results), sum(1 for r in results if r['kind'] == 'piglit'),
                 sum(1 for r in results if r['kind'] == 'programs')), '',
             'Each trace is replayed with `fragsim replay --snapshot CALLS`; every snapshot is',
             'compared at tolerance 0 with a reference made without fragsim: glretrace',
             '(apitrace on llvmpipe under Xvfb) and tests/conformance/osmesa_replay.py',
             '(`apitrace pickle` into libOSMesa).  A reference counts where both agree, or where',
             'glretrace\'s image is shown invalid (reason in the last column of the .md5 file).',
             'Columns: snapshots with a valid reference, exact, within 1 (every channel off by at',
             'most 1), the worst snapshot\'s differing pixels, GL errors fragsim raised, and the',
             'calls fragsim counted as unsupported.', '']
    for kind in KINDS:
        rows = [r for r in results if r['kind'] == kind]
        if not rows:
            continue
        lines += ['## %s (%d of %d bit-exact)' % (kind, sum(1 for r in rows if r['bit_exact']), len(rows)), '',
                  '| trace | refs | exact | within 1 | worst px | GL errors | unsupported | status |',
                  '|---|---|---|---|---|---|---|---|']
        for r in rows:
            uns = ', '.join(sorted(r['unsupported'])[:4]) + (' ...' if len(r['unsupported']) > 4 else '')
            status = 'exact' if r['bit_exact'] else ('expected failure' if r['name'] in expected else 'FAIL')
            if r['changed']:
                status += ', reference changed'
            lines.append('| %s | %d/%d | %d | %d | %d | %d | %s | %s |' % (
                r['name'], r['refs'], r['snapshots'], r['exact'], r['within1'], r['worst'],
                r['errors'], uns.replace('|', '/'), status))
        lines.append('')
    with open(path, 'w') as f:
        f.write('\n'.join(lines))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('--build', default='build')
    ap.add_argument('--only', default='')
    ap.add_argument('--jobs', type=int, default=os.cpu_count() or 2)
    ap.add_argument('--update-md5', action='store_true')
    ap.add_argument('--update-expected', action='store_true')
    ap.add_argument('--doc', default=os.path.join(ROOT, 'docs', 'conformance.md'))
    args = ap.parse_args()
    build = os.path.abspath(os.path.join(ROOT, args.build))
    args.fragsim = os.path.join(build, 'fragsim')
    for tool in ('apitrace', 'glretrace'):
        if not shutil.which(tool):
            raise SystemExit('conformance: %s not found (Debian package apitrace)' % tool)
    if not os.environ.get('DISPLAY'):
        raise SystemExit('conformance: no DISPLAY; run under xvfb-run (make conformance does)')
    traces = []
    for kind in KINDS:
        d = os.path.join(HERE, kind)
        for f in sorted(os.listdir(d)) if os.path.isdir(d) else []:
            if f.endswith('.trace') and re.search(args.only, f):
                traces.append(Trace(kind, os.path.join(d, f), build))
    with concurrent.futures.ProcessPoolExecutor(max_workers=max(1, args.jobs)) as ex:
        results = list(ex.map(check, traces, [args] * len(traces)))
    exp_path = os.path.join(HERE, 'expected_failures.txt')
    expected = load_expected(exp_path)
    if args.update_expected:
        keep = {r['name']: expected.get(r['name']) or auto_reason(r) for r in results if not r['bit_exact']}
        with open(exp_path, 'w') as f:
            f.write('# Traces of the conformance corpus known not to be bit-exact, with the reason.\n'
                    '# name<TAB>reason.  make conformance fails when a trace not listed here is not\n'
                    '# exact, and when a listed one has become exact: then remove its line.\n')
            for name in sorted(keep):
                f.write('%s\t%s\n' % (name, keep[name]))
        expected = load_expected(exp_path)
    if not args.only:
        write_doc(args.doc, results, expected)
    passed = failed = 0
    for r in results:
        tag = '%s/%s' % (r['kind'], r['name'])
        if r['uncommitted']:
            print('note: %s: references at calls %s have no committed MD5 and are not compared'
                  % (tag, ','.join(map(str, r['uncommitted'][:5]))))
        if r['changed']:
            print('reference changed: %s (calls %s): regenerate with run.py --update-md5 after checking'
                  % (tag, ','.join(map(str, r['changed'][:5]))))
        if r['bit_exact'] and r['name'] in expected:
            print('now exact: %s: remove it from tests/conformance/expected_failures.txt' % tag)
            failed += 1
        elif r['no_md5_file']:
            print('FAIL %s: no committed .md5 file (run.py --update-md5 --only ...)' % tag)
            failed += 1
        elif not r['bit_exact'] and r['name'] not in expected and not r['changed']:
            print('FAIL %s: %s' % (tag, auto_reason(r)))
            failed += 1
        else:
            passed += 1
    print('conformance: %d of %d traces bit-exact' % (sum(1 for r in results if r['bit_exact']), len(results)))
    print('%d passed, %d failed' % (passed, failed))
    if not results:
        print('FAIL: --only %r matches no trace of %s' % (args.only, ', '.join(KINDS)))
        return 1
    with open(os.path.join(build, 'conformance', 'results.json'), 'w') as f:
        json.dump(results, f, indent=1, default=str)
    return 1 if failed else 0


if __name__ == '__main__':
    sys.exit(main())
