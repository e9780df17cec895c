#!/usr/bin/env python3
"""The SHOE / GLRT statistic of a log, summarised: how far its motion lies
from the foot-tuned threshold (docs/navigation.md, "Gentle motion").

T_k = 1/W sum_j (|f_j - g u|^2 / sigma_a^2 + |w_j|^2 / sigma_g^2), u the
unit vector of the window's mean specific force (Skog et al. 2010, eq. 13),
with footnav's default weights (sigma_a 0.01 m/s^2, sigma_g 0.1 deg/s) and a
window of W samples. An independent numpy computation, not the C detector.

Input: a CSV with a header whose columns 2-4 are f_x..f_z (m/s^2) and 5-7
w_x..w_z (rad/s), as openshoe_square2/square2_u.csv.

Usage: /usr/bin/python3 scripts/shoe_statistic.py LOG.csv [--window 3] [--gamma 100]
Prints max |w|, max ||f| - g|, and log10 T at rest (T < gamma) and while
moving (T >= gamma): median and percentiles, and the share of frames at rest.
"""
import argparse
import sys

import numpy as np

G = 9.80665


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("log")
    ap.add_argument("--window", type=int, default=3, help="window W, samples (25 ms at 100 Hz: 3)")
    ap.add_argument("--gamma", type=float, default=100.0, help="rest / motion split of T for the summary")
    a = ap.parse_args()
    try:
        d = np.loadtxt(a.log, delimiter=",", skiprows=1)
    except (OSError, ValueError) as e:
        sys.exit("shoe_statistic.py: %s: %s" % (a.log, e))
    if d.ndim != 2 or d.shape[1] < 7 or d.shape[0] <= a.window:
        sys.exit("shoe_statistic.py: %s: expected at least 7 columns and more rows than the window" % a.log)
    f, w = d[:, 1:4], d[:, 4:7]
    sa, sg, W = 0.01, 0.1 * np.pi / 180.0, a.window
    n = len(f) - W
    T = np.empty(n)
    for k in range(n):
        fw, ww = f[k:k + W], w[k:k + W]
        u = fw.mean(0)
        u /= np.linalg.norm(u)
        T[k] = np.mean(np.sum((fw - G * u) ** 2, 1) / sa ** 2 + np.sum(ww ** 2, 1) / sg ** 2)
    lt = np.log10(T)
    rest = lt < np.log10(a.gamma)
    print("max |w| %.2f rad/s, max ||f| - g| %.2f m/s^2" %
          (np.linalg.norm(w, axis=1).max(), np.abs(np.linalg.norm(f, axis=1) - G).max()))
    print("rest   (T < %g): %.0f %% of frames, log10 T median %.1f, 1st-99th percentile %.1f-%.1f" %
          (a.gamma, 100.0 * rest.mean(), np.median(lt[rest]), *np.percentile(lt[rest], [1, 99])))
    print("moving (T >= %g): log10 T median %.1f, 5th-99th percentile %.1f-%.1f" %
          (a.gamma, np.median(lt[~rest]), *np.percentile(lt[~rest], [5, 99])))


if __name__ == "__main__":
    main()
