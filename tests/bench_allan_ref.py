#!/usr/bin/python3
"""Reference for tests/bench_allan.c: a vectorised numpy octave-tau
overlapping Allan deviation (NIST SP 1065 eq. 11 on the phase), the way one
writes it for speed: one cumsum, then per octave m one vectorised second
difference and a dot product. Reads raw little-endian float64 samples,
prints 'seconds <best of R runs>' and the deviations for a cross-check."""
import sys
import time
import numpy as np


def oadev_octave(y):
    x = np.empty(len(y) + 1)
    x[0] = 0.0
    np.cumsum(y, out=x[1:])
    n = len(x)
    out = []
    m = 1
    while 2 * m < n:
        d = x[2 * m:] - 2.0 * x[m:-m] + x[:-2 * m]
        out.append((m, np.sqrt(np.dot(d, d) / (2.0 * m * m * len(d))), len(d)))
        m *= 2
    return out


def main():
    y = np.fromfile(sys.argv[1], dtype="<f8")
    runs = int(sys.argv[2]) if len(sys.argv) > 2 else 5
    best = float("inf")
    res = None
    for _ in range(runs):
        t = time.perf_counter()
        res = oadev_octave(y)
        best = min(best, time.perf_counter() - t)
    print("seconds %.6f" % best)
    for m, dev, terms in res:
        print("tau %d %.12e %d" % (m, dev, terms))


if __name__ == "__main__":
    main()
