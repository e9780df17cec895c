#!/usr/bin/python3
"""How well can any estimator get flicker's B from the fit segment of a
validation case? (docs/simgap.md, "Validation": the parameter target.)

The same setting as scripts/flicker_rrw_limit.py (whose simulation and
likelihood it uses): the Shimmer accelerometer's white noise N, one hour,
fit on the first and last 1080 s, white noise plus the simulator's flicker
at a multiple of its detectable B. The ideal estimator knows the model
exactly (white + flicker, nothing else, N known) and maximises the exact
Gaussian likelihood of the first differences of the 4 s block means of the
two fit blocks over B. Prints, per multiple of the threshold, the fraction
of simulated logs whose B is within 25 % of the truth and the median
relative error.

With --ar1 the estimator also fits an AR(1) nuisance beside the flicker,
as the diagnosis's baseline model must (scripts/flicker_rrw_ar1_limit.py):
B at the joint maximum, and B when the AR(1) is kept only if it lowers
-2 ln L by more than 4 (two parameters' worth, Akaike's rule). The logs
hold no AR(1).

Run: /usr/bin/python3 scripts/flicker_b_limit.py [--ar1]
(about two minutes; with --ar1 about 5 minutes, multiples 1, 2 and 3)
"""
import sys

import numpy as np
from scipy.optimize import minimize_scalar

import flicker_rrw_limit as flk
import flicker_rrw_ar1_limit as ar1

RUNS = 100


def ml_b(segs):
    """B maximising the likelihood, searched in its log within a factor 30 of the threshold."""
    res = minimize_scalar(lambda l: flk.nll(segs, flk.FLK_UNIT, np.exp(2.0 * l)),
                          bounds=(np.log(flk.B_TH / 30.0), np.log(flk.B_TH * 30.0)),
                          method="bounded", options={"xatol": 1e-3})
    return np.exp(res.x)


def main_ar1():
    flk.rng = np.random.default_rng(20261125)
    for mult in (1.0, 2.0, 3.0):
        b = mult * flk.B_TH
        e = {"without": [], "joint": [], "aic": []}
        for _ in range(RUNS):
            q, m, q0, m0 = ar1.fit_ar1(flk.simulate("flicker", b), flk.FLK_UNIT, flk.B_TH)
            e["without"].append(abs(m0 / b - 1.0))
            e["joint"].append(abs(m / b - 1.0))
            e["aic"].append(abs((m if q < q0 - 4.0 else m0) / b - 1.0))
        print("%.1fx threshold: B within 25 %% in %s of %d (median error %s): without the AR(1), jointly, "
              "AR(1) only when it pays" % (mult, " / ".join(str(int(np.sum(np.array(v) <= 0.25))) for v in e.values()),
                                           RUNS, " / ".join("%.3f" % np.median(v) for v in e.values())), flush=True)


def main():
    if "--ar1" in sys.argv[1:]:
        main_ar1()
        return
    flk.rng = np.random.default_rng(20261124)
    for mult in (1.0, 1.5, 2.0, 3.0, 4.0):
        b = mult * flk.B_TH
        err = np.array([abs(ml_b(flk.simulate("flicker", b)) / b - 1.0) for _ in range(RUNS)])
        print("%.1fx threshold: B within 25 %% in %d/%d, median error %.3f"
              % (mult, int(np.sum(err <= 0.25)), RUNS, float(np.median(err))), flush=True)


if __name__ == "__main__":
    main()
