#!/usr/bin/env python3
"""Invariance probes of `harness psd` and `harness allan` on a real log
(docs/robustness.md, "Probes of an unseen recording").

The log (our CSV, `bin/harness convert` of any format) is written again
transformed and each copy analysed with --json; the figures are compared
with the log's as recorded, channel by channel:
- axes rotated x -> y -> z (both triads; ay of the copy against ax), every
  sign reversed, both triads turned 180 deg about z: psd and allan must be
  unchanged (each channel's figures are those of its source channel);
- the time column shifted by 1000 s; accelerometer in g and gyro in deg/s
  read with --units accel=g,gyro=deg/s: unchanged;
- the first 5 s cut: psd within its resolution (the bandwidth moves by a
  fraction of resolution_hz, the rounded frequencies equal), allan within
  its intervals;
- psd: every second sample (half the rate; docs/psd.md says what changes);
- allan: the first or the last 10 % cut (the changes, per channel, below).
psd runs with the default (the paper's setting) and --dc global --nfft 256.

Prints per transform the largest relative difference of the total power,
the largest bandwidth change in resolutions and any rounded frequency that
moved (psd); the largest relative difference of the OADEV table and of the
paper's and the corrected parameters (allan), and the warnings that differ.
Usage: /usr/bin/python3 scripts/probe_psd_allan.py CSV [psd|allan|both]
[--tmp DIR] (HARNESS=path overrides bin/harness). The 2.78 h ADIS16405 log
takes about a minute.
"""
import json
import os
import subprocess
import sys
import tempfile

import numpy as np

H = os.environ.get('HARNESS', 'bin/harness')
W = None
AX = ['ax', 'ay', 'az', 'gx', 'gy', 'gz']
HDR = 't,ax,ay,az,gx,gy,gz'


def write(d, p, tfmt='%.9f'):
    with open(p, 'w') as f:
        f.write(HDR + '\n')
        np.savetxt(f, d, delimiter=',', fmt=[tfmt] + ['%.17g'] * 6)


def run(cmd, p, extra=()):
    j = p + '.%s.json' % cmd
    r = subprocess.run([H, cmd, p, '--json', j, *extra] + (['--no-sim', '--quiet'] if cmd == 'allan' else []),
                       capture_output=True, text=True)
    warn = [l.replace(p, 'LOG') for l in r.stderr.splitlines() if 'warning' in l or 'error' in l]
    try:
        return r.returncode, json.load(open(j)), warn
    except Exception:
        return r.returncode, None, warn + [r.stderr[-300:]]


# transforms: (name, func(d)->d, channel map new->old, extra args)
PERM = {'ax': 'az', 'ay': 'ax', 'az': 'ay', 'gx': 'gz', 'gy': 'gx', 'gz': 'gy'}  # x->y->z


def t_perm(d):
    e = d.copy()
    e[:, 2], e[:, 3], e[:, 1] = d[:, 1], d[:, 2], d[:, 3]
    e[:, 5], e[:, 6], e[:, 4] = d[:, 4], d[:, 5], d[:, 6]
    return e


def t_flip(d):
    e = d.copy(); e[:, 1:] *= -1; return e


def t_rz180(d):
    e = d.copy(); e[:, [1, 2, 4, 5]] *= -1; return e


def t_cut(s):
    def f(d):
        return d[d[:, 0] >= d[0, 0] + s]
    return f


def t_shift(d):
    e = d.copy(); e[:, 0] += 1000.0; return e


def t_units(d):
    e = d.copy(); e[:, 1:4] /= 9.80665; e[:, 4:7] *= 180 / np.pi; return e


ID = {a: a for a in AX}


def rel(a, b):
    if a is None or b is None:
        return float('nan') if a != b else 0.0
    return abs(a - b) / max(abs(a), abs(b), 1e-300)


def cmp_psd(j0, j1, cmap, name):
    r0, r1 = j0['result'], j1['result']
    res = max(r0['resolution_hz'], r1['resolution_hz'])
    worst_p, worst_bw, fsdiff = 0, 0, []
    for new, old in cmap.items():
        a0, a1 = r0['axes'].get(old, {}), r1['axes'].get(new, {})
        if not a0 or not a1:
            if a0 != a1:
                fsdiff.append('%s empty mismatch' % new)
            continue
        worst_p = max(worst_p, rel(a0['total_power'], a1['total_power']))
        worst_bw = max(worst_bw, abs(a0['bandwidth_hz'] - a1['bandwidth_hz']) / res)
        if a0['fs_rounded_hz'] != a1['fs_rounded_hz']:
            fsdiff.append('%s %g->%g (bw %.2f->%.2f)' % (new, a0['fs_rounded_hz'], a1['fs_rounded_hz'],
                                                         a0['bandwidth_hz'], a1['bandwidth_hz']))
    for k in ('fs_hz', 'accel_fs_hz', 'gyro_fs_hz', 'fs_is_lower_bound', 'band_at_nyquist', 'fs_above_log_rate'):
        v0 = r0.get(k, j0.get(k)); v1 = r1.get(k, j1.get(k))
        if v0 != v1:
            fsdiff.append('%s %s->%s' % (k, v0, v1))
    print('  psd %-10s rate %.6g->%.6g  maxrel total_power %.2e  max |dbw|/res %.3f  %s' % (
        name, j0['rate_hz'], j1['rate_hz'], worst_p, worst_bw, '; '.join(fsdiff) or 'fs equal'))


