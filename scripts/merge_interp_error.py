#!/usr/bin/env python3
"""How far linear interpolation (what `harness merge` does for the slower of
two files) is from the samples of a foot: each channel of a walk kept at
every second (and fourth) sample and interpolated at the others, the error
RMS and largest, beside the channel's RMS and its noise at rest (the first
1.5 s, from successive differences). The figures of docs/log-format.md,
"Accelerometer and gyroscope in two files":

  bin/harness convert vectors/walk.bin walk.csv
  /usr/bin/python3 scripts/merge_interp_error.py walk.csv

Repeated stamps are dropped first, keeping the first row of each, as merge
does."""
import sys

import numpy as np

d = np.genfromtxt(sys.argv[1], delimiter=',', names=True)
keep = np.concatenate([[True], np.diff(d['t']) > 0])
d = d[keep]
t = d['t']
rate = 1.0 / np.median(np.diff(t))
still = t - t[0] < 1.5
for k in ('gx', 'gy', 'gz', 'ax', 'ay', 'az'):
    x = d[k]
    noise = np.std(np.diff(x[still])) / np.sqrt(2.0)
    for step in (2, 4):
        kept = np.arange(0, len(t), step)
        rest = np.setdiff1d(np.arange(len(t)), kept)
        rest = rest[rest < kept[-1]]
        e = np.interp(t[rest], t[kept], x[kept]) - x[rest]
        print('%s at %.0f Hz: error RMS %.3g, largest %.3g; channel RMS %.3g, noise at rest %.3g'
              % (k, rate / step, np.sqrt(np.mean(e ** 2)), np.abs(e).max(), np.std(x), noise))
