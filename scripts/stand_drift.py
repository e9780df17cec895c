#!/usr/bin/env python3
"""How far the position estimate moves while the foot stands still.

For each log, runs `bin/harness replay LOG --out CSV` (extra replay options
after `--`), takes the log's last stance (the replay CSV's `stance` column)
if it lasts at least MIN_STAND_S, and compares the position at its end with
the position SKIP_S after it began (the landing's settling excluded):
the displacement (height up positive), its rate, and the integral of the
estimated velocity over the same span. Where the displacement is much larger
than that integral, the updates themselves moved the position: each ZUPT
corrects it through the gain's position rows (its covariance with velocity,
attitude and biases), a correction of the path already walked.

Usage: /usr/bin/python3 scripts/stand_drift.py LOG... [-- REPLAY OPTIONS]
Prints a markdown table (mm, mm/s).
"""
import os
import sys

import numpy as np

from replay_runs import split_args, trajectories

SKIP_S = 1.0
MIN_STAND_S = 2.0


def stand(csv_path):
    d = np.genfromtxt(csv_path, delimiter=',', names=True)
    t = d['t']
    st = d['stance'] > 0
    if not st.any():
        return None
    i1 = int(np.nonzero(st)[0][-1])
    i0 = i1
    while i0 > 0 and st[i0 - 1]:
        i0 -= 1
    if t[i1] - t[i0] < MIN_STAND_S:
        return None
    j = int(np.searchsorted(t, t[i0] + SKIP_S))
    span = t[i1] - t[j]
    p = np.array([d['x'], d['y'], -d['z']]).T  # north, east, up
    v = np.array([d['vx'], d['vy'], -d['vz']]).T
    dp = p[i1] - p[j]
    dt = np.diff(t[j:i1 + 1])
    iv = np.sum(0.5 * (v[j + 1:i1 + 1] + v[j:i1]) * dt[:, None], axis=0)
    return span, dp, iv


def main(argv):
    logs, opts = split_args(argv, __doc__)
    print('| log | last stance from %.0f s in (s) | north / east / up (mm) | rate (mm/s) | integral of the velocity (mm) |'
          % SKIP_S)
    print('| --- | ---: | ---: | ---: | ---: |')
    for log, out in trajectories(logs, opts):
        res = stand(out)
        if res is None:
            print('| %s | (no stance of %.0f s at the end) | | | |' % (os.path.basename(log), MIN_STAND_S))
            continue
        span, dp, iv = res
        print('| %s | %.1f | %+.1f / %+.1f / %+.1f | %.1f | %.1f |'
              % (os.path.basename(log), span, 1e3 * dp[0], 1e3 * dp[1], 1e3 * dp[2],
                 1e3 * np.linalg.norm(dp) / span, 1e3 * np.linalg.norm(iv)))

if __name__ == '__main__':
    main(sys.argv[1:])
