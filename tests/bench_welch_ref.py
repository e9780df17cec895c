#!/usr/bin/python3
"""Reference for tests/bench_welch.c: scipy.signal.welch with the paper's
settings (Hamming 64, 50 % overlap, constant detrend, one-sided density) on
raw little-endian float64 samples. Prints 'seconds <best of R runs>' and a
few bins for a cross-check."""
import sys
import time
import numpy as np
import scipy.signal as sig


def main():
    y = np.fromfile(sys.argv[1], dtype="<f8")
    fs = float(sys.argv[2])
    nperseg = int(sys.argv[3])
    runs = int(sys.argv[4]) if len(sys.argv) > 4 else 5
    best = float("inf")
    p = None
    for _ in range(runs):
        t = time.perf_counter()
        _, p = sig.welch(y, fs=fs, window="hamming", nperseg=nperseg, noverlap=nperseg // 2, detrend="constant",
                         scaling="density")
        best = min(best, time.perf_counter() - t)
    print("seconds %.6f" % best)
    for k in (1, len(p) // 2, len(p) - 1):
        print("bin %d %.12e" % (k, p[k]))


if __name__ == "__main__":
    main()
