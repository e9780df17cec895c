#!/usr/bin/python3
"""Reference for tests/test_align.c test_rounded_variance_clamped: the
still period's accelerometer variance in float32 with fnav_align.c's order
of operations (add_sample: running sums of the offsets from the period's
first sample, sa and sa2; period_result: ma = sa (1 / n), va = (sa2 - sa
ma) (1 / (n - 1))), numpy float32 throughout. The period holds one sample
of -9.81 m/s^2 and 10,000 of -9.81 + 0.7: the true variance is 0.7^2 / n
(4.9e-5), which the float32 sums round to a negative number (-5.2e-6), so
fnav_align must clamp it (the test asserts a standard deviation of 0 in the
float build). Prints the terms and the variance; exit 1 if it is not
negative (the test's float branch would then be wrong).

  /usr/bin/python3 tests/align_clamp_ref.py
"""
import sys
import numpy as np

f = np.float32
n = 10001
d = f(f(-9.81 + 0.7) - f(-9.81))  # the offset of the 10,000 samples (exact: Sterbenz)
sa = f(0.0)
sa2 = f(0.0)
for k in range(n):
    dk = f(0.0) if k == 0 else d
    sa = f(sa + dk)
    sa2 = f(sa2 + f(dk * dk))
inv = f(f(1.0) / f(n))
ma = f(sa * inv)
va = f(f(sa2 - f(sa * ma)) * f(f(1.0) / f(n - 1)))
# the true sample variance of one 0 and n - 1 offsets d: d^2 / n
print("d %.9g sa %.9g sa2 %.9g ma %.9g: float32 variance %.4g (true %.4g)" % (d, sa, sa2, ma, va, float(d) ** 2 / n))
sys.exit(0 if va < 0 else 1)
