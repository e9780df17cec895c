#!/usr/bin/env python3
"""The best a jumps amplitude can do in the simgap validation (docs/simgap.md).

Steps N(0, amp^2) at 6 per hour; the fit segment is 60 % of one hour
(2160 s), so it holds n ~ Poisson(3.6) steps. An estimator that knew every
step's size exactly would use sqrt(sum s^2 / n), with sum s^2 / amp^2 ~
chi^2_n; it is within 25 % of amp when that lies in [0.5625 n, 1.5625 n].
Prints that probability for n = 4 and averaged over the Poisson count
(given at least one step, as the validation needs one to name `jumps`).
Then the same for n = 3, the steps found on gy of the run of 2026-12-02's
case 23 (5 per hour on the fit segment's 2160 s), and how often such an
estimator is as low as that case's amplitude (0.743 of the truth: relative
error 0.257).
Run with Debian's /usr/bin/python3 (scipy).
"""
from scipy.stats import chi2, poisson


def within(n, tol=0.25):
    return chi2.cdf((1 + tol) ** 2 * n, n) - chi2.cdf((1 - tol) ** 2 * n, n)


def main():
    lam = 6.0 / 3600.0 * 0.6 * 3600.0
    p = sum(poisson.pmf(n, lam) * within(n) for n in range(1, 80)) / (1.0 - poisson.pmf(0, lam))
    print("n = 4: P(within 25 %%) = %.3f" % within(4))
    print("n ~ Poisson(%.1f), n >= 1: P(within 25 %%) = %.3f" % (lam, p))
    r = 1.0 - 0.257
    print("n = 3: P(within 25 %%) = %.3f; P(estimate <= %.3f amp) = %.3f; P(error >= 0.257 either way) = %.3f"
          % (within(3), r, chi2.cdf(3 * r * r, 3), 1.0 - within(3, 0.257)))


if __name__ == "__main__":
    main()
