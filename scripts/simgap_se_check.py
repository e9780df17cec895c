#!/usr/bin/python3
"""How well simgap's standard errors describe the spread of its estimates.

Writes 16 logs (300 s at 100 Hz, numpy seeds 1-16) to a temporary
directory, runs `bin/harness simgap LOG --max-effects 0 --json` on each and
compares each baseline parameter's `*_se` with the spread of the parameter
over the seeds (docs/simgap.md, section 3, the paragraph on the standard
errors after the parameter bootstrap, and Limitations):

- default: pure white noise, density 1e-3 m/s^2/sqrt(Hz) on the
  accelerometers and 5e-4 rad/s/sqrt(Hz) on the gyros; the white density
  on the fits without an AR(1) (the model then is the truth). The
  Cramer-Rao bound of a white density from n samples, 1 / sqrt(2 n)
  relative, is printed beside it: the fit segment holds 18,000 samples.
- --ar1: the same white noise plus an AR(1) bias (sigma 2e-3 m/s^2 and
  1e-3 rad/s, tau 0.5 s); the white density, the AR(1) sigma and tau on the
  fits with an AR(1).

For each parameter: the relative sd over the seeds, the mean relative se,
their ratio per channel and pooled over the channels (the sd pooled about
each channel's mean), and the 95 % interval the pooled ratio falls in when
the se is right: the chi-square interval of the pooled sd for its degrees
of freedom, widened by the se's own scatter (each se is the sd of 16 twins'
refits, about 1 / sqrt(2 x 15) relative; the observed scatter of the se's
is used).

Usage: /usr/bin/python3 scripts/simgap_se_check.py [--ar1] [HARNESS]
"""
import json
import os
import subprocess
import sys
import tempfile

import numpy as np
from scipy import stats

FS = 100.0
N = 30000
SEEDS = range(1, 17)
NAMES = ["ax", "ay", "az", "gx", "gy", "gz"]


def write_log(path, seed, white, sig=None, tau=0.5):
    """A static log of N samples at FS Hz to path (CSV, t and six channels):
    white noise of density white per channel (numpy seed seed), plus an
    AR(1) of sd sig and time tau s unless sig is None, gravity on az."""
    rng = np.random.default_rng(seed)
    t = np.arange(N) / FS
    x = rng.normal(0.0, 1.0, (N, 6)) * white * np.sqrt(FS)
    if sig is not None:
        phi = np.exp(-1.0 / (FS * tau))
        e = rng.normal(0.0, 1.0, (N, 6)) * sig * np.sqrt(1.0 - phi * phi)
        b = np.zeros((N, 6))
        b[0] = rng.normal(0.0, 1.0, 6) * sig
        for k in range(1, N):
            b[k] = phi * b[k - 1] + e[k]
        x += b
    x[:, 2] += 9.81
    np.savetxt(path, np.column_stack([t, x]), delimiter=",", header="t,ax,ay,az,gx,gy,gz", comments="", fmt="%.9f")


def main():
    args = [a for a in sys.argv[1:] if a != "--ar1"]
    ar1 = "--ar1" in sys.argv[1:]
    harness = args[0] if args else os.path.join(os.path.dirname(__file__), "..", "bin", "harness")
    truth = np.array([1e-3, 1e-3, 1e-3, 5e-4, 5e-4, 5e-4])
    sig = np.array([2e-3, 2e-3, 2e-3, 1e-3, 1e-3, 1e-3])
    tau = 0.5
    pars = [("white_density", truth)]
    if ar1:
        pars += [("ar1_sigma", sig), ("ar1_tau_s", np.full(6, tau))]
    val = {p: {ch: [] for ch in range(6)} for p, _ in pars}
    se = {p: {ch: [] for ch in range(6)} for p, _ in pars}
    nfit = None
    with tempfile.TemporaryDirectory() as tmp:
        for s in SEEDS:
            log = os.path.join(tmp, "w%d.csv" % s)
            out = os.path.join(tmp, "w%d.json" % s)
            write_log(log, s, truth, sig if ar1 else None, tau)
            subprocess.run([harness, "simgap", log, "--quiet", "--max-effects", "0", "--json", out],
                           stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, check=False)
            with open(out) as f:
                d = json.load(f)
            nfit = sum(b["samples"] for b in d["split"]["fit"])
            for ch in range(6):
                b = d["channels"][ch]["baseline"]
                if (b["ar1_sigma"] > 0.0) != ar1:
                    continue
                for p, tr in pars:
                    if b[p] is None or b[p + "_se"] is None:
                        continue
                    val[p][ch].append(b[p] / tr[ch])
                    se[p][ch].append(b[p + "_se"] / tr[ch])
    for p, _ in pars:
        dev2, dof, ses = 0.0, 0, []
        for ch in range(6):
            v = np.array(val[p][ch])
            e = np.array(se[p][ch])
            if len(v) < 3:
                print("%s %s: %d fits, too few" % (p, NAMES[ch], len(v)))
                continue
            print("%s %s: %2d fits: relative sd %.4f, mean relative se %.4f, ratio %.2f"
                  % (p, NAMES[ch], len(v), v.std(ddof=1), e.mean(), v.std(ddof=1) / e.mean()))
            dev2 += float(((v - v.mean()) ** 2).sum())
            dof += len(v) - 1
            ses += list(e)
        if dof == 0:
            continue
        sd = np.sqrt(dev2 / dof)
        ses = np.array(ses)
        # the pooled sd's chi-square interval, widened by the mean se's own
        # scatter (relative sd of the mean of the se's), in quadrature on the log
        lo_c, hi_c = np.sqrt(stats.chi2.ppf([0.025, 0.975], dof) / dof)
        rel_mse = ses.std(ddof=1) / ses.mean() / np.sqrt(len(ses))
        w = 1.96 * np.sqrt(((np.log(hi_c) - np.log(lo_c)) / (2 * 1.96)) ** 2 + rel_mse ** 2)
        print("%s pooled: relative sd %.4f (%d degrees of freedom), mean relative se %.4f, ratio %.2f; "
              "95 %% interval of the ratio if the se is right %.2f-%.2f"
              % (p, sd, dof, ses.mean(), sd / ses.mean(), np.exp(-w), np.exp(w)))
    if not ar1:
        print("Cramer-Rao bound of the white density 1/sqrt(2 x %d) = %.4f" % (nfit, 1.0 / np.sqrt(2.0 * nfit)))


if __name__ == "__main__":
    main()
