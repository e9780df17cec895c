#!/usr/bin/python3
"""The equivalent degrees of freedom that a Stable32 table's printed limits imply.

Stable32 prints, per averaging factor, min sigma, sigma and max sigma at a
"Confidence Factor" of 0.683. Each limit alone gives the EDF of the
chi-square interval it came from (SP 1065 eq. 45): min = sigma sqrt(edf /
chi2(1 - p/2, edf)), max = sigma sqrt(edf / chi2(p/2, edf)), p = 1 - conf.
One interval has one EDF, so the confidence at which the EDFs from the two
limits agree is the one Stable32 used. This script prints both EDFs at
conf 0.683 and at erf(1/sqrt(2)) = 0.682689 (one sigma) for every row.

Usage: /usr/bin/python3 scripts/stable32_conf.py STABLE32.txt
Example (docs/allan.md, "Confidence intervals"):
  /usr/bin/python3 scripts/stable32_conf.py ../shared/data/allan_reference/phasedat/phase_dat_hdev_octave.txt
"""
import math
import sys

from scipy.optimize import brentq
from scipy.stats import chi2


def implied(dev, lim, q):
    """EDF (>= 1) at which dev sqrt(edf / chi2.ppf(q, edf)) equals the limit."""
    return brentq(lambda e: dev * math.sqrt(e / chi2.ppf(q, e)) - lim, 1.0, 1e7)  # monotone in edf from 1 on


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__.split("\n\n")[-1])
    confs = (0.683, math.erf(1.0 / math.sqrt(2.0)))
    print("%6s %6s %5s | %s" % ("m", "terms", "alpha",
                                 " | ".join("conf %.6f: edf(min) edf(max)" % c for c in confs)))
    for line in open(sys.argv[1]):
        c = line.split()
        if line.startswith("#") or len(c) < 7 or float(c[4]) <= 0.0:
            continue
        lo, dev, hi = float(c[4]), float(c[5]), float(c[6])
        cols = []
        for conf in confs:
            p = 1.0 - conf
            cols.append("%10.4f %10.4f" % (implied(dev, lo, 1.0 - p / 2.0), implied(dev, hi, p / 2.0)))
        print("%6s %6s %5s | %s" % (c[0], c[2], c[3], " | ".join("            " + x for x in cols)))


if __name__ == "__main__":
    main()
