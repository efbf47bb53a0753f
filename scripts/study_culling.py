#!/usr/bin/python3
"""Writes docs/studies/culling.md from the runs of scripts/study_culling.sh
(issue 21, item 6): analogues of Huettner 1999, Tables 3.2, 3.3 and 3.4, for
the O2 and InfiniteReality configurations, with the dissertation's figures
beside them, and per-frame plots like Figs. 3.8-3.11 (gnuplot)."""
import argparse
import csv
import json
import os
import re
import subprocess

CONFIGS = [('o2', 'O2'), ('o2_h99', 'O2-H99'), ('infinite_reality', 'IR')]
HIERS = [('phbvo', 'p-HBVO'), ('dbvs', 'D-BVS'), ('sgi', 'SGI')]
SCENES = ['cathedrals', 'city', 'forest', 'garbage']

# Huettner 1999, Table 3.4 (culled, speed-up over VFC only), O2.
TABLE_3_4 = [('cathedrals', 'vo', 'cathedrals', 91.3, 4.2), ('city', 'vo', 'city', 99.8, 4.8),
             ('forest', 'ac', 'forest AC', 89.0, 3.8), ('forest', 'vo', 'forest V+O', 84.7, 2.6),
             ('garbage', 'vo', 'garbage', 96.0, 7.0)]
# Tables 3.2 (cathedrals) and 3.3 (city), HP B180/fx4 with the HP occlusion
# flag, per hierarchy p-HBVO, D-BVS, SGI.
TABLE_3_2_3 = {
    'cathedrals': {'nodes': (9, 59, 51), 'leaves': (10, 67, 52), 't_vfc': (0.0021, 0.0077, 0.0089),
                   't_occ': (0.0041, 0.0322, 0.027), 't_ren': (0.1361, 0.1239, 0.1426),
                   'rate': (30.0, 25.9, 30.1), 'fps': (12.4, 8.8, 7.8), 'vfc_rate': (33.1, 25.9, 32.2),
                   'vfc_fps': (12.4, 10.8, 9.5)},
    'city': {'nodes': (2722, 266, 420), 'leaves': (2723, 495, 420), 't_vfc': (0.0189, 0.0111, 0.0124),
             't_occ': (0.0541, 0.0318, 0.0332), 't_ren': (0.0073, 0.0831, 0.0787), 'rate': (0.1, 4.1, 3.6),
             'fps': (14.0, 10.9, 11.8), 'vfc_rate': (47.0, 50.7, 50.4), 'vfc_fps': (1.0, 1.4, 1.4)},
}


class Run:
    """One cullstudy run: per-frame counts and, per config, per-frame cycles."""

    def __init__(self, d):
        self.rows = list(csv.DictReader(open(os.path.join(d, 'culling.csv'))))
        log = open(os.path.join(d, 'cullstudy.log')).read()
        m = re.search(r'(\d+) nodes, (\d+) leaves, (\d+) objects', log)
        self.nodes, self.leaves, self.objects = (int(x) for x in m.groups())
        self.cyc = {}
        for c, _ in CONFIGS:
            j = json.load(open(os.path.join(d, c + '.json')))['cycle']
            if len(j['frames']) < len(self.rows):
                raise SystemExit('%s: %d frames replayed for %d rows' % (d, len(j['frames']), len(self.rows)))
            self.cyc[c] = (j['frames'][:len(self.rows)], j['clock_khz'])

    def tris(self):
        return sum(int(r['triangles_rendered']) for r in self.rows)

    def frame_seconds(self, c):
        frames, khz = self.cyc[c]
        return [f['cycles'] / (khz * 1000.0) for f in frames]

    def seconds(self, c, part=None):
        """Mean seconds per frame: all, or the VFC (selection-mode drains),
        occlusion (query latency) or rendering (the rest) part."""
        frames, khz = self.cyc[c]
        tot = 0.0
        for f in frames:
            vfc, occ = f['rendermode_sync_cycles'], f['query_latency']
            v = {None: f['cycles'], 'vfc': vfc, 'occ': occ, 'ren': f['cycles'] - vfc - occ}[part]
            tot += v
        return tot / len(frames) / (khz * 1000.0)


def load(out):
    runs = {}
    for s in SCENES:
        sd = os.path.join(out, s)
        if not os.path.isdir(sd):
            continue
        for name in sorted(os.listdir(sd)):
            method, hier = name.split('-')
            runs[(s, method, hier)] = Run(os.path.join(sd, name))
    return runs


def pct(x):
    return '%.1f%%' % x


