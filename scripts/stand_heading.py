#!/usr/bin/env python3
"""Where a stand inserted in mid-walk costs closure (docs/robustness.md,
"Probes of an unseen recording"): for each LOG and stand length, the stand
of scripts/probe_transforms.py (insert_stand) is replayed with the default
filter and with the ZARU (--param zaru=1 --param zaru_after_s=1), and the
script prints
- the heading's change during the stand and the position's;
- the closure (the replay's return_error_3d_m) of the walk with the stand
  and of the walk as recorded, and that of the walk as recorded with the
  rest after the stand
  turned by the stand's heading change about the stand's point (what the
  stand's heading drift alone costs);
- the heading of the walk with the stand against the walk as recorded at
  the end (the rest drifting on after the stand), and the filter's gyro
  bias estimate there in both.

Usage: /usr/bin/python3 scripts/stand_heading.py LOG... [--stand S]...
(default stands 60 and 300 s; HARNESS=path overrides bin/harness). About
10 s per log and stand.
"""
import json
import os
import subprocess
import sys
import tempfile

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from probe_transforms import H, insert_stand  # noqa: E402

ZARU = ('--param', 'zaru=1', '--param', 'zaru_after_s=1')


def closure(log, extra=()):
    r = subprocess.run([H, 'replay', log, '--json', '-', '--quiet', *extra], check=True, capture_output=True,
                       text=True)
    return json.loads(r.stdout)['return_error_3d_m']


def traj(path):
    o = np.genfromtxt(path, delimiter=',', names=True)
    return o, np.column_stack([o['x'], o['y'], o['z']]), np.unwrap(o['yaw'])


def main():
    args = sys.argv[1:]
    stands = []
    while '--stand' in args:
        i = args.index('--stand')
        stands.append(float(args[i + 1]))
        del args[i:i + 2]
    if not args:
        sys.exit(__doc__)
    stands = stands or [60.0, 300.0]
    with tempfile.TemporaryDirectory() as tmp:
        for log in args:
            base = os.path.join(tmp, 'b.csv')
            subprocess.run([H, 'convert', log, base], check=True, capture_output=True)
            d0 = np.loadtxt(base, delimiter=',', skiprows=1)
            tr = os.path.join(tmp, 'tr.csv')
            subprocess.run([H, 'replay', base, '--out', tr, '--quiet'], check=True, capture_output=True)
            b, pb, yb = traj(tr)
            print('%s: closure as recorded %.3f m' % (os.path.basename(log), closure(base)))
            print('| stand (s) | filter | heading change in the stand (deg) | position change in it (m) | closure (m) '
                  '| closure, the rest turned by the heading change (m) | heading off at the end (deg) '
                  '| gyro bias z at the end, with the stand / as recorded (rad/s) |')
            print('| ---: | --- | ---: | ---: | ---: | ---: | ---: | ---: |')
            for stand_s in stands:
                p = os.path.join(tmp, 'p.csv')
                _, t0, t1 = insert_stand(d0, tr, stand_s, p)
                for name, extra in (('default', ()), ('ZARU', ZARU)):
                    out = os.path.join(tmp, 'o.csv')
                    subprocess.run([H, 'replay', p, '--out', out, '--quiet', *extra], check=True,
                                   capture_output=True)
                    o, po, yo = traj(out)
                    i0, i1 = np.searchsorted(o['t'], t0), np.searchsorted(o['t'], t1)
                    dpsi = yo[i1] - yo[i0]
                    k = np.searchsorted(b['t'], t0 - 1e-9)
                    c, s = np.cos(dpsi), np.sin(dpsi)
                    turned = pb[k] + (po[i1] - po[i0]) + np.array([[c, -s, 0], [s, c, 0], [0, 0, 1]]) @ (pb[-1] - pb[k])
                    print('| %g | %s | %.2f | %.3f | %.3f | %.3f | %.2f | %.5f / %.5f |' % (
                        stand_s, name, np.degrees(dpsi), np.linalg.norm(po[i1] - po[i0]),
                        closure(p, extra), np.linalg.norm(turned - pb[0]),
                        np.degrees(yo[-1] - yb[-1]), o['bgz'][-1], b['bgz'][-1]))


if __name__ == '__main__':
    main()