AKEYS = [('paper', 'sigma_v'), ('paper', 'bs'), ('paper', 't_bs_s'), ('paper', 'sigma_bias'),
         ('corrected', 'sigma_v'), ('corrected', 'tau_s'), ('corrected', 'sigma_bias'),
         ('profile', 'sigma_v'), ('profile', 'tau_s'), ('profile', 'sigma_bias')]


def cmp_allan(j0, j1, cmap, name, show=False):
    c0 = {c['name']: c for c in j0['channels']}
    c1 = {c['name']: c for c in j1['channels']}
    worst = {}
    notes = []
    tab = 0
    for new, old in cmap.items():
        a, b = c0[old], c1[new]
        for s, k in AKEYS:
            v0, v1 = a.get(s, {}).get(k), b.get(s, {}).get(k)
            d = rel(v0, v1)
            key = {'paper': 'paper', 'corrected': 'fit', 'profile': 'profile'}[s] + '.' + k
            if not (d <= worst.get(key, 0)):
                worst[key] = d
                if show:
                    notes.append('%s %s %s->%s' % (new, key, v0, v1))
        if a.get('corrected', {}).get('ar1_identified') != b.get('corrected', {}).get('ar1_identified'):
            notes.append('%s ar1_identified %s->%s' % (new, a['corrected'].get('ar1_identified'),
                                                       b['corrected'].get('ar1_identified')))
        if a.get('profile', {}).get('basis') != b.get('profile', {}).get('basis'):
            notes.append('%s basis changed' % new)
        t0 = {r['m']: r['oadev'] for r in a['table']}
        for r in b['table']:
            if r['m'] in t0 and t0[r['m']] is not None and r['oadev'] is not None:
                tab = max(tab, rel(t0[r['m']], r['oadev']))
    print('  allan %-10s oadev %.1e | ' % (name, tab) + ' '.join('%s %.1e' % kv for kv in worst.items()))
    for n in notes[:12]:
        print('     ', n)


def main():
    global W
    args = sys.argv[1:]
    if '--tmp' in args:
        i = args.index('--tmp')
        W = args[i + 1]
        del args[i:i + 2]
    if not args:
        sys.exit(__doc__)
    W = W or tempfile.mkdtemp(prefix='probe_')
    os.makedirs(W, exist_ok=True)
    src = args[0]
    what = args[1] if len(args) > 1 else 'both'
    tag = os.path.basename(src).replace('.csv', '')
    d = np.loadtxt(src, delimiter=',', skiprows=1)
    base = os.path.join(W, tag + '_base.csv')
    write(d, base)
    T = [('perm', t_perm, PERM, ()), ('flip', t_flip, ID, ()), ('rz180', t_rz180, ID, ()),
         ('cut5s', t_cut(5.0), ID, ()), ('t+1000', t_shift, ID, ()),
         ('units', t_units, ID, ('--units', 'accel=g,gyro=deg/s'))]
    psd_sets = [(), ('--dc', 'global', '--nfft', '256')]
    outs = {}
    for name, f, cmap, extra in T + [('dec2', lambda x: x[::2], ID, ())]:
        p = os.path.join(W, '%s_%s.csv' % (tag, name))
        write(f(d), p)
        outs[name] = (p, cmap, extra)
    print(src, len(d), 'rows')
    if what in ('psd', 'both'):
        for s in psd_sets:
            rc, j0, w0 = run('psd', base, s)
            print(' psd settings', s or 'default', 'rc', rc, 'fs', j0['result']['fs_hz'],
                  'rate', j0['rate_hz'], 'res', j0['result']['resolution_hz'], w0[:2])
            for name, (p, cmap, extra) in outs.items():
                rc, j1, w1 = run('psd', p, (*s, *extra))
                if j1 is None:
                    print('  psd', name, 'FAILED rc', rc, w1); continue
                cmp_psd(j0, j1, cmap, name)
                if rc != 0 or w1 != w0:
                    print('     rc', rc, 'warnings differ:', [x[:200] for x in w1 if x not in w0],
                          'gone:', [x[:200] for x in w0 if x not in w1])
    if what in ('allan', 'both'):
        rc, j0, w0 = run('allan', base)
        print(' allan rc', rc, w0[:3])
        n = len(d)
        extra_t = [('cut10first', d[n // 10:]), ('cut10last', d[:n - n // 10])]
        for name, dd in extra_t:
            p = os.path.join(W, '%s_%s.csv' % (tag, name))
            write(dd, p)
            outs[name] = (p, ID, ())
        for name, (p, cmap, extra) in outs.items():
            if name == 'dec2':
                continue
            rc, j1, w1 = run('allan', p, extra)
            if j1 is None or 'channels' not in j1:
                print('  allan', name, 'FAILED rc', rc, w1); continue
            cmp_allan(j0, j1, cmap, name, show=name.startswith('cut10'))
            if rc != 0 or w1 != w0:
                print('     rc', rc, 'warnings differ:', [x[:200] for x in w1 if x not in w0],
                      'gone:', [x[:200] for x in w0 if x not in w1])


if __name__ == '__main__':
    main()
