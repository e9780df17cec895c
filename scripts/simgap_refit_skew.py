#!/usr/bin/python3
"""How skewed simgap's twins' refits of the baseline parameters are (the
white density, the AR(1) sigma and T): the evidence behind the refits' 68 %
interval beside the se (docs/simgap.md, section 3, the paragraph on ci68).

Writes the AR(1) logs of scripts/simgap_se_check.py --ar1 (300 s at 100 Hz,
numpy seeds 1-NLOGS; white 1e-3 / 5e-4, AR(1) sigma 2e-3 / 1e-3, T 0.5 s or
$TAU s), runs `HARNESS simgap LOG --max-effects 0 --seeds S` on each and
reads every refit's value from stderr. The JSON does not give the refits
themselves, so HARNESS must be a build with this throwaway print at the end
of sg_se_from_refits' loop over a parameter, after `e->se[k] = ...`
(harness/hx_simgap_fit.c; `#include <stdio.h>`), not committed:

    if (getenv("SG_DEBUG_REFITS") != NULL) {
        fprintf(stderr, "REFIT %d %d %.9g", e->id, k, e->p[k]);
        for (s = 0; s < S; s++) {
            if (refit_value(fits, ok, s, e->id, k, mp, &v)) {
                fprintf(stderr, " %.9g", v);
            }
        }
        fprintf(stderr, "\n");
    }

Prints, per parameter over the sets of refits (one per channel and log):
the median's and the 16th / 84th percentiles' distance from the mean in
sd, the upper over the lower half-width about the median, the skewness
(per set, and of ln value), and the fitted values' own spread over the
logs relative to the truth (--max-effects 0: one set per channel, ax..gz).

Usage: /usr/bin/python3 scripts/simgap_refit_skew.py HARNESS [--seeds S] [NLOGS]
       (defaults S 16, NLOGS 16; TAU=5 in the environment for T = 5 s)
"""
import os
import subprocess
import sys
import tempfile

import numpy as np
from scipy import stats

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from simgap_se_check import FS, N, write_log  # noqa: E402  (the same logs)

harness = sys.argv[1]
S = int(sys.argv[sys.argv.index("--seeds") + 1]) if "--seeds" in sys.argv else 16
nseeds = int(sys.argv[-1]) if len(sys.argv) > 2 and sys.argv[-1].isdigit() and sys.argv[-2] != "--seeds" else 16
truth = np.array([1e-3, 1e-3, 1e-3, 5e-4, 5e-4, 5e-4])
sig = np.array([2e-3, 2e-3, 2e-3, 1e-3, 1e-3, 1e-3])
tau = float(os.environ.get("TAU", "0.5"))
sets = {(0, 0): [], (1, 0): [], (1, 1): []}
fitted = {(0, 0): [], (1, 0): [], (1, 1): []}
with tempfile.TemporaryDirectory() as tmp:
    for s in range(1, nseeds + 1):
        log = os.path.join(tmp, "w%d.csv" % s)
        write_log(log, s, truth, sig, tau)
        r = subprocess.run([harness, "simgap", log, "--quiet", "--max-effects", "0", "--seeds", str(S)],
                           stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True,
                           env=dict(os.environ, SG_DEBUG_REFITS="1"))
        for line in r.stderr.splitlines():
            if line.startswith("REFIT "):
                f = line.split()
                key = (int(f[1]), int(f[2]))
                if key in sets:
                    fitted[key].append(float(f[3]))
                    sets[key].append(np.array([float(v) for v in f[4:]]))
names = {(0, 0): "white density", (1, 0): "AR(1) T", (1, 1): "AR(1) sigma"}
print("S = %d twins per log, %d logs x 6 channels" % (S, nseeds))
for key, name in names.items():
    L = [v for v in sets[key] if len(v) >= 3]
    if not L:
        continue
    md = np.array([(np.median(v) - v.mean()) / v.std(ddof=1) for v in L])
    lo = np.array([(v.mean() - np.percentile(v, 16)) / v.std(ddof=1) for v in L])
    hi = np.array([(np.percentile(v, 84) - v.mean()) / v.std(ddof=1) for v in L])
    sk = np.array([stats.skew(v) for v in L])
    rel = np.array([v.std(ddof=1) / v.mean() for v in L])
    # all refits pooled, each standardised by its own set's mean and sd
    z = np.concatenate([(v - v.mean()) / v.std(ddof=1) for v in L])
    print("%s: %d refit sets of %d-%d refits; relative sd (mean) %.3f" % (name, len(L), min(map(len, L)),
          max(map(len, L)), rel.mean()))
    print("  (median - mean)/sd: mean %+.3f, median below mean in %d of %d sets" % (md.mean(), (md < 0).sum(), len(L)))
    print("  (mean - p16)/sd mean %.3f, (p84 - mean)/sd mean %.3f (1 and 1 if symmetric normal)"
          % (lo.mean(), hi.mean()))
    asy = np.array([(np.percentile(v, 84) - np.median(v)) / (np.median(v) - np.percentile(v, 16)) for v in L
                    if np.median(v) > np.percentile(v, 16)])
    print("  (p84 - median)/(median - p16): median over sets %.3f, geometric mean %.3f" % (np.median(asy),
          np.exp(np.log(asy[asy > 0]).mean())))
    print("  sample skewness per set: mean %+.3f (sd of the mean %.3f); pooled standardised refits skew %+.3f" %
          (sk.mean(), sk.std(ddof=1) / np.sqrt(len(sk)), stats.skew(z)))
    lz = np.concatenate([(np.log(v) - np.log(v).mean()) / np.log(v).std(ddof=1) for v in L if (v > 0).all()])
    print("  the same on ln(value): pooled skew %+.3f" % stats.skew(lz))
    tr = {(0, 0): truth, (1, 0): np.full(6, tau), (1, 1): sig}[key]
    fv = np.array(fitted[key]) / np.resize(tr, len(fitted[key]))  # one set per channel, ax..gz, per log
    print("  fitted values / truth over the logs and channels (the estimator's own spread): "
          "mean %.4g median %.4g p16 %.4g p84 %.4g "
          "sd %.4g skew %+.3f" % (fv.mean(), np.median(fv), np.percentile(fv, 16), np.percentile(fv, 84),
                                   fv.std(ddof=1), stats.skew(fv)))
