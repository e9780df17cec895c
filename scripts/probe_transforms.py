#!/usr/bin/env python3
"""Probes of an unseen recording: a walk transformed as another user's
recording could differ from it, replayed, and compared with the walk as
recorded (docs/robustness.md, "Probes of an unseen recording").

Each LOG is converted to our CSV (`bin/harness convert`), transformed, written
to a scratch directory and replayed (`bin/harness replay --json -`):
- mounting: both triads turned by 90 and 180 deg about x, y and z and by an
  arbitrary rotation (a proper rotation: the closure and the path length
  should not move); one axis of both triads reversed (a left-handed frame, a
  mis-wired sensor: the gyro, a pseudo-vector, then reads the wrong way
  against the accelerometer); the accelerometer's sign reversed (a sensor
  that reports gravity instead of the specific force: a mirror image);
- units: accelerometer in g and mg, gyro in deg/s, time in ms and us;
- sensor errors: a gyro bias of 2 deg/s, an accelerometer bias of 0.5
  m/s^2 (both constant, as a turn-on bias), a gyro scale error of +2 %;
- time: Unix seconds (1.7e9 s, printed to the microsecond); stamps rounded
  as float32 seconds at 1e4, 1e5 and 1e6 s; stamps jittered by +-30 % of
  the period; 10 % of the samples dropped at random; --rate 100 and 50;
- a stand of 60 and 300 s inserted at the first stance after the walk's
  middle (its specific force, with the noise and gyro of the log's first
  1.5 s, a standstill in every shared walk), with and without the ZARU.

Prints one markdown row per probe: exit status, return-to-start error (3-D),
step-to-step distance, strides, ZUPT share, and what the harness said (the
first warning, error or note). The rotation rows end with the largest change
of the closure and of the distance over the proper rotations.

Usage: /usr/bin/python3 scripts/probe_transforms.py LOG... [--tmp DIR]
(HARNESS=path overrides bin/harness). Takes about 15 s per log.
"""
import json
import os
import subprocess
import sys
import tempfile

import numpy as np

H = os.environ.get('HARNESS', 'bin/harness')


def rot(axis, deg):
    a = np.radians(deg)
    c, s = np.cos(a), np.sin(a)
    if axis == 'x':
        return np.array([[1, 0, 0], [0, c, -s], [0, s, c]])
    if axis == 'y':
        return np.array([[c, 0, s], [0, 1, 0], [-s, 0, c]])
    return np.array([[c, -s, 0], [s, c, 0], [0, 0, 1]])


def turn(R):
    def f(d):
        d[:, 1:4] = d[:, 1:4] @ R.T
        d[:, 4:7] = d[:, 4:7] @ R.T
    return f


def scale(cols, k):
    def f(d):
        d[:, cols] *= k
    return f


def float32_time(t0):
    def f(d):
        d[:, 0] = (d[:, 0] + t0).astype(np.float32)
    return f


def jitter(d):
    dt = np.median(np.diff(d[:, 0]))
    d[:, 0] += np.random.default_rng(1).uniform(-0.3, 0.3, len(d)) * dt
    d[:, 0] = np.maximum.accumulate(d[:, 0])


PROPER = [('x 90', rot('x', 90)), ('x 180', rot('x', 180)), ('y 90', rot('y', 90)), ('y 180', rot('y', 180)),
          ('z 90', rot('z', 90)), ('z 180', rot('z', 180)),
          ('z 37, y -23, x 61', rot('z', 37) @ rot('y', -23) @ rot('x', 61))]
OTHERS = [('z reversed (left-handed)', turn(np.diag([1.0, 1.0, -1.0])), '%.9g'),
          ('accelerometer sign reversed', scale([1, 2, 3], -1.0), '%.9g'),
          ('accel in g', scale([1, 2, 3], 1 / 9.80665), '%.9g'),
          ('accel in mg', scale([1, 2, 3], 1 / 0.00980665), '%.9g'),
          ('gyro in deg/s', scale([4, 5, 6], 180 / np.pi), '%.9g'),
          ('gyro bias 2 deg/s (x, -0.7 y, 0.5 z)', lambda d: d.__setitem__((slice(None), slice(4, 7)), d[:, 4:7] + np.radians(2.0) * np.array([1, -0.7, 0.5])), '%.9g'),
          ('accelerometer bias 0.5 m/s^2 (x, -0.7 y, 0.5 z)', lambda d: d.__setitem__((slice(None), slice(1, 4)), d[:, 1:4] + 0.5 * np.array([1, -0.7, 0.5])), '%.9g'),
          ('gyro scale +2 %', scale([4, 5, 6], 1.02), '%.9g'),
          ('time in ms', scale([0], 1e3), '%.17g'),
          ('time in us', scale([0], 1e6), '%.17g'),
          ('Unix time 1.7e9 s', lambda d: d.__setitem__((slice(None), 0), d[:, 0] + 1.7e9), '%.6f'),
          ('float32 time at 1e4 s', float32_time(1e4), '%.9f'),
          ('float32 time at 1e5 s', float32_time(1e5), '%.9f'),
          ('float32 time at 1e6 s', float32_time(1e6), '%.9f'),
          ('stamps jittered 30 %', jitter, '%.9f')]


