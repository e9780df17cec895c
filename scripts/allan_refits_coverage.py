#!/usr/bin/env python3
"""How often `harness allan --refits N`'s 68 % interval holds the truth
(docs/allan.md, "The corrected fit's interval (`--refits N`)").

REPS series of white noise (0.2 u per sample at 10 Hz) plus a stationary
AR(1) bias (T samples, stationary std 0.3 u; its first value drawn from the
stationary law, so that no start-up transient biases the fit) of N samples
each, seeds 100 .. 100 + REPS - 1, are analysed by
`harness allan --series F --rate 10 --no-sim --refits REFITS --seed K` (K = 1 ..
REPS: each series its own refits, so that the shares are of independent
intervals; with one --seed every series would take the same draws,
scaled to its fit, and the shares would be of one draw). Prints the mean
and standard deviation of the fitted tau and sigma_bias over the series
(the spread the interval should describe), the intervals' median
half-width, and the share of the intervals that hold the truth (68 % is
the aim; with 30 series the share itself is uncertain by about 0.085).
Series whose AR(1) part is not identified are counted and skipped.

Usage: /usr/bin/python3 scripts/allan_refits_coverage.py T N REPS [REFITS]
       (REFITS default 20; HARNESS=path overrides bin/harness), e.g.
       300 50000 30: about 8 s.
"""
import os
import re
import subprocess
import sys
import tempfile

import numpy as np
from scipy.signal import lfilter

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
H = os.environ.get("HARNESS", os.path.join(ROOT, "bin", "harness"))
SB = 0.3  # stationary std of the bias, u


def main():
    if len(sys.argv) not in (4, 5):
        sys.exit(__doc__)
    T, N, reps = float(sys.argv[1]), int(sys.argv[2]), int(sys.argv[3])
    refits = int(sys.argv[4]) if len(sys.argv) == 5 else 20
    c = np.exp(-1.0 / T)
    fits, ints, skipped = [], [], 0
    with tempfile.TemporaryDirectory() as tmp:
        path = os.path.join(tmp, "series.txt")
        for s in range(reps):
            r = np.random.default_rng(100 + s)
            e = SB * np.sqrt(1.0 - c * c) * r.standard_normal(N)
            b = lfilter([1.0], [1.0, -c], e, zi=[c * SB * r.standard_normal()])[0]
            np.savetxt(path, 0.2 * r.standard_normal(N) + b)
            out = subprocess.run([H, "allan", "--series", path, "--rate", "10", "--no-sim", "--refits", str(refits),
                                  "--seed", str(1 + s), "--quiet"], capture_output=True, text=True, check=True).stdout
            rows = [l for l in out.splitlines() if l.startswith("series u")]
            m = re.search(r"tau (\S+) to (\S+) samples, sigma_bias (\S+) to (\S+)", rows[-1])
            if m is None:
                skipped += 1
                continue
            f = rows[0].split("|")[2].split()
            fits.append((float(f[1]), float(f[2])))
            ints.append(tuple(float(x) for x in m.groups()))
    fits, ints = np.array(fits), np.array(ints)
    print("T %g samples, N %d, %d series (%d skipped: AR(1) not identified), %d refits each"
          % (T, N, len(fits), skipped, refits))
    print("fitted tau: mean %.1f, sd %.1f (truth %g); sigma_bias: mean %.3f, sd %.3f (truth %g)"
          % (fits[:, 0].mean(), fits[:, 0].std(ddof=1), T, fits[:, 1].mean(), fits[:, 1].std(ddof=1), SB))
    q = np.percentile(fits, [15.87, 84.13], axis=0)
    print("fits' own 68 %% half-range: tau %.1f, sigma_bias %.3f" % ((q[1, 0] - q[0, 0]) / 2, (q[1, 1] - q[0, 1]) / 2))
    print("interval median half-width: tau %.1f, sigma_bias %.3f"
          % (np.median((ints[:, 1] - ints[:, 0]) / 2), np.median((ints[:, 3] - ints[:, 2]) / 2)))
    print("share holding the truth: tau %.2f, sigma_bias %.2f"
          % (np.mean((ints[:, 0] <= T) & (T <= ints[:, 1])), np.mean((ints[:, 2] <= SB) & (SB <= ints[:, 3]))))


if __name__ == "__main__":
    main()
