#!/usr/bin/env python3
"""make sampling-study: sampled mode against full cycle mode on programs the
sampler was not tuned on (issue 24, item 1).

For every program trace of the conformance corpus (tests/conformance/programs)
and the scene generators' traces, on configs/o2.ini and
configs/infinite_reality.ini, runs `fragsim bench --mode cycle` once and
`fragsim bench --mode sampled` for each sampling setting below, and writes
docs/sampling.md (per trace: frames, speed-up, error against full cycle mode,
the estimate sampled mode reports, and whether the error lies within it) and
docs/sampling_error.png (error against speed-up, one point per trace, config
and setting).  Times are `bench`'s replay seconds (from decoded calls, the
load excluded), repeated (at most 64 times) as often as MIN_SECONDS needs at
the rate of a first run.

Environment: BUILD (build), OUT (build/sampling), SCALE (100000 triangles per
frame for the scenes), FRAMES (20), LONG_FRAMES (100, the long traces),
QUICK=1 (three programs, two scenes, the default setting only: for tests).
"""
import json
import math
import os
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
BUILD = os.path.join(ROOT, os.environ.get('BUILD', 'build'))
OUT = os.path.join(ROOT, os.environ.get('OUT', os.path.join('build', 'sampling')))
QUICK = os.environ.get('QUICK') == '1'
SCALE = os.environ.get('SCALE', '100000')
FRAMES = int(os.environ.get('FRAMES', '20'))
LONG_FRAMES = int(os.environ.get('LONG_FRAMES', '100'))
MIN_SECONDS = float(os.environ.get('MIN_SECONDS', '0.2'))
DOC = os.environ.get('DOC', os.path.join(ROOT, 'docs', 'sampling.md'))
PLOT = os.environ.get('PLOT', os.path.join(ROOT, 'docs', 'sampling_error.png'))
CONFIGS = [('O2', 'configs/o2.ini'), ('InfiniteReality', 'configs/infinite_reality.ini')]
# Sampling settings (the [sampling] keys of `fragsim config --list`): the
# defaults, a denser and a sparser one, for the error-against-speed-up plot.
SETTINGS = [
    ('default', {}),
    # one pass: no resampling (sampling.max_error = 0), the estimate only reported
    ('one pass', {'max_error': 0}),
    ('dense', {'frames': 3, 'frame_tiles': 4, 'every': 4, 'tiles': 16}),
    ('sparse', {'frames': 15, 'frame_tiles': 64, 'every': 20, 'tiles': 256}),
]
FRAGSIM = os.path.join(BUILD, 'fragsim')
SCENEGEN = os.path.join(BUILD, 'scenegen')


def run_json(args):
    r = subprocess.run(args, capture_output=True, text=True)
    if r.returncode != 0:
        raise SystemExit('sampling-study: %s failed (%d): %s' % (' '.join(args), r.returncode, r.stderr.strip()))
    return json.loads(r.stdout.strip().splitlines()[-1])


def config_file(base, setting):
    """The config with the setting's [sampling] keys appended (the reader
    takes the last value of a key)."""
    name, keys = setting
    if not keys:
        return os.path.join(ROOT, base)
    path = os.path.join(OUT, '%s.%s.ini' % (os.path.basename(base)[:-4], name))
    with open(os.path.join(ROOT, base)) as f, open(path, 'w') as g:
        g.write(f.read())
        g.write('\n[sampling]\n' + ''.join('%s = %d\n' % kv for kv in keys.items()))
    return path


def bench(trace, mode, cfg):
    """One bench line: a run, and if that took less than MIN_SECONDS, one of as
    many repetitions as MIN_SECONDS needs at its rate (at most 64); seconds
    per run."""
    j = run_json([FRAGSIM, 'bench', '--mode', mode, '--config', cfg, '--repeat', '1', trace])
    repeat = 1
    if 0 < j['seconds'] < MIN_SECONDS:
        # one more run, as many repetitions as MIN_SECONDS needs at this rate
        repeat = min(64, math.ceil(MIN_SECONDS / j['seconds']))
        j = run_json([FRAGSIM, 'bench', '--mode', mode, '--config', cfg, '--repeat', str(repeat), trace])
    j['seconds'] /= repeat  # bench adds seconds and frames up over the runs
    j['frames'] //= repeat
    j['repeat'] = repeat
    return j


