#!/usr/bin/env python3
"""How far the integration rule moves the 95 % bandwidth (docs/psd.md,
"The lowest usable sampling frequency").

Reads the PSD that `bin/harness psd LOG --out PSD.csv` writes and finds, per
axis, the frequency below which 95 % of the power lies three ways:
  footnav   bin k holds P_k df over [(k - 1/2) df, (k + 1/2) df] (clipped to
            [0, fs/2]), linear inside the bin (fnav_welch_bandwidth);
  cumsum    the running sum of P_k df read at the bin centres, linear between;
  trapezoid the trapezoid rule over the bin centres (scipy's
            cumulative_trapezoid), linear between.
Prints the three bandwidths and the largest difference in bins.

Usage: /usr/bin/python3 scripts/psd_integration.py PSD.csv [--threshold 0.95]
"""
import argparse

import numpy as np


def crossing(x, c, level):
    """First x where the non-decreasing c reaches level, linear between points."""
    k = int(np.searchsorted(c, level))
    if k == 0:
        return x[0]
    return x[k - 1] + (level - c[k - 1]) / (c[k] - c[k - 1]) * (x[k] - x[k - 1])


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument('csv')
    ap.add_argument('--threshold', type=float, default=0.95)
    a = ap.parse_args()
    d = np.genfromtxt(a.csv, delimiter=',', names=True, skip_header=1)
    f = d['freq_hz']
    df = f[1] - f[0]
    edges = np.clip(np.r_[f - 0.5 * df, f[-1] + 0.5 * df], 0.0, f[-1])
    print('| axis | footnav (Hz) | cumsum (Hz) | trapezoid (Hz) | largest difference (bins) |')
    print('| --- | ---: | ---: | ---: | ---: |')
    for ax in ('ax', 'ay', 'az', 'gx', 'gy', 'gz'):
        p = d['psd_' + ax]
        power = p * df  # P_k df in the bin's span (fnav_welch_bandwidth)
        c_edge = np.r_[0.0, np.cumsum(power)] / power.sum()
        b_foot = crossing(edges, c_edge, a.threshold)
        c_sum = np.cumsum(p * df) / np.sum(p * df)
        b_sum = crossing(f, c_sum, a.threshold)
        c_tr = np.r_[0.0, np.cumsum(0.5 * (p[1:] + p[:-1]) * df)]
        b_tr = crossing(f, c_tr / c_tr[-1], a.threshold)
        spread = (max(b_foot, b_sum, b_tr) - min(b_foot, b_sum, b_tr)) / df
        print('| %s | %.1f | %.1f | %.1f | %.1f |' % (ax, b_foot, b_sum, b_tr, spread))


if __name__ == '__main__':
    main()
