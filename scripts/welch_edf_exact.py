#!/usr/bin/env python3
"""Exact variance of a Welch band average on white noise against the
approximation of welch_band_edf (harness/hx_simgap_stat.c; docs/simgap.md).

For white Gaussian noise every periodogram bin is a linear function of the
samples, so the covariance of the band average over K segments and B bins is
exact: cov(|X|^2, |Y|^2) = |E[X Y*]|^2 + |E[X Y]|^2, with each segment's mean
removed (FNAV_DETREND_CONSTANT) and the Hamming window of the core. The
approximation multiplies the segments' overlap correlation (bins at equal
frequency) by the window's leakage between bins (one segment) and leaves out
the terms where neighbouring bins of overlapping segments correlate.

Prints, per band of test_psd_edf_monte_carlo's layout (tests/test_simgap.c:
8,192 samples, 512-point segments, half overlap, three bands per octave), the
approximate and exact degrees of freedom and the ratio of the variances of
ln PSD they imply (trigamma(nu/2)), and the mean ratio over the bands, to
compare with the Monte Carlo ratio that test prints.

  /usr/bin/python3 scripts/welch_edf_exact.py
"""
import math

import numpy as np
from scipy.special import polygamma

N_SAMPLES, NFFT, BANDS_PER_OCTAVE = 8192, 512, 3
HOP = NFFT // 2
K = (N_SAMPLES - NFFT) // HOP + 1
n = np.arange(NFFT)
w = 0.54 - 0.46 * np.cos(2.0 * np.pi * n / NFFT)


def approx_edf(B):
    """welch_band_edf, as in harness/hx_simgap_stat.c."""
    s2 = (w * w).sum()
    rho = (w[: NFFT - HOP] * w[HOP:]).sum() / s2
    nu_bin = 2.0 * K / (1.0 + 2.0 * rho * rho * (K - 1) / K)
    den = 1.0
    for l in range(1, min(B, 8)):
        c = (w * w * np.exp(2j * np.pi * l * n / NFFT)).sum()
        den += 2.0 * (1.0 - l / B) * abs(c) ** 2 / s2 ** 2
    return B * nu_bin / den


def exact_edf(b0, B):
    L = (K - 1) * HOP + NFFT
    A = np.zeros((K * B, L), complex)
    for j, b in enumerate(range(b0, b0 + B)):
        row = w * np.exp(-2j * np.pi * b * n / NFFT)
        row = row - row.mean()  # the segment's mean removed before the window: x - mean(x)
        for k in range(K):
            A[k * B + j, k * HOP : k * HOP + NFFT] = row
    C = A @ A.conj().T
    P = A @ A.T
    mean = np.real(np.diag(C)).mean()
    var = (np.abs(C) ** 2 + np.abs(P) ** 2).sum() / (K * B) ** 2
    return 2.0 * mean * mean / var


def bands():
    nb = NFFT // 2  # bins 1 .. nb - 1 (the Nyquist bin left out)
    k = 1
    while k < nb:
        band = math.floor(BANDS_PER_OCTAVE * math.log2(k) + 1e-9)
        k1 = k
        while k1 < nb and math.floor(BANDS_PER_OCTAVE * math.log2(k1) + 1e-9) == band:
            k1 += 1
        yield k, k1 - k
        k = k1


def main():
    ratios = []
    print("K = %d segments of %d; band: first bin, bins, nu approx, nu exact, var ratio" % (K, NFFT))
    for b0, B in bands():
        na, ne = approx_edf(B), exact_edf(b0, B)
        r = polygamma(1, ne / 2.0) / polygamma(1, na / 2.0)
        ratios.append(r)
        print("%4d %3d %8.1f %8.1f %6.3f" % (b0, B, na, ne, r))
    print("mean variance ratio exact / approx over %d bands: %.3f" % (len(ratios), float(np.mean(ratios))))


if __name__ == "__main__":
    main()