def table_3_4(runs):
    out = ['| scene | triangles / frame (DR) | culled (model) | culled (H99) | ' +
           ' | '.join('speed-up %s' % cl for _, cl in CONFIGS) + ' | speed-up (H99, O2) |', '|---|' + '---|' * (4 + len(CONFIGS))]
    for s, m, label, h_cull, h_speed in TABLE_3_4:
        dr, vfc, run = runs[(s, 'dr', 'phbvo')], runs[(s, 'vfc', 'phbvo')], runs[(s, m, 'phbvo')]
        n = len(dr.rows)
        culled = 100.0 * (1 - run.tris() / dr.tris())
        sp = [vfc.seconds(c) / run.seconds(c) for c, _ in CONFIGS]
        out.append('| %s | %s | %s | %s | %s | %.1f |' % (
            label, format(dr.tris() // n, ','), pct(culled), pct(h_cull), ' | '.join('%.2f' % x for x in sp), h_speed))
    return out


def table_hier(runs, scene):
    h99 = TABLE_3_2_3[scene]
    cols = [cl for _, cl in CONFIGS] + ['H99']
    head = '| | ' + ' | '.join('%s %s' % (hl, col) for _, hl in HIERS for col in cols) + ' |'
    out = [head, '|---|' + '---|' * (len(HIERS) * len(cols))]
    dr = runs[(scene, 'dr', 'phbvo')]

    def row(label, key, fn, fmt):
        cells = []
        for i, (h, _) in enumerate(HIERS):
            vals = fn(h)
            cells += [fmt % v for v in vals] + [fmt % h99[key][i]]
        out.append('| %s | %s |' % (label, ' | '.join(cells)))

    vo = lambda h: runs[(scene, 'vo', h)]
    vf = lambda h: runs[(scene, 'vfc', h)]
    row('subdivision nodes (inner)', 'nodes', lambda h: (vo(h).nodes - vo(h).leaves,) * len(CONFIGS), '%d')
    row('leaf nodes', 'leaves', lambda h: (vo(h).leaves,) * len(CONFIGS), '%d')
    for part, label in (('vfc', 'time for VFC [s]'), ('occ', 'time for occlusion [s]'),
                        ('ren', 'time for rendering [s]')):
        row(label, 't_' + part, lambda h, p=part: tuple(vo(h).seconds(c, p) for c, _ in CONFIGS), '%.4f')
    row('render rate [%]', 'rate', lambda h: (100.0 * vo(h).tris() / dr.tris(),) * len(CONFIGS), '%.1f')
    row('frame rate [fps]', 'fps', lambda h: tuple(1 / vo(h).seconds(c) for c, _ in CONFIGS), '%.1f')
    row('render rate of VFC only [%]', 'vfc_rate', lambda h: (100.0 * vf(h).tris() / dr.tris(),) * len(CONFIGS), '%.1f')
    row('frame rate of VFC only [fps]', 'vfc_fps', lambda h: tuple(1 / vf(h).seconds(c) for c, _ in CONFIGS),
        '%.1f')
    return out


def plot(runs, scene, fig, out):
    methods = [m for m in ('dr', 'vfc', 'vo', 'ac') if (scene, m, 'phbvo') in runs]
    dat = os.path.join(out, scene + '_fps.dat')
    with open(dat, 'w') as f:
        f.write('# frame ' + ' '.join('%s_%s' % (m, c) for c, _ in CONFIGS for m in methods) + '\n')
        n = len(runs[(scene, 'dr', 'phbvo')].rows)
        secs = {(m, c): runs[(scene, m, 'phbvo')].frame_seconds(c) for m in methods for c, _ in CONFIGS}
        for i in range(n):
            f.write('%d %s\n' % (i, ' '.join('%.4f' % (1 / secs[(m, c)][i]) for c, _ in CONFIGS for m in methods)))
    png = os.path.join(fig, 'culling_%s.png' % scene)
    names = {'dr': 'DR', 'vfc': 'VFC', 'vo': 'V+O', 'ac': 'AC'}
    plots = []
    col = 2
    for c, cl in CONFIGS:
        for m in methods:
            plots.append("'%s' using 1:%d with linespoints dt %d title '%s %s'" % (
                dat, col, {'o2': 3, 'o2_h99': 1, 'infinite_reality': 2}[c], names[m], cl))
            col += 1
    script = ("set terminal pngcairo size 640,360 font ',9'\nset output '%s'\nset title '%s: frame rate along the "
              "path (cycle model)'\nset xlabel 'frame'\nset ylabel 'frames per second'\nset logscale y\n"
              "set key outside right\nplot %s\n") % (png, scene, ', '.join(plots))
    subprocess.run(['gnuplot'], input=script.encode(), check=True)
    return png


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('--out', required=True)
    ap.add_argument('--doc', required=True)
    ap.add_argument('--fig', required=True)
    ap.add_argument('--frames', type=int, required=True)
    ap.add_argument('--scale', required=True)
    ap.add_argument('--seconds', type=int, required=True)
    ap.add_argument('--jobs', type=int, required=True)
    ap.add_argument('--o2-tri-cycles', required=True)
    a = ap.parse_args()
    runs = load(a.out)
    tmpl = open(os.path.join(os.path.dirname(os.path.abspath(__file__)), 'study_culling.md.in')).read()
    figs = '\n'.join('![%s](%s)' % (s, os.path.relpath(plot(runs, s, a.fig, a.out), os.path.dirname(a.doc)))
                     for s in SCENES)
    subst = {
        'FRAMES': str(a.frames), 'SCALE': a.scale, 'SECONDS': str(a.seconds), 'JOBS': str(a.jobs),
        'RUNS': str(len(runs)), 'O2_TRI_CYCLES': a.o2_tri_cycles, 'TABLE_3_4': '\n'.join(table_3_4(runs)),
        'TABLE_3_2': '\n'.join(table_hier(runs, 'cathedrals')), 'TABLE_3_3': '\n'.join(table_hier(runs, 'city')),
        'FIGURES': figs,
    }
    for k, v in subst.items():
        tmpl = tmpl.replace('@%s@' % k, v)
    open(a.doc, 'w').write(tmpl)


if __name__ == '__main__':
    main()
