#!/usr/bin/python3
"""How well can any estimator get a rate random walk's K from the fit segment
of a validation case? (docs/simgap.md, "Validation".)

The validation's static case: one hour at 200 Hz, fit on the first and last
18 minutes (1080 s each, a 1440 s held-out gap between them), white noise
plus a rate random walk at a multiple of the detectable threshold
(vectors/sim/detectable.csv; here the Shimmer accelerometer: N 6.0e-3
m/s^2/sqrt(Hz), threshold K 7.15e-5 m/s^2/sqrt(s)). The ideal estimator
knows the model exactly (white + walk, nothing else, N known) and
maximises the exact likelihood of the 1 s block means of both fit blocks:
the block means of white + walk are exactly a local-level model with walk
variance K^2 D per block and observation variance N^2 / D - K^2 D / 6
(the MA(1) of their differences matches), carried across the gap.
Prints, per multiple of the threshold, the fraction of simulated logs whose
K estimate is within 25 % of the truth, and the median relative error.

Run: /usr/bin/python3 scripts/rrw_k_limit.py   (about half a minute)
"""
import numpy as np
from scipy.optimize import minimize_scalar

N = 6.0e-3           # white noise, m/s^2/sqrt(Hz)
K_TH = 7.15099e-05   # detectable K, shimmer acc (vectors/sim/detectable.csv)
D = 1.0              # block-mean length, s
L = 1080             # fit blocks of 1080 s
GAP = 1440           # held-out middle, s
SUB = 20             # sub-steps per block for the walk's block mean
RUNS = 100

rng = np.random.default_rng(20261123)


def simulate(K):
    """Block means of the two fit blocks (the walk runs through the gap)."""
    n = 2 * L + GAP
    w = rng.standard_normal(n * SUB) * K * np.sqrt(D / SUB)
    b = np.cumsum(w).reshape(n, SUB).mean(axis=1)
    y = b + rng.standard_normal(n) * N / np.sqrt(D)
    keep = np.r_[np.arange(L), np.arange(L + GAP, n)]
    return y, keep


def nll(y, keep, K):
    q = K * K * D
    r = N * N / D - K * K * D / 6.0
    if r <= 0.0:
        return np.inf
    x, P = y[keep[0]], r
    last, tot = keep[0], 0.0
    for k in keep[1:]:
        P += q * (k - last)
        last = k
        S = P + r
        v = y[k] - x
        tot += np.log(S) + v * v / S
        g = P / S
        x += g * v
        P *= 1.0 - g
    return tot


def fit(y, keep):
    """K maximising the likelihood, searched in ln K over [K_th/20, 40 K_th]."""
    res = minimize_scalar(lambda l: nll(y, keep, np.exp(l)), bounds=(np.log(K_TH / 20.0), np.log(K_TH * 40.0)),
                          method="bounded", options={"xatol": 1e-3})
    return np.exp(res.x)

for mult in (1.0, 1.5, 2.0, 3.0):
    K = mult * K_TH
    e = np.array([fit(*simulate(K)) / K - 1.0 for _ in range(RUNS)])
    print("%.1fx threshold: within 25 %% %3.0f %% of %d logs, median |error| %.3f"
          % (mult, 100.0 * np.mean(np.abs(e) <= 0.25), RUNS, np.median(np.abs(e))))
