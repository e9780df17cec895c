#!/usr/bin/python3
"""Detectable magnitudes of the Allan-visible effects of the simulator's
catalogue (docs/simulator.md), computed analytically with numpy.

Reference conditions: a static log of 1 hour at 200 Hz whose baseline is a
paper profile (white noise + AR(1) bias, Tables IV-VI, the rate-independent
units of include/footnav/fnav_profile.h). An effect adds AVAR_e(tau) to the
baseline's AVAR_b(tau) (independent processes add). It is *detectable* when,
at some octave tau = m / f_s with at least 10 averages of tau in the log
(the paper's "10 % of the total"), the excess exceeds z = 5 standard
deviations of the overlapping Allan variance estimate:

    AVAR_e(m) > z * sqrt(2 / edf(m)) * AVAR_b(m),

edf from NIST SP 1065 Table 5 for white FM (the baseline is white-dominated
at every tau of these profiles). The threshold magnitude is the smallest
over m. Effects whose Allan signature is absorbed by a refitted baseline
(plain quantisation, aliasing: white-like) or that do not show in a static
log (scale factor, misalignment, g-sensitivity, timing) are described in
docs/simulator.md in words.

Writes vectors/sim/detectable.csv; --check regenerates in memory and
compares (relative tolerance 1e-6).
"""
import csv
import math
import os
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
OUT = os.path.join(HERE, "detectable.csv")
FS = 200.0
T = 3600.0
Z = 5.0
D2R = math.pi / 180.0

# paper Tables IV-VI, x rows of accelerometer and gyroscope: noise
# (m/s^2/sqrt(Hz), deg/s/sqrt(Hz)), tau in samples at 200 Hz, sigma_bias
PROFILES = {
    "navchip": {"acc": (7.4e-4, 2000.0, 1.3e-5), "gyro": (3.3e-3, 1000.0, 8.5e-5)},
    "mtx": {"acc": (8.9e-4, 2600.0, 7.9e-6), "gyro": (2.6e-2, 42000.0, 1.8e-5)},
    "shimmer": {"acc": (6.0e-3, 14600.0, 8.7e-6), "gyro": (1.9e-2, 4200.0, 1.0e-4)},
}


def avar_ar1(m, var, c):
    """Allan variance of a discrete AR(1) with stationary variance var and
    coefficient c at averaging factor m (exact, from the autocovariance)."""
    k = np.arange(1, 2 * m, dtype=float)
    ck = c ** k
    vs = m + 2.0 * np.sum((m - k[k < m]) * ck[k < m])
    cv = np.sum((m - np.abs(k - m)) * ck)
    return var * (vs - cv) / (m * m)


def edf_white(N, m):
    return (3.0 * (N - 1.0) / (2.0 * m) - 2.0 * (N - 2.0) / N) * 4.0 * m * m / (4.0 * m * m + 5.0)


def octaves(n):
    m = 1
    while n / m >= 10.0 * 2.0:  # 2m <= n/10: tau at most 10 % of the log
        yield m
        m *= 2


def baseline(row):
    noise, tau_samples, sigma = row
    dt = 1.0 / FS
    tau_s = tau_samples / 200.0
    c = math.exp(-dt / tau_s)
    return lambda m: noise * noise * FS / m + avar_ar1(m, sigma * sigma, c)


def flicker_shape(m, lo=0.5, hi=5000.0, poles=12):
    """AVAR per B^2 of the 12-pole 1/f model with its default band."""
    lnr = math.log(hi / lo) / (poles - 1)
    v = lnr / math.pi
    s = 0.0
    for i in range(poles):
        tau = lo * math.exp(lnr * i)
        s += avar_ar1(m, v, math.exp(-1.0 / (FS * tau)))
    return s


def thermal_shape(ms, rise=10.0, tau=600.0):
    """AVAR per coef^2 of coef * rise * (1 - exp(-t / tau)) over the log."""
    n = int(T * FS)
    t = np.arange(1, n + 1) / FS
    x = rise * (1.0 - np.exp(-t / tau))
    X = np.concatenate(([0.0], np.cumsum(x)))
    out = {}
    for m in ms:
        d = X[2 * m:] - 2.0 * X[m:-m] + X[:-2 * m]
        out[m] = np.mean(d * d) / (2.0 * m * m)
    return out


def vib_shape(m, f=37.0):
    w = 2.0 * math.pi * f / FS
    return math.sin(0.5 * w * m) ** 4 / (m * m * math.sin(0.5 * w) ** 2)


def threshold(avar_b, shape, ms, N):
    best = math.inf
    best_tau = None
    for m in ms:
        s = shape(m)
        if s <= 0.0:
            continue
        need = Z * math.sqrt(2.0 / edf_white(N, m)) * avar_b(m) / s
        if need < best:
            best = need
            best_tau = m / FS
    return math.sqrt(best), best_tau


def compute():
    n = int(T * FS)
    N = n + 1.0
    ms = list(octaves(n))
    therm = thermal_shape(ms)
    rows = []
    for prof, sensors in PROFILES.items():
        for kind, row in sensors.items():
            unit = "m/s^2" if kind == "acc" else "rad/s"
            scale = 1.0 if kind == "acc" else D2R
            srow = (row[0] * scale, row[1], row[2] * scale)
            avb = baseline(srow)
            lam = 1.0 / 600.0  # jumps: one step per 10 min on average
            effects = [
                ("flicker", "b", unit, lambda m: flicker_shape(m)),
                ("rrw", "k", unit + "/sqrt(s)", lambda m: (2.0 * m * m + 1.0) / (6.0 * m) / FS),
                ("ramp", "rate", unit + "/s", lambda m: (m / FS) ** 2 / 2.0),
                ("thermal", "coef", unit + "/degC", lambda m: therm[m]),
                ("quant_shaped", "lsb", unit, lambda m: 1.0 / (4.0 * m * m)),
                ("vibration_37hz", "amp", unit, lambda m: vib_shape(m)),
                ("jumps_1per600s", "amp", unit,
                 lambda m: (1.0 - math.exp(-lam / FS)) * (2.0 * m * m + 1.0) / (6.0 * m)),
            ]
            for name, param, u, shape in effects:
                thr, tau = threshold(avb, shape, ms, N)
                rows.append([prof, kind, name, param, u, "%.6g" % thr, "%.6g" % tau])
    return rows


HEADER = ["profile", "sensor", "effect", "param", "unit", "threshold", "best_tau_s"]


def main():
    rows = compute()
    if len(sys.argv) > 1 and sys.argv[1] == "--check":
        with open(OUT, newline="") as f:
            old = list(csv.reader(f))
        if old[0] != HEADER or len(old) - 1 != len(rows):
            print("detectable.csv: header or row count differs")
            return 1
        for a, b in zip(old[1:], rows):
            if a[:5] != b[:5]:
                print("detectable.csv: row differs:", a, b)
                return 1
            for i in (5, 6):
                x, y = float(a[i]), float(b[i])
                if abs(x - y) > 1e-6 * abs(y):
                    print("detectable.csv: value differs:", a, b)
                    return 1
        return 0
    with open(OUT, "w", newline="") as f:
        w = csv.writer(f, lineterminator="\n")
        w.writerow(HEADER)
        w.writerows(rows)
    return 0


if __name__ == "__main__":
    sys.exit(main())
