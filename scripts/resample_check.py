#!/usr/bin/env python3
"""The --rate resampler (harness/hx_nav.c, hx_nav_resample) against an
independent scipy chain: the log upsampled 8 x by resample_poly, the same
low-pass spec (Blackman-windowed, cut-off 0.45 x the new rate, about 41 x the
rate ratio long) designed with firwin on the fine grid, read at the output
instants through the input's own stamps. Prints, per channel, the RMS of the
difference over the middle 80 % as a fraction of the channel's spread, and
the worst difference over the first and last 20 outputs (edges).

usage: /usr/bin/python3 scripts/resample_check.py [--max RMS EDGE] LOG RATE [LOG RATE ...]
(runs bin/harness convert LOG raw.csv and convert LOG out.csv --rate RATE)
--max: exit 1 when a channel's RMS or edge fraction exceeds RMS or EDGE
(docs/harness.md states 0.0008 and 0.003; tests/cli/test_foundation.sh)
"""
import os
import subprocess
import sys
import tempfile

import numpy as np
import scipy.signal as ss

HARNESS = os.environ.get("HARNESS", "bin/harness")
U = 8


def load(path):
    d = np.loadtxt(path, delimiter=",", skiprows=1, usecols=range(7))
    return np.round(d[:, 0] * 1e9).astype(np.int64), d[:, 1:]


def check(log, rate, tmp):
    raw, out = os.path.join(tmp, "raw.csv"), os.path.join(tmp, "out.csv")
    for args in ([log, raw], [log, out, "--rate", str(rate)]):
        subprocess.run([HARNESS, "convert"] + args, check=True, stderr=subprocess.DEVNULL)
    t, x = load(raw)
    to, y = load(out)
    keep = np.r_[True, np.diff(t) > 0]  # exact duplicates dropped, as the resampler does
    t, x = t[keep], x[keep]
    t, to = t - t[0], to - to[0]
    fs = 1e9 / np.median(np.diff(t))
    xu = ss.resample_poly(x, U, 1, axis=0, padtype="line")
    n_taps = int(2 * np.ceil(20 * fs / rate) * U) + 1
    h = ss.firwin(n_taps, 0.45 * rate, window="blackman", fs=fs * U)
    ones = ss.fftconvolve(np.ones(len(xu)), h, "same")
    xf = np.column_stack([ss.fftconvolve(xu[:, c], h, "same") / ones for c in range(6)])
    tu = np.interp(np.arange(len(xu)) / U, np.arange(len(t)), t.astype(float))
    ref = np.column_stack([np.interp(to, tu, xf[:, c]) for c in range(6)])
    e, sc, n = y - ref, np.std(y, 0), len(to)
    mid = slice(n // 10, n - n // 10)
    rms = np.sqrt(np.mean(e[mid] ** 2, 0)) / sc
    edge = np.maximum(np.max(np.abs(e[:20]), 0), np.max(np.abs(e[-20:]), 0)) / sc
    print("%s -> %g Hz: RMS difference / spread (ax..gz) %s; edges (worst of first/last 20) %s"
          % (os.path.basename(log), rate, np.array2string(rms, precision=4), np.array2string(edge, precision=3)))
    return np.max(rms), np.max(edge)


def main():
    a = sys.argv[1:]
    lim = None
    if a[:1] == ["--max"] and len(a) >= 3:
        lim, a = (float(a[1]), float(a[2])), a[3:]
    if len(a) < 2 or len(a) % 2:
        sys.exit(__doc__)
    bad = 0
    with tempfile.TemporaryDirectory() as tmp:
        for i in range(0, len(a), 2):
            rms, edge = check(a[i], float(a[i + 1]), tmp)
            if lim is not None and not (rms <= lim[0] and edge <= lim[1]):
                print("over --max %g %g" % lim)
                bad = 1
    sys.exit(bad)


if __name__ == "__main__":
    main()
