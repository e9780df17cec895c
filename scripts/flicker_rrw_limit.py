#!/usr/bin/python3
"""Can flicker and a rate random walk be told apart near threshold?
(docs/simgap.md, "Validation"; what would help next: docs/simgap-history.md.)

The validation's static case on the Shimmer accelerometer (white N 6.0e-3
m/s^2/sqrt(Hz); detectable B 8.0e-4 m/s^2 and K 7.15e-5 m/s^2/sqrt(s),
vectors/sim/detectable.csv): one hour, fit on the first and last 1080 s.
Each simulated log holds white noise plus either the simulator's flicker
(12 AR(1) poles log-spaced over 0.5-5000 s, equal variance B^2 ln r / pi,
docs/simulator.md) or a walk, at a multiple of its threshold. The ideal
test knows both models exactly (white N known, nothing else in the data),
fits each one's magnitude by the exact Gaussian likelihood of the first
differences of the 4 s block means of the two fit blocks (their
autocovariances in closed form, a dense Cholesky), and names the model with
the higher likelihood. Prints, per multiple, how often it names each right.

Run: /usr/bin/python3 scripts/flicker_rrw_limit.py   (about a minute)
"""
import numpy as np
from scipy.linalg import cho_factor, cho_solve
from scipy.optimize import minimize_scalar
from scipy.signal import lfilter

N = 6.0e-3
K_TH = 7.15099e-05
B_TH = 8.00685e-04
D = 4.0                       # block-mean length, s
L, GAP = 1080.0, 1440.0       # fit blocks and the held-out middle, s
SUB = 16                      # simulation sub-steps per block
P = 12                        # flicker poles over [0.5, 5000] s
TAUS = 0.5 * np.exp(np.log(5000.0 / 0.5) * np.arange(P) / (P - 1))
LNR = np.log(5000.0 / 0.5) / (P - 1)
RUNS = 60
NB, NG = int(L / D), int(GAP / D)
DT = D / SUB

rng = np.random.default_rng(20261123)


def simulate(kind, mag):
    n = (2 * NB + NG) * SUB
    if kind == "rrw":
        b = np.cumsum(rng.standard_normal(n) * mag * np.sqrt(DT))
    else:
        v = mag * mag * LNR / np.pi
        b = np.zeros(n)
        for t in TAUS:
            ph = np.exp(-DT / t)
            x0 = rng.standard_normal() * np.sqrt(v)
            e = rng.standard_normal(n) * np.sqrt(v * (1.0 - ph * ph))
            xs, _ = lfilter([1.0], [1.0, -ph], e, zi=[ph * x0])
            b += xs
    bm = b.reshape(-1, SUB).mean(axis=1)
    y = bm + rng.standard_normal(bm.size) * N / np.sqrt(D)
    return [y[:NB], y[NB + NG:]]


def ar1_blockmean_acov(s2, tau, kmax):
    """Autocovariance of D-long block means of an AR(1) (variance s2, tau)."""
    a = D / tau
    c = np.empty(kmax + 1)
    c[0] = 2.0 * s2 / (a * a) * (a - 1.0 + np.exp(-a))
    k = np.arange(1, kmax + 1)
    c[1:] = s2 / (a * a) * (2.0 * np.cosh(a) - 2.0) * np.exp(-k * a)
    return c


def diff_acov(c):
    """Autocovariance of the first differences of a stationary series."""
    d = np.empty(len(c) - 1)
    d[0] = 2.0 * (c[0] - c[1])
    d[1:] = 2.0 * c[1:-1] - c[:-2] - c[2:]
    return d


n1 = NB - 1
WHITE = np.zeros(n1)
WHITE[0], WHITE[1] = 2.0 * N * N / D, -N * N / D
RRW_UNIT = np.zeros(n1)                        # per K^2
RRW_UNIT[0], RRW_UNIT[1] = 2.0 * D / 3.0, D / 6.0
FLK_UNIT = diff_acov(sum(ar1_blockmean_acov(LNR / np.pi, t, n1) for t in TAUS))  # per B^2
IDX = np.abs(np.arange(n1)[:, None] - np.arange(n1)[None, :])


def nll_acv(segs, acv):
    """-2 ln L of the segments' differenced block means with autocovariance acv."""
    cf = cho_factor(acv[IDX])
    logdet = 2.0 * np.log(np.diag(cf[0])).sum()
    return sum(logdet + d @ cho_solve(cf, d) for d in (np.diff(y) for y in segs))


def nll(segs, unit, m2):
    return nll_acv(segs, WHITE + m2 * unit)


def fit_mag(segs, unit, m0):
    """(least -2 ln L, magnitude) over the magnitude, searched in its log within a factor 30 of m0."""
    res = minimize_scalar(lambda l: nll(segs, unit, np.exp(2.0 * l)), bounds=(np.log(m0 / 30.0), np.log(m0 * 30.0)),
                          method="bounded", options={"xatol": 2e-3})
    return res.fun, np.exp(res.x)


def best_nll(segs, unit, m0):
    return fit_mag(segs, unit, m0)[0]


def main():
    for mult in (1.0, 1.5, 2.0):
        right = {}
        for kind in ("flicker", "rrw"):
            ok = 0
            for _ in range(RUNS):
                segs = simulate(kind, mult * (B_TH if kind == "flicker" else K_TH))
                named = "flicker" if best_nll(segs, FLK_UNIT, B_TH) < best_nll(segs, RRW_UNIT, K_TH) else "rrw"
                ok += named == kind
            right[kind] = ok
        print("%.1fx threshold: flicker named right %d/%d, rrw named right %d/%d"
              % (mult, right["flicker"], RUNS, right["rrw"], RUNS), flush=True)


if __name__ == "__main__":
    main()
