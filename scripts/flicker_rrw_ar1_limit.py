#!/usr/bin/python3
"""Does a free AR(1) beside the drift cost the flicker/rrw discrimination?
(docs/simgap.md, "Validation": flicker and rrw near threshold.)

scripts/flicker_rrw_limit.py's ideal test knows the white noise and that
nothing else is in the data: it names flicker right in 50-59 of 60 logs at
1-2x threshold. The diagnosis cannot assume that: its baseline model is
white noise plus an AR(1) bias per channel (issue 6), fitted beside every
candidate. This script runs logs from the same generator (the same
two 1080 s fit blocks, the same 4 s block means and exact
likelihood) through the same test, except that each of the two models also
carries an AR(1) nuisance with its sigma and tau fitted jointly with the
drift's magnitude (tau over 4-400 s, sigma down to zero); 40 logs per
multiple and model. Both models have
the same number of free parameters, so their maxima compare directly.
The logs hold no AR(1) (the profiles' AR(1) is negligible at these time
scales). Prints, per multiple, how often each test names each model right
on the same logs.

Run: /usr/bin/python3 scripts/flicker_rrw_ar1_limit.py [MULT ...]
(default 1 1.5 2; about 2 minutes per multiple on one core)
"""
import os
import sys

import numpy as np
from scipy.optimize import minimize

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import flicker_rrw_limit as fl  # noqa: E402  (the generator and the likelihood)

TAU_GRID = np.exp(np.linspace(np.log(4.0), np.log(400.0), 5))  # AR(1) tau, s
RUNS = 40


def ar1_unit(tau):
    """Differenced block-mean autocovariance of an AR(1) of unit variance."""
    return fl.diff_acov(fl.ar1_blockmean_acov(1.0, tau, fl.n1))


AR1_UNITS = [ar1_unit(t) for t in TAU_GRID]


def fit_ar1(segs, unit, m0):
    """Least -2 ln L over the magnitude (within a factor 30 of m0), the AR(1)'s
    variance (from 1e-4 of the white noise's block-mean variance up to 100
    times it, the lower end standing for none; started at a tenth) and tau
    (five values over 4-400 s), the magnitude started at its fit without
    the AR(1). Returns (-2 ln L, magnitude) with the AR(1) and without it."""
    w = fl.N * fl.N / fl.D
    q0, m0_fit = fl.fit_mag(segs, unit, m0)
    best, mag = q0, m0_fit
    for aunit in AR1_UNITS:
        def f(p):
            return fl.nll_acv(segs, fl.WHITE + np.exp(2.0 * p[0]) * unit + np.exp(p[1]) * aunit)
        res = minimize(f, x0=[np.log(m0_fit), np.log(0.1 * w)], method="L-BFGS-B",
                       bounds=[(np.log(m0 / 30.0), np.log(m0 * 30.0)), (np.log(1e-4 * w), np.log(100.0 * w))])
        if res.fun < best:
            best, mag = res.fun, np.exp(res.x[0])
    return best, mag, q0, m0_fit


def main():
    mults = [float(a) for a in sys.argv[1:]] or [1.0, 1.5, 2.0]
    for mult in mults:
        fl.rng = np.random.default_rng(20261124 + int(round(10.0 * mult)))  # the same logs whatever the order
        right = {"flicker": [0, 0], "rrw": [0, 0]}
        for kind in ("flicker", "rrw"):
            for _ in range(RUNS):
                segs = fl.simulate(kind, mult * (fl.B_TH if kind == "flicker" else fl.K_TH))
                qf, _, qf0, _ = fit_ar1(segs, fl.FLK_UNIT, fl.B_TH)
                qr, _, qr0, _ = fit_ar1(segs, fl.RRW_UNIT, fl.K_TH)
                plain = "flicker" if qf0 < qr0 else "rrw"
                nuis = "flicker" if qf < qr else "rrw"
                right[kind][0] += plain == kind
                right[kind][1] += nuis == kind
        print("%.1fx threshold: flicker named right %d/%d without, %d/%d with the AR(1) nuisance; "
              "rrw %d/%d without, %d/%d with" % (mult, right["flicker"][0], RUNS, right["flicker"][1], RUNS,
                                                   right["rrw"][0], RUNS, right["rrw"][1], RUNS), flush=True)


if __name__ == "__main__":
    main()
