#!/usr/bin/env python3
"""Independent reference for the total forms of the modified Allan and the
Hadamard deviations (harness/hx_devs.c: MTOTDEV, TTOTDEV, HTOTDEV;
docs/allan.md, "Total forms").

The definitions, written out as NIST SP 1065 (Riley 2008, eqs. 27-29) words
them, with whole arrays (the C code works on prefix sums instead):
- each start takes 3m values (phase for MTOT, fractional frequency for HTOT);
- removes the line through the means of the first and last halves
  (floor(3m/2) values each, the middle one left out when 3m is odd);
- extends the result to 9m values by uninverted even reflection
  (reversed, as is, reversed);
- averages the squares of the 6m second differences of m-sample means of the
  extended sequence;
- MTOTVAR is the mean over the n - 3m + 1 starts divided by 2 m^2 tau0^2;
  TTOT = tau MTOT / sqrt(3); HTOTVAR is the mean over the n - 3m starts of the
  frequency windows divided by 6, and the overlapping Hadamard variance at
  m = 1. No bias correction.

Default: the NBS14 1000-point set at m = 1..333 (golden values for
tests/test_allan.c, 17 digits), and a check against the Stable32 values in
nbs14_1000pt_expected.csv / nbs14_10pt_expected.csv.

--mc R: R simulated records each of white PM, white FM and random-walk FM
(n = 1001 phase values) at m = 4, 16, 64. Prints the simulated EDF,
2 mean^2 / var, of MTOTVAR against SP 1065 Table 8 (b n / m - c), and of
HTOTVAR against the same records' overlapping Hadamard variance (whose
Greenhall EDF the harness gives HTOTDEV's interval: is it the smaller?).

Usage: /usr/bin/python3 scripts/totdev_ref.py [DATA_DIR] [--mc R]
       (DATA_DIR defaults to ../shared/data)
"""
import argparse
import os

import numpy as np

from pvar_edf import NBS14_10, nbs14_1000_phase, phase, simulate  # simulate: white PM, white FM, random-walk FM records


def window_terms(v, m):
    """Mean over the 6m starts of the squared second difference of m-sample
    means of each row of v (rows: windows of 3m values), detrended and reflected."""
    L = 3 * m
    h = L // 2
    slope = (v[:, L - h:].mean(axis=1) - v[:, :h].mean(axis=1)) / (L - h)
    x0 = v - slope[:, None] * np.arange(L)[None, :]
    xs = np.concatenate((x0[:, ::-1], x0, x0[:, ::-1]), axis=1)
    c = np.concatenate((np.zeros((xs.shape[0], 1)), np.cumsum(xs, axis=1)), axis=1)
    means = (c[:, m:] - c[:, :-m]) / m
    d = means[:, :6 * m] - 2.0 * means[:, m:7 * m] + means[:, 2 * m:8 * m]
    return np.mean(d * d, axis=1)


def windows(v, L):
    return np.lib.stride_tricks.sliding_window_view(v, L)


def mtotvar(x, m):
    if 3 * m > len(x):
        return float("nan")
    return float(np.mean(window_terms(windows(x, 3 * m), m)) / (2.0 * m * m))


def ohvar(x, m):
    d = x[3 * m:] - 3.0 * x[2 * m:-m] + 3.0 * x[m:-2 * m] - x[:-3 * m]
    return float(np.mean(d * d) / (6.0 * m * m))


def htotvar(x, m):
    if 3 * m + 1 > len(x):
        return float("nan")
    if m == 1:
        return ohvar(x, 1)
    return float(np.mean(window_terms(windows(np.diff(x), 3 * m), m)) / 6.0)


TABLE8 = {2: (1.90, 2.10), 1: (1.20, 1.40), 0: (1.10, 1.20), -1: (0.85, 0.50), -2: (0.75, 0.31)}


def golden(data_dir):
    x = nbs14_1000_phase(data_dir)
    print("# NBS14 1000-point set: m, MTOTDEV, HTOTDEV (no bias correction)")
    for m in (1, 2, 3, 5, 8, 10, 16, 33, 64, 100, 128, 256, 333):
        print("%d,%.17g,%.17g" % (m, np.sqrt(mtotvar(x, m)), np.sqrt(htotvar(x, m))))
    print("# against Stable32 (5 digits; HTOTDEV published with the white-FM bias correction 0.995 applied):")
    want = {"MTOTDEV": (2.0664e-01, 5.5529e-02, 1.9547e-02), "TTOTDEV": (1.1930e-01, 3.2060e-01, 1.1285e+00),
            "HTOTDEV": (2.943883e-01, 9.614787e-02, 3.058103e-02)}
    for name, vals in want.items():
        for m, w in zip((1, 10, 100), vals):
            if name == "HTOTDEV":
                got = np.sqrt(htotvar(x, m) / (0.995 if m > 1 else 1.0))
            else:
                got = np.sqrt(mtotvar(x, m)) * (m / np.sqrt(3.0) if name == "TTOTDEV" else 1.0)
            print("%s m=%d: %.6g against %.6g (%+.1e)" % (name, m, got, w, got / w - 1.0))
    x10 = phase(NBS14_10)
    for m, wm, wt, wh in ((1, 64.509, 37.244, 70.80607), (2, 64.794, 74.818, 91.16396)):
        print("NBS14 10-point m=%d: MTOTDEV %.6g (%.6g), TTOTDEV %.6g (%.6g), HTOTDEV corrected %.7g (%.7g)"
              % (m, np.sqrt(mtotvar(x10, m)), wm, np.sqrt(mtotvar(x10, m)) * m / np.sqrt(3.0), wt,
                 np.sqrt(htotvar(x10, m) / (0.995 if m > 1 else 1.0)), wh))


def monte_carlo(reps):
    rng = np.random.default_rng(20261126)
    n = 1001
    alpha = {"white PM": 2, "white FM": 0, "random-walk FM": -2}
    print("noise, m: MTOT EDF simulated / SP 1065 Table 8; HTOT EDF simulated / OHVAR EDF simulated "
          "(%d records of %d phase values each)" % (reps, n))
    for kind, a in alpha.items():
        for m in (4, 16, 64):
            mt = np.empty(reps)
            ht = np.empty(reps)
            oh = np.empty(reps)
            for r in range(reps):
                x = simulate(a, n, rng)
                mt[r] = mtotvar(x, m)
                ht[r] = htotvar(x, m)
                oh[r] = ohvar(x, m)
            edf = [2.0 * np.mean(v) ** 2 / np.var(v, ddof=1) for v in (mt, ht, oh)]
            b, c = TABLE8[a]
            print("%-15s m=%3d: MTOT %7.1f / %7.1f; HTOT %7.1f / OHVAR %7.1f" % (kind, m, edf[0], b * n / m - c,
                                                                                 edf[1], edf[2]))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("data", nargs="?", default=os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..",
                                                            "shared", "data"))
    ap.add_argument("--mc", type=int, default=0, help="simulated records per case for the EDF check")
    a = ap.parse_args()
    if a.mc > 0:
        monte_carlo(a.mc)
    else:
        golden(a.data)


if __name__ == "__main__":
    main()
