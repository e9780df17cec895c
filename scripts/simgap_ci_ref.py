#!/usr/bin/python3
"""Reference values of tests/test_simgap.c's test_refit_quantile and
test_ci_from_refits (the interval of the refits): numpy's percentiles with
its default method, linear interpolation between the order statistics
(numpy.percentile(x, q), method="linear": h = (n - 1) q / 100, x[floor h]
+ (h - floor h) (x[floor h + 1] - x[floor h]); Hyndman and Fan's type 7),
the definition simgap's ci68 uses (docs/simgap.md, section 3).

Usage: /usr/bin/python3 scripts/simgap_ci_ref.py
"""
import numpy as np

# test_refit_quantile: 16 values (as S = 16 twins' refits), then 8 (the
# fewest simgap gives an interval from) and 1
x16 = np.array([0.61, 0.47, 0.52, 0.95, 0.44, 0.58, 0.50, 0.49, 0.71, 0.55, 0.46, 0.53, 0.66, 0.48, 0.57, 0.51])
x8 = np.array([3.0, 1.0, 4.0, 1.5, 9.0, 2.6, 5.0, 3.5])
for name, x in (("x16", x16), ("x8", x8), ("x1", np.array([2.5]))):
    for q in (0.0, 16.0, 50.0, 84.0, 100.0):
        print("%s q %5.1f %%: %.17g" % (name, q, np.percentile(x, q)))

# test_ci_from_refits: 11 refits, the last failed (not counted); the AR(1)
# sigma over the other 10, one of them 0 (a refit without an AR(1)); the
# time over the 9 with sigma > 0
tau = np.array([2.0, 1.0, 4.0, 3.0, 1.6, 2.2, 8.0, 2.9, 1.2])
sigma = np.array([0.5, 0.4, 0.7, 0.6, 0.45, 0.0, 0.55, 0.9, 0.52, 0.48])
print("sigma over the %d counted refits: sd %.17g, p16 %.17g, p50 %.17g, p84 %.17g"
      % (len(sigma), sigma.std(ddof=1), np.percentile(sigma, 16), np.percentile(sigma, 50),
         np.percentile(sigma, 84)))
print("tau over the %d counted refits: sd %.17g, p16 %.17g, p50 %.17g, p84 %.17g"
      % (len(tau), tau.std(ddof=1), np.percentile(tau, 16), np.percentile(tau, 50), np.percentile(tau, 84)))