def traces():
    progs = os.path.join(ROOT, 'tests', 'conformance', 'programs')
    names = sorted(f for f in os.listdir(progs) if f.endswith('.trace'))
    if QUICK:
        names = [n for n in names if n in ('glxgears.trace', 'atlantis.trace', 'morph3d.trace')]
    out = [('program', n[:-6], os.path.join(progs, n)) for n in names]
    scenes = [('city', SCALE, FRAMES), ('norwich', SCALE, FRAMES), ('cathedrals', SCALE, FRAMES),
              ('forest', SCALE, FRAMES), ('garbage', SCALE, FRAMES), ('terrain', SCALE, FRAMES),
              ('textured', 'small', FRAMES), ('bench8', SCALE, 1),
              ('city', 'small', LONG_FRAMES), ('garbage', SCALE, LONG_FRAMES)]
    if QUICK:
        scenes = [('cathedrals', '20000', 6), ('bench8', '20000', 1)]
    for scene, scale, frames in scenes:
        path = os.path.join(OUT, '%s_%s_%d.trace' % (scene, scale, frames))
        if not os.path.exists(path):
            args = [SCENEGEN, scene, '--scale', scale, '-o', path]
            if frames > 1:
                args[4:4] = ['--frames', str(frames)]
            subprocess.run(args, check=True, stdout=subprocess.DEVNULL)
        out.append(('scene', '%s (%s, %d frames)' % (scene, scale, frames), path))
    return out


def main():
    os.makedirs(OUT, exist_ok=True)
    for tool in (FRAGSIM, SCENEGEN):
        if not os.path.exists(tool):
            raise SystemExit('sampling-study: %s not built (make all)' % tool)
    settings = SETTINGS[:1] if QUICK else SETTINGS
    rows = []
    for kind, name, path in traces():
        for cname, cbase in CONFIGS:
            full = bench(path, 'cycle', os.path.join(ROOT, cbase))
            for st in settings:
                s = bench(path, 'sampled', config_file(cbase, st))
                err = (s['cycles'] - full['cycles']) / full['cycles'] if full['cycles'] else 0.0
                rows.append({'kind': kind, 'trace': name, 'config': cname, 'setting': st[0],
                             'frames': full['frames'], 'cycles': full['cycles'], 'sampled_cycles': s['cycles'],
                             'cycle_s': full['seconds'], 'sampled_s': s['seconds'],
                             'speedup': full['seconds'] / s['seconds'] if s['seconds'] > 0 else float('inf'),
                             'error': err, 'estimate': s['error_estimate'], 'passes': s.get('passes', 1)})
                r = rows[-1]
                print('%-8s %-40s %-16s %-8s frames %4d  speed-up %7.1f  error %+7.2f%%  estimate %6.2f%%' % (
                    kind, name, cname, st[0], r['frames'], r['speedup'], 100 * err, 100 * r['estimate']), flush=True)
    with open(os.path.join(OUT, 'sampling.json'), 'w') as f:
        json.dump(rows, f, indent=1)
    write_doc(rows)
    write_plot(rows)
    return 0


def geomean(xs):
    xs = [x for x in xs if x > 0 and math.isfinite(x)]
    return math.exp(sum(math.log(x) for x in xs) / len(xs)) if xs else float('nan')


def summary(rows, setting):
    lines = ['| config | traces | abs(error) <= 2% | abs(error) <= its estimate | worst error | '
             'geomean speed-up, >= 5 frames | geomean speed-up, >= 100 frames |', '|---|---|---|---|---|---|---|']
    for cname, _ in CONFIGS:
        rs = [r for r in rows if r['config'] == cname and r['setting'] == setting]
        if not rs:
            continue
        worst = max(rs, key=lambda r: abs(r['error']))
        lines.append('| %s | %d | %d | %d | %+.2f%% (%s) | %.1fx (%d traces) | %.1fx (%d traces) |' % (
            cname, len(rs), sum(abs(r['error']) <= 0.02 for r in rs),
            sum(abs(r['error']) <= r['estimate'] for r in rs), 100 * worst['error'], worst['trace'],
            geomean([r['speedup'] for r in rs if r['frames'] >= 5]), sum(r['frames'] >= 5 for r in rs),
            geomean([r['speedup'] for r in rs if r['frames'] >= 100]), sum(r['frames'] >= 100 for r in rs)))
    return lines


