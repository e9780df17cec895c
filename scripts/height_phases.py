#!/usr/bin/env python3
"""Where a walk's height changes: the replay's height steps summed by phase.

For each log, runs `bin/harness replay LOG --out CSV` (extra replay options
after `--`), then sums the height change of consecutive frames (up positive)
by the detector's decision at the later frame (the replay CSV's `stance`): in
swing, or in stance by the time since that stance began (0-30 ms, 30-150
ms, later).
The phases mix error with real motion (the IMU of a rolling foot rises in
late stance and comes down in the swing), so a phase's sum is where the
filter put the height, not how much of it is error; the total is the
replay's end height against its start.

Usage: /usr/bin/python3 scripts/height_phases.py LOG... [-- REPLAY OPTIONS]
Prints a markdown table (metres; per stance phase in brackets: cm).
"""
import os
import sys

import numpy as np

from replay_runs import split_args, trajectories

EDGES_S = (0.03, 0.15)


def phases(csv_path):
    d = np.genfromtxt(csv_path, delimiter=',', names=True)
    t = d['t']
    h = -d['z']  # n frame, z down
    st = d['stance'] > 0
    since = np.full(len(t), -1.0)
    start = None
    for k in range(len(t)):
        if st[k]:
            if start is None:
                start = t[k]
            since[k] = t[k] - start
        else:
            start = None
    runs = int(np.sum(st[1:] & ~st[:-1]) + (1 if st[0] else 0))
    dh = np.diff(h)
    zz, s = st[1:], since[1:]
    parts = (
        dh[~zz].sum(),
        dh[zz & (s <= EDGES_S[0])].sum(),
        dh[zz & (s > EDGES_S[0]) & (s <= EDGES_S[1])].sum(),
        dh[zz & (s > EDGES_S[1])].sum(),
    )
    return h[-1] - h[0], parts, runs


def main(argv):
    logs, opts = split_args(argv, __doc__)
    print('| log | stance phases | total | swing | stance 0-30 ms | 30-150 ms | after 150 ms |')
    print('| --- | ---: | ---: | ---: | ---: | ---: | ---: |')
    for log, out in trajectories(logs, opts):
        total, parts, runs = phases(out)
        cells = ['%+.3f (%+.1f)' % (p, 100.0 * p / max(runs, 1)) for p in parts]
        print('| %s | %d | %+.3f | %s |' % (os.path.basename(log), runs, total, ' | '.join(cells)))

if __name__ == '__main__':
    main(sys.argv[1:])
