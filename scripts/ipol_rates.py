#!/usr/bin/env python3
"""|w| of an ipol_gait_xsens foot over a range of packets, with the experts'
swings of both feet that touch it (docs/navigation.md, "Strides and gait
events": the expert swings with both feet in the air).

Usage: /usr/bin/python3 scripts/ipol_rates.py TRIAL FOOT FROM TO [STEP]
  e.g. /usr/bin/python3 scripts/ipol_rates.py ../shared/data/ipol_gait_xsens/2-3 rf 3040 3340 8
TRIAL is the path without _lf.txt / _rf.txt / .json; FOOT lf or rf; FROM, TO
packets (the PacketCounter, as the experts count).
"""
import json
import sys

import numpy as np


def main():
    if len(sys.argv) not in (5, 6):
        sys.exit(__doc__)
    trial, foot, lo, hi = sys.argv[1], sys.argv[2], int(sys.argv[3]), int(sys.argv[4])
    step = int(sys.argv[5]) if len(sys.argv) == 6 else 4
    d = np.genfromtxt('%s_%s.txt' % (trial, foot), skip_header=2, usecols=range(7))
    pc, w = d[:, 0], np.linalg.norm(d[:, 4:7], axis=1)
    ev = json.load(open(trial + '.json'))
    for key in ('LeftFootEvents', 'RightFootEvents'):
        sw = [s for s in ev[key] if s[1] >= lo and s[0] <= hi]
        print('%s swings in %d-%d: %s' % (key, lo, hi, sw))
    for p in range(lo, hi + 1, step):
        k = int(np.searchsorted(pc, p))
        if k < len(pc):
            print('%6d  |w| %5.2f rad/s  %s' % (int(pc[k]), w[k], '#' * int(min(60, 10 * w[k]))))


if __name__ == '__main__':
    main()