def write_doc(rows):
    settings = []
    for r in rows:
        if r['setting'] not in settings:
            settings.append(r['setting'])
    L = ['# Sampled mode against full cycle mode', '',
         'Generated by `make sampling-study` (scripts/sampling_study.py); do not edit.', '',
         'Every program trace of the conformance corpus (tests/conformance/programs, captured',
         'programs the sampler was not tuned on: 4 frames each) and the scene generators\' traces',
         '(%s triangles per frame; 20 frames, two of %d), on O2 and InfiniteReality.' % (SCALE, LONG_FRAMES),
         'Sampled mode simulates traces of 3 to 5 frames in full (too short to sample with an',
         'error estimate, docs/cycle_model.md): the 4-frame programs have error 0 and speed-up about 1.',
         'Error: sampled mode\'s total cycles against full cycle mode\'s; estimate: the error',
         'sampled mode reports for itself (`error_estimate` of `fragsim bench`: the half-width of a',
         '95% confidence interval, docs/cycle_model.md); passes: the replays `sampling.max_error`',
         '(default 2%) took, the last one full simulation where sampling could not meet it;',
         'speed-up: full cycle mode\'s replay time over sampled mode\'s over all passes (load',
         'excluded).  Settings: the',
         '`[sampling]` keys, ' + '; '.join('%s: %s' % (n, ', '.join('%s = %d' % kv for kv in k.items()) or
                                                      'the defaults') for n, k in SETTINGS if n in settings) + '.', '']
    for st in settings:
        L += ['## Summary, %s setting' % st, ''] + summary(rows, st) + ['']
    L += ['![error against speed-up](sampling_error.png)', '',
          '## Per trace, default setting', '',
          '| trace | config | frames | full cycles | speed-up | error | estimate | within estimate | within 2% | passes |',
          '|---|---|---|---|---|---|---|---|---|---|']
    for r in rows:
        if r['setting'] != 'default':
            continue
        L.append('| %s | %s | %d | %d | %.1f | %+.2f%% | %.2f%% | %s | %s | %d |' % (
            r['trace'], r['config'], r['frames'], r['cycles'], r['speedup'], 100 * r['error'],
            100 * r['estimate'], 'yes' if abs(r['error']) <= r['estimate'] else 'no',
            'yes' if abs(r['error']) <= 0.02 else 'no', r['passes']))
    with open(DOC, 'w') as f:
        f.write('\n'.join(L) + '\n')
    print('sampling-study: wrote %s' % DOC)


def write_plot(rows):
    data = os.path.join(OUT, 'sampling_plot.dat')
    with open(data, 'w') as f:
        for st, _ in SETTINGS:
            f.write('# %s\n' % st)
            for r in rows:
                if r['setting'] == st and math.isfinite(r['speedup']):
                    f.write('%.4f %.4f\n' % (r['speedup'], max(1e-3, 100 * abs(r['error']))))
            f.write('\n\n')
    script = ('set terminal pngcairo size 800,500\nset output "%s"\nset logscale xy\n'
              'set xlabel "speed-up over full cycle mode"\nset ylabel "|error| (%%)"\n'
              'set key top left\nset grid\n' % PLOT)
    plots = ['"%s" index %d title "%s" with points pt %d' % (data, i, st, 7 + 2 * i)
             for i, (st, _) in enumerate(SETTINGS) if any(r['setting'] == st for r in rows)]
    script += 'plot ' + ', '.join(plots) + ', 2 title "2%" with lines dt 2\n'
    r = subprocess.run(['gnuplot'], input=script, capture_output=True, text=True)
    if r.returncode != 0:
        raise SystemExit('sampling-study: gnuplot failed: %s' % r.stderr.strip())
    print('sampling-study: wrote %s' % PLOT)


if __name__ == '__main__':
    sys.exit(main())
