#!/usr/bin/env python3
"""Give a log the x-io NGIMU's lost-sample pattern (docs/xio-climb.md,
"Round 6"): in the xio_ngimu_gait logs a lost sample is almost always
followed by the next sample written twice (same time stamp, same values).

Reads a CSV `t,ax,ay,az,gx,gy,gz` (e.g. from `bin/harness convert`), keeps
every K-th sample (--keep, default 2: the 820 Hz OpenShoe walk at 410 Hz,
the NGIMU's rate; point sampling, no filter), then with probability P per
sample (--p) drops the next sample and writes the one after it twice.
Writes the same CSV format.

Usage:
  bin/harness convert ../shared/data/openshoe_c_820hz/OpenShoeDataSet.txt os.csv
  /usr/bin/python3 scripts/drop_pattern.py os.csv out.csv [--keep 2] [--p 0.012] [--seed 1]
  bin/harness replay out.csv
(--p 0 gives the decimated log alone, the comparison's baseline.)
"""
import argparse

import numpy as np


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument('inp')
    ap.add_argument('out')
    ap.add_argument('--keep', type=int, default=2)
    ap.add_argument('--p', type=float, default=0.012)
    ap.add_argument('--seed', type=int, default=1)
    a = ap.parse_args()
    d = np.genfromtxt(a.inp, delimiter=',', skip_header=1)[::a.keep]
    rng = np.random.default_rng(a.seed)
    rows, i, n = [], 0, len(d)
    while i < n:
        if i + 2 < n and rng.random() < a.p:
            rows += [d[i], d[i + 2], d[i + 2]]  # i + 1 lost, i + 2 twice
            i += 3
        else:
            rows.append(d[i])
            i += 1
    np.savetxt(a.out, np.array(rows), delimiter=',', header='t,ax,ay,az,gx,gy,gz', comments='', fmt='%.9g')


if __name__ == '__main__':
    main()
