#!/usr/bin/python3
"""The time columns of the OpenShoe GX2 logs (docs/log-format.md, "GX2 time").

Reads every *_data_inert.txt of the openshoe_gx2 folder as written by the
logger (not through the harness's importer, so that the figures check it)
and prints per file: the range of the sensor timer's tick differences
(`Counter`, 19.6608 MHz) where it advances, in ticks and in ms; how often
it restarts (a difference that is not positive); the standard deviation of
the filtered host stamps' intervals (`Filtered ts[s]`, index 10) and the
standard deviation, minimum and maximum of the unfiltered ones (index 11);
and the median of the logger's own rate estimate (`Freq. [Hz]`).

Usage: /usr/bin/python3 scripts/gx2_timing.py [DIR]
       (DIR: the openshoe_gx2 folder; default ../shared/data/openshoe_gx2)
"""
import glob
import os
import sys

import numpy as np

TICK_HZ = 19.6608e6


def columns(path):
    rows = []
    with open(path) as f:
        for line in f:
            p = line.split()
            if len(p) < 14 or not p[0].startswith('0x'):
                continue  # the preamble, the header, a line cut off mid-write
            try:
                rows.append([float(p[7]), float(p[10]), float(p[11]), float(p[13])])
            except ValueError:
                continue
    return np.array(rows)


def main():
    d = sys.argv[1] if len(sys.argv) > 1 else '../shared/data/openshoe_gx2'
    files = sorted(glob.glob(os.path.join(d, '*_data_inert.txt')))
    if not files:
        sys.exit('gx2_timing.py: no *_data_inert.txt in ' + d)
    print('file  ticks(min-max)  ms(min-max)  restarts  filtered_sd_ms  '
          'unfiltered_sd_ms  unfiltered_min_ms  unfiltered_max_ms  freq_median_hz')
    for f in files:
        a = columns(f)
        dc = np.diff(a[:, 0])
        adv = dc[dc > 0]
        fi = np.diff(a[:, 1]) * 1e3
        un = np.diff(a[:, 2]) * 1e3
        print('%s  %d-%d  %.4f-%.4f  %d  %.2f  %.2f  %.2f  %.1f  %.2f' % (
            os.path.basename(f), adv.min(), adv.max(),
            adv.min() / TICK_HZ * 1e3, adv.max() / TICK_HZ * 1e3,
            int((dc <= 0).sum()), fi.std(), un.std(), un.min(), un.max(),
            np.median(a[:, 3])))


if __name__ == '__main__':
    main()
