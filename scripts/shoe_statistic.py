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
from numpy.lib.stride_tricks import sliding_window_view

G = 9.80665


def shoe_terms(f, w, W, g=G, sigma_a=0.01, sigma_g=0.1 * np.pi / 180.0):
    """The SHOE statistic's two terms over each window of W samples, the
    window starting at sample k = 0 .. n - W: 1/W sum |f_j - g u|^2 /
    sigma_a^2 and 1/W sum |w_j|^2 / sigma_g^2 (T is their sum); f and w are
    n x 3 arrays. Also scripts/probe_slow.py's."""
    fw = sliding_window_view(f, (W, 3)).reshape(-1, W, 3)
    ww = sliding_window_view(w, (W, 3)).reshape(-1, W, 3)
    u = fw.mean(1)
    u /= np.linalg.norm(u, axis=1)[:, None]
    return (np.mean(np.sum((fw - g * u[:, None, :]) ** 2, 2), 1) / sigma_a ** 2,
            np.mean(np.sum(ww ** 2, 2), 1) / sigma_g ** 2)


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
    ta, tg = shoe_terms(f, w, a.window)
    lt = np.log10((ta + tg)[:len(f) - a.window])  # every window but the last, as before
    rest = lt < np.log10(a.gamma)
    print("max |w| %.2f rad/s, max ||f| - g| %.2f m/s^2" %
          (np.linalg.norm(w, axis=1).max(), np.abs(np.linalg.norm(f, axis=1) - G).max()))
    print("rest   (T < %g): %.0f %% of frames, log10 T median %.1f, 1st-99th percentile %.1f-%.1f" %
          (a.gamma, 100.0 * rest.mean(), np.median(lt[rest]), *np.percentile(lt[rest], [1, 99])))
    print("moving (T >= %g): log10 T median %.1f, 5th-99th percentile %.1f-%.1f" %
          (a.gamma, np.median(lt[~rest]), *np.percentile(lt[~rest], [5, 99])))


if __name__ == "__main__":
    main()
