#!/usr/bin/env python3
"""Does a walk's height change per stride depend on the walking direction?
(docs/xio-climb.md, "Round 6: the climb is the same in every direction").

For each log, runs `bin/harness replay LOG --out CSV` (extra replay options
after `--`) and takes the stance mid-points as results.md does (the middle
frame of every run of the replay's `stance` column lasting at least
MIN_STANCE_S). For each stride between consecutive mid-points it forms the
height change dh (up positive), the horizontal step L and its direction psi
in the n frame, and fits by least squares

    dh / L = c0 + c1 cos(psi) + c2 sin(psi).

An error fixed in the navigation frame (a tilt of the frame the filter
believes level, a gravity direction, an accelerometer bias held in n) makes
dh proportional to the step's component along one horizontal direction:
c1, c2, which cancel around a closed loop. An error that every stride makes
in the foot's own frame (a misalignment, a delay, the landing) gives the
same climb in every direction: c0. Standard errors from the residuals.

Usage: /usr/bin/python3 scripts/climb_heading.py LOG... [-- REPLAY OPTIONS]
Prints one markdown row per log.
"""
import os
import sys

import numpy as np

from replay_runs import split_args, trajectories

MIN_STANCE_S = 0.05
MIN_STEP_M = 0.3  # shorter steps (shuffles, turns on the spot) have no direction


def midpoints(d):
    t, st = d['t'], d['stance'] > 0
    mids, k, n = [], 0, len(t)
    while k < n:
        if st[k]:
            j = k
            while j + 1 < n and st[j + 1]:
                j += 1
            if t[j] - t[k] >= MIN_STANCE_S:
                mids.append((k + j) // 2)
            k = j + 1
        else:
            k += 1
    return mids


def fit(csv_path):
    d = np.genfromtxt(csv_path, delimiter=',', names=True)
    m = midpoints(d)
    x, y, h = d['x'][m], d['y'][m], -d['z'][m]
    dx, dy, dh = np.diff(x), np.diff(y), np.diff(h)
    L = np.hypot(dx, dy)
    ok = L >= MIN_STEP_M
    psi = np.arctan2(dy[ok], dx[ok])
    A = np.column_stack((np.ones(ok.sum()), np.cos(psi), np.sin(psi)))
    r = dh[ok] / L[ok]
    c, *_ = np.linalg.lstsq(A, r, rcond=None)
    res = r - A @ c
    dof = max(len(r) - 3, 1)
    cov = np.linalg.inv(A.T @ A) * (res @ res) / dof
    se = np.sqrt(np.diag(cov))
    return len(r), L[ok].sum(), c, se, np.std(res, ddof=3 if len(r) > 3 else 0)


def main(argv):
    logs, opts = split_args(argv, __doc__)
    print('| log | strides | path (m) | c0 (%) | c1 (%) | c2 (%) | residual sd (%) |')
    print('| --- | ---: | ---: | ---: | ---: | ---: | ---: |')
    for log, out in trajectories(logs, opts):
        n, sL, c, se, sd = fit(out)
        cells = ['%+.2f ± %.2f' % (100.0 * c[i], 100.0 * se[i]) for i in range(3)]
        print('| %s | %d | %.1f | %s | %.2f |' % (os.path.basename(log), n, sL, ' | '.join(cells), 100.0 * sd))


if __name__ == '__main__':
    main(sys.argv[1:])
