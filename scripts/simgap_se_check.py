#!/usr/bin/python3
"""How well the Allan fit's standard errors describe its spread.

Writes 16 logs of pure white noise (300 s at 100 Hz, density 1e-3 m/s^2/sqrt(Hz)
on the accelerometers and 5e-4 rad/s/sqrt(Hz) on the gyros, numpy seeds
1-16) to a temporary directory, runs `bin/harness simgap LOG --max-effects 0
--json` on each and compares the baseline's `white_density_se` (the
Gauss-Newton covariance of the Allan fit, docs/simgap.md, section 4) with
the spread of `white_density` over the seeds, on the fits without an AR(1)
(the model then is the truth). The Cramer-Rao bound of a white density
from n samples, 1 / sqrt(2 n) relative, is printed beside them: the fit
segment holds 18,000 samples.

Usage: /usr/bin/python3 scripts/simgap_se_check.py [HARNESS]
"""
import json
import os
import subprocess
import sys
import tempfile

import numpy as np

FS = 100.0
N = 30000
SEEDS = range(1, 17)


def main():
    harness = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "..", "bin", "harness")
    truth = [1e-3, 1e-3, 1e-3, 5e-4, 5e-4, 5e-4]
    val = {ch: [] for ch in range(6)}
    se = {ch: [] for ch in range(6)}
    nfit = None
    with tempfile.TemporaryDirectory() as tmp:
        for s in SEEDS:
            rng = np.random.default_rng(s)
            t = np.arange(N) / FS
            x = rng.normal(0.0, 1.0, (N, 6)) * np.array(truth) * np.sqrt(FS)
            x[:, 2] += 9.81
            log = os.path.join(tmp, "w%d.csv" % s)
            out = os.path.join(tmp, "w%d.json" % s)
            np.savetxt(log, np.column_stack([t, x]), delimiter=",", header="t,ax,ay,az,gx,gy,gz", comments="",
                       fmt="%.9f")
            subprocess.run([harness, "simgap", log, "--quiet", "--max-effects", "0", "--json", out],
                           stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, check=False)
            with open(out) as f:
                d = json.load(f)
            nfit = sum(b["samples"] for b in d["split"]["fit"])
            for ch in range(6):
                b = d["channels"][ch]["baseline"]
                if b["ar1_sigma"] > 0.0:
                    continue
                val[ch].append(b["white_density"] / truth[ch])
                se[ch].append(b["white_density_se"] / truth[ch])
    dev2, dof, ses = 0.0, 0, []
    for ch in range(6):
        v = np.array(val[ch])
        e = np.array(se[ch])
        name = ["ax", "ay", "az", "gx", "gy", "gz"][ch]
        print("%s: %2d fits without AR(1): relative sd %.4f, mean relative se %.4f, ratio %.2f"
              % (name, len(v), v.std(ddof=1), e.mean(), v.std(ddof=1) / e.mean()))
        dev2 += float(((v - v.mean()) ** 2).sum())
        dof += len(v) - 1
        ses += list(e)
    sd = np.sqrt(dev2 / dof)
    print("pooled: relative sd %.4f (%d degrees of freedom), mean relative se %.4f, ratio %.2f; "
          "Cramer-Rao bound 1/sqrt(2 x %d) = %.4f" % (sd, dof, np.mean(ses), sd / np.mean(ses), nfit,
                                                     1.0 / np.sqrt(2.0 * nfit)))


if __name__ == "__main__":
    main()
