#!/usr/bin/python3
"""EDF of the streaming estimator's cascade points (tau > 255 samples) for
white FM: a Monte Carlo of the same terms against the harness's edf column.

The cascade serves tau = m 2^j from phase values 2^j samples apart with lag
m = 5..8 (docs/allan.md, "Cascade beyond"); its EDF is Greenhall & Riley's
at that lag with F = m (docs/allan.md, "Confidence intervals"), which for
white FM is below the simulated one at every cascade level: the intervals
are conservative there.

  /usr/bin/python3 scripts/edf_streaming_mc.py [--harness bin/harness] [--records 3000]
"""
import argparse
import csv
import os
import subprocess
import tempfile

import numpy as np

ap = argparse.ArgumentParser()
ap.add_argument("--harness", default="bin/harness")
ap.add_argument("--records", type=int, default=3000)
a = ap.parse_args()
rng = np.random.default_rng(11)
N, R = 65536, a.records
taus = [(256, 5, 8), (384, 6, 6), (1024, 7, 8), (2048, 8, 8), (3072, 9, 6)]  # tau, level j, lag m
vals = {t: [] for t, _, _ in taus}
for r in range(R):
    x = np.concatenate([[0], np.cumsum(rng.standard_normal(N))])
    for tau, lev, m in taus:
        xs = x[::1 << lev]
        d = xs[2 * m:] - 2 * xs[m:-m] + xs[:-2 * m]
        vals[tau].append(np.mean(d * d) / (2 * tau * tau))
with tempfile.TemporaryDirectory() as td:
    series, out = os.path.join(td, "w.txt"), os.path.join(td, "w.csv")
    np.savetxt(series, rng.standard_normal(N))
    subprocess.run([a.harness, "allan", "--series", series, "--rate", "1", "--estimator", "streaming",
                    "--per-octave", "2", "--no-sim", "--quiet", "--out", out], check=True, capture_output=True)
    ed = {int(r["m"]): float(r["edf"]) for r in csv.DictReader(l for l in open(out) if not l.startswith("#"))}
for tau, lev, m in taus:
    v = np.array(vals[tau])
    e = 2 * v.mean() ** 2 / v.var()
    print("tau %5d level %d lag %d: MC EDF %.1f +- %.1f, harness EDF %.1f (%+.0f %%)"
          % (tau, lev, m, e, e * np.sqrt(2.0 / R), ed[tau], 100 * (ed[tau] / e - 1)))