def insert_stand(d0, trajectory, stand_s, path):
    """Write to path the log d0 (rows t, ax..gz) with a stand of stand_s s
    inserted at the first stance after its middle (0.2 s in stance in the
    replay's trajectory CSV): that stance's accelerometer mean with the noise
    of the log's own first 1.5 s (a standstill in every shared walk), and
    that standstill's gyro (its bias and noise), what a stop to talk looks
    like. Returns the time of that stance and the stand's first and last
    time stamps."""
    st = np.genfromtxt(trajectory, delimiter=',', names=True)['stance']
    dt = np.median(np.diff(d0[:, 0]))
    n = int(0.2 / dt)
    m = len(d0) // 2
    while not st[m:m + n].all():
        m += 1
    still = d0[d0[:, 0] < 1.5]
    blk = np.tile(still[:, 1:], (int(np.ceil(stand_s / (len(still) * dt))), 1))[:int(stand_s / dt)]
    blk[:, 0:3] += d0[m:m + n, 1:4].mean(0) - still[:, 1:4].mean(0)
    tin = d0[m + n - 1, 0] + dt * np.arange(1, len(blk) + 1)
    after = d0[m + n:].copy()
    after[:, 0] += tin[-1] - after[0, 0] + dt
    np.savetxt(path, np.vstack([d0[:m + n], np.column_stack([tin, blk]), after]), delimiter=',',
               header='t,ax,ay,az,gx,gy,gz', comments='', fmt='%.9f')
    return d0[m, 0], tin[0], tin[-1]


def replay(path, extra=()):
    r = subprocess.run([H, 'replay', path, '--json', '-', *extra], capture_output=True, text=True)
    try:
        j = json.loads(r.stdout)
    except ValueError:
        j = {}
    said = [ln.strip() for ln in r.stderr.splitlines() if 'warning:' in ln or 'error:' in ln or ln.startswith('note')
            or 'MISMATCH' in ln]
    return r.returncode, j, said[0] if said else ''


def row(name, rc, j, said):
    def num(k, fmt):
        v = j.get(k)
        return fmt % v if isinstance(v, (int, float)) else '-'
    said = said.replace('|', '/')
    if len(said) > 110:
        said = said[:107] + '...'
    print('| %s | %d | %s | %s | %s | %s | %s |' % (name, rc, num('return_error_3d_m', '%.3f'),
                                                     num('distance_m', '%.2f'), num('strides', '%d'),
                                                     num('stance_fraction', '%.3f'), said))
    sys.stdout.flush()


def main():
    args = sys.argv[1:]
    tmp = None
    if '--tmp' in args:
        i = args.index('--tmp')
        tmp = args[i + 1]
        del args[i:i + 2]
    if not args:
        sys.exit(__doc__)
    tmp = tmp or tempfile.mkdtemp(prefix='probe_')
    os.makedirs(tmp, exist_ok=True)
    for log in args:
        base = os.path.join(tmp, os.path.basename(log) + '.csv')
        subprocess.run([H, 'convert', log, base], check=True, capture_output=True)
        d0 = np.loadtxt(base, delimiter=',', skiprows=1)
        print('\n%s\n' % log)
        print('| probe | exit | closure 3-D (m) | distance (m) | strides | ZUPT share | said |')
        print('| --- | ---: | ---: | ---: | ---: | ---: | --- |')
        rc, j0, said = replay(base)
        row('as recorded', rc, j0, said)
        dc, dd = 0.0, 0.0
        for name, R in PROPER:
            d = d0.copy()
            turn(R)(d)
            p = os.path.join(tmp, 'p.csv')
            np.savetxt(p, d, delimiter=',', header='t,ax,ay,az,gx,gy,gz', comments='', fmt='%.9g')
            rc, j, said = replay(p)
            row('turned ' + name, rc, j, said)
            if j.get('return_error_3d_m') is not None:
                dc = max(dc, abs(j['return_error_3d_m'] - j0['return_error_3d_m']))
                dd = max(dd, abs(j['distance_m'] - j0['distance_m']))
        print('| proper rotations: largest change | | %.4f | %.4f | | | |' % (dc, dd))
        for name, f, fmt in OTHERS:
            d = d0.copy()
            f(d)
            p = os.path.join(tmp, 'p.csv')
            np.savetxt(p, d, delimiter=',', header='t,ax,ay,az,gx,gy,gz', comments='', fmt=fmt)
            rc, j, said = replay(p)
            row(name, rc, j, said)
        keep = np.random.default_rng(2).uniform(size=len(d0)) > 0.1
        p = os.path.join(tmp, 'p.csv')
        np.savetxt(p, d0[keep], delimiter=',', header='t,ax,ay,az,gx,gy,gz', comments='', fmt='%.9f')
        row('10 % of samples dropped', *replay(p))
        for r in (100, 50):
            row('--rate %d' % r, *replay(base, ('--rate', str(r))))
        tr = os.path.join(tmp, 'tr.csv')
        subprocess.run([H, 'replay', base, '--out', tr, '--quiet'], check=True, capture_output=True)
        for stand_s in (60, 300):
            p = os.path.join(tmp, 'p.csv')
            at, _, _ = insert_stand(d0, tr, stand_s, p)
            row('stand of %d s inserted at %.1f s' % (stand_s, at), *replay(p))
            row('the same, --param zaru=1 --param zaru_after_s=1', *replay(p, ('--param', 'zaru=1', '--param',
                                                                             'zaru_after_s=1')))


if __name__ == '__main__':
    main()
