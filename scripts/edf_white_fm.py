#!/usr/bin/python3
"""EDF of the overlapping Allan variance of white FM (white rate noise) at
small m: Greenhall & Riley's model against the discrete-time truth.

fnav_allan_edf(0, m, n, 1) is Greenhall & Riley's algorithm (PTTI 2003) as
Stable32 uses it: for the unmodified variance the filter factor F = m, i.e.
the phase is modelled as averaged over one sample. A record of i.i.d. rate
samples (white noise; the harness's phase is their running sum, x_k =
y_0 + .. + y_{k-1}) has point-sampled phase, whose exact EDF is the same
basic sum with F = infinity. This prints, for white FM and the overlapping
Allan variance of n phase values:

- "GR F=m": Greenhall & Riley's basic sum with F = m (what the C code gives:
  scripts/pvar_edf.py --greenhall checks that identity at every alpha);
- "GR F=inf": the same sum with F = infinity;
- "exact": 2 E[s2]^2 / Var[s2] from the exact covariance of the second
  differences of a discrete random walk (no model);
- "MC": the same from R simulated records (relative standard error about
  sqrt(2 / R)).

Usage: /usr/bin/python3 scripts/edf_white_fm.py [N_PHASE [R]]   (default 4001, 4000)
"""
import math
import sys

import numpy as np


def sw(t):
    return abs(t) ** 3  # Greenhall & Riley's sw for alpha = 0


def sx(t, F):
    if math.isinf(F):
        return -6.0 * abs(t)  # the limit of F^2 (2 sw(t) - sw(t - 1/F) - sw(t + 1/F))
    return F * F * (2.0 * sw(t) - sw(t - 1.0 / F) - sw(t + 1.0 / F))


def sz(t, F):
    return sum((-1) ** k * math.comb(4, 2 - k) * sx(t + k, F) for k in range(-2, 3))


def gr_edf(m, n, F):
    """Their basic sum for d = 2, overlapping (S = m), J = min(M, 3m) lags."""
    M = n - 2 * m
    J = min(M, 3 * m)
    s = sz(0.0, F) ** 2 + (1.0 - J / M) * sz(J / m, F) ** 2
    s += 2.0 * sum((1.0 - j / M) * sz(j / m, F) ** 2 for j in range(1, J))
    return M * sz(0.0, F) ** 2 / s


def exact_edf(m, n):
    """Second differences d_i = sum of y over [i+m, i+2m) minus over [i, i+m)."""
    K = n - 2 * m
    h = np.r_[-np.ones(m), np.ones(m)]
    c = [float(np.dot(h[: 2 * m - l], h[l:])) for l in range(2 * m)]
    var = 2.0 * (K * c[0] ** 2 + 2.0 * sum((K - l) * c[l] ** 2 for l in range(1, min(2 * m, K))))
    return 2.0 * (K * c[0]) ** 2 / var


def mc_edf(m, n, R, rng):
    y = rng.standard_normal((R, n - 1))
    x = np.concatenate([np.zeros((R, 1)), np.cumsum(y, axis=1)], axis=1)
    d = x[:, 2 * m:] - 2.0 * x[:, m:-m] + x[:, : -2 * m]
    v = np.mean(d * d, axis=1)
    return 2.0 * v.mean() ** 2 / v.var(ddof=1)


def main():
    n = int(sys.argv[1]) if len(sys.argv) > 1 else 4001
    R = int(sys.argv[2]) if len(sys.argv) > 2 else 4000
    rng = np.random.default_rng(7)
    print("white FM, overlapping AVAR, %d phase values, %d records" % (n, R))
    print("%4s %10s %10s %10s %10s %9s" % ("m", "GR F=m", "GR F=inf", "exact", "MC", "F=m/exact"))
    for m in (1, 2, 4, 8, 16, 32):
        a, b, e = gr_edf(m, n, float(m)), gr_edf(m, n, math.inf), exact_edf(m, n)
        print("%4d %10.1f %10.1f %10.1f %10.1f %9.3f" % (m, a, b, e, mc_edf(m, n, R, rng), a / e))


if __name__ == "__main__":
    main()
