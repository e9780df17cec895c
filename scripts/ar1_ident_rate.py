#!/usr/bin/python3
"""How often `harness allan` takes a Gauss-Markov (AR(1)) bias as identified.

Simulates series of known noise in numpy (white noise of density N, plus an
optional stationary AR(1) of std sigma and correlation time T, paper eqs.
2-4), runs `harness allan --series F --rate FS --estimator streaming` on each
and counts the channels whose JSON says `ar1_identified` (the fit a profile
holds as the bias; docs/allan.md, "When the AR(1) part is not identifiable").
On white noise alone every identification is a false one.

Usage: /usr/bin/python3 scripts/ar1_ident_rate.py [--harness bin/harness] [--fs 100] [--n 1000,3000]
       [--seeds 20] [--white 0.01] [--sigma 0] [--tau 5]
Examples (docs/allan.md):
  /usr/bin/python3 scripts/ar1_ident_rate.py --n 1000,3000,6000,30000,100000 --seeds 20
  /usr/bin/python3 scripts/ar1_ident_rate.py --n 30000,100000 --seeds 10 --sigma 0.004 --tau 5
"""
import argparse
import json
import os
import subprocess
import tempfile

import numpy as np
from scipy.signal import lfilter


def series(rng, n, fs, white, sigma, tau):
    y = white * np.sqrt(fs) * rng.standard_normal(n)
    if sigma > 0.0:
        c = np.exp(-1.0 / (tau * fs))
        drive = sigma * np.sqrt(1.0 - c * c) * rng.standard_normal(n)  # eq. (4)
        b, _ = lfilter([1.0], [1.0, -c], drive, zi=[c * sigma * rng.standard_normal()])  # eq. (3), stationary start
        y += b
    return y


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--harness", default="bin/harness")
    ap.add_argument("--fs", type=float, default=100.0)
    ap.add_argument("--n", default="1000,3000")
    ap.add_argument("--seeds", type=int, default=20)
    ap.add_argument("--white", type=float, default=0.01)
    ap.add_argument("--sigma", type=float, default=0.0)
    ap.add_argument("--tau", type=float, default=5.0)
    a = ap.parse_args()
    with tempfile.TemporaryDirectory() as d:
        f, j = os.path.join(d, "s.txt"), os.path.join(d, "s.json")
        for n in (int(float(x)) for x in a.n.split(",")):
            hits = 0
            for seed in range(1, a.seeds + 1):
                rng = np.random.default_rng(seed)
                np.savetxt(f, series(rng, n, a.fs, a.white, a.sigma, a.tau), fmt="%.9e")
                subprocess.run([a.harness, "allan", "--series", f, "--rate", "%g" % a.fs, "--estimator", "streaming",
                                "--no-sim", "--quiet", "--json", j], check=True, stdout=subprocess.DEVNULL,
                               stderr=subprocess.DEVNULL)
                hits += bool(json.load(open(j))["channels"][0]["corrected"]["ar1_identified"])
            print("n = %d (%g s): AR(1) identified in %d of %d records" % (n, n / a.fs, hits, a.seeds))


if __name__ == "__main__":
    main()
