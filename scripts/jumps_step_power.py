#!/usr/bin/env python3
"""How often the simgap step detector finds a step on the fit segment, and
how often long-scale variants of it fire on effects that are not jumps
(docs/simgap.md, Validation, "jumps near the threshold").

A numpy re-implementation of find_steps (harness/hx_simgap_fit.c), run on
the fit segment's geometry of a one-hour log at 200 Hz: two blocks of
1080 s (216000 samples) each, the detector run per block, a detection when
either block holds a step. Noise: white only, density N = 1 (units / sqrt
Hz; the profiles' AR(1) is negligible against it at these scales). The
effects at m times the catalogue's detectable thresholds
(vectors/sim/detectable.csv), which are white-limited, so their ratio to N
is the same for every profile: jumps amp 0.293 N at 1 per 600 s, rrw K
8.8e-6 / 7.4e-4 N, ramp 5.6e-7 / 7.4e-4 N, flicker B 9.9e-5 / 7.4e-4 N
(12 AR(1) poles over 0.5-5000 s as the simulator's).

Detectors (columns):
  cur  find_steps as it is: two-window mean differences d at w = 64 samples
       doubling while 8 w <= n, hop w / 4, z = |d| / (1.4826 median |d|),
       threshold Q^-1(0.0025 / positions), local maxima, merged across
       scales;
  B    scales while 3 w <= n, the spread max(MAD, the shortest scale's MAD
       extrapolated as white noise, sqrt(64 / w));
  C    scales while 3 w <= n, the null spread from that white-noise
       extrapolation alone (a model-based GLR), d centred on its median (a
       ramp's constant), Bonferroni over positions and scales;
  D    C with Bonferroni over the positions only.
Prints, per effect, cases with a detection / trials (mean steps found).

Usage: /usr/bin/python3 scripts/jumps_step_power.py SEED TRIALS
"""
import math
import sys

import numpy as np
from scipy.signal import lfilter
from scipy.stats import norm

FS = 200.0
NB = 216000
N = 1.0
AMP_THR = 0.293 * N
K_THR = 8.8e-6 / 7.4e-4 * N
R_THR = 5.6e-7 / 7.4e-4 * N
B_THR = 9.9e-5 / 7.4e-4 * N
VARS = ["cur", "B", "C", "D"]


def white(rng, n):
    return rng.standard_normal(n) * N * math.sqrt(FS)


def jumps(rng, n, amp, rate=1.0 / 600.0):
    p = 1.0 - math.exp(-rate / FS)
    k = rng.random(n) < p
    s = np.zeros(n)
    s[k] = rng.standard_normal(k.sum()) * amp
    return np.cumsum(s)


def rrw(rng, n, K):
    return np.cumsum(rng.standard_normal(n)) * K / math.sqrt(FS)


def flicker(rng, n, B, lo=0.5, hi=5000.0, poles=12):
    lnr = math.log(hi / lo) / (poles - 1)
    v = B * B * lnr / math.pi
    out = np.zeros(n)
    for i in range(poles):
        c = math.exp(-1.0 / (FS * lo * math.exp(lnr * i)))
        e = rng.standard_normal(n) * math.sqrt(v * (1.0 - c * c))
        y, _ = lfilter([1.0], [1.0, -c], e, zi=[c * rng.standard_normal() * math.sqrt(v)])
        out += y
    return out


def detect(x, var):
    n = len(x)
    cs = np.concatenate(([0.0], np.cumsum(x - x[0])))
    lim = 8 if var == "cur" else 3
    ws = []
    w = 64
    while lim * w <= n:
        ws.append(w)
        w *= 2
    found = []
    ref = None
    for w in ws:
        k = np.arange(w, n - w + 1, w // 4)
        d = (cs[k + w] - cs[k]) / w - (cs[k] - cs[k - w]) / w
        nd = len(d)
        mad = 1.4826 * np.median(np.abs(d))
        if ref is None:
            ref = mad * math.sqrt(w)
        if var == "cur":
            sd, thr = mad, norm.isf(0.0025 / nd)
        elif var == "B":
            sd, thr = max(mad, ref / math.sqrt(w)), norm.isf(0.0025 / nd)
        else:
            d = d - np.median(d)
            sd = ref / math.sqrt(w)
            thr = norm.isf(0.0025 / nd / (len(ws) if var == "C" else 1))
        z = np.abs(d) / sd
        for i in np.nonzero(z >= thr)[0]:
            lo, hi = max(0, i - 4), min(nd - 1, i + 4)
            if np.abs(d[i]) < np.abs(d[lo:hi + 1]).max():
                continue
            t = k[i]
            if any(abs(p - t) < max(s, w) for p, s in found):
                continue
            found.append((t, w))
    return len(found)


def main():
    rng = np.random.default_rng(int(sys.argv[1]))
    trials = int(sys.argv[2])
    cases = [("white", lambda n: white(rng, n))]
    for m in (1, 2, 4, 8):
        cases.append(("jumps %gx" % m, lambda n, m=m: white(rng, n) + jumps(rng, n, m * AMP_THR)))
    for m in (1, 3, 10):
        cases.append(("rrw %gx" % m, lambda n, m=m: white(rng, n) + rrw(rng, n, m * K_THR)))
    for m in (1, 3, 10):
        cases.append(("ramp %gx" % m, lambda n, m=m: white(rng, n) + m * R_THR * np.arange(n) / FS))
    for m in (1, 3, 10):
        cases.append(("flicker %gx" % m, lambda n, m=m: white(rng, n) + flicker(rng, n, m * B_THR)))
    for name, gen in cases:
        hit = {v: 0 for v in VARS}
        cnt = {v: 0 for v in VARS}
        for _ in range(trials):
            xs = [gen(NB), gen(NB)]
            for v in VARS:
                c = detect(xs[0], v) + detect(xs[1], v)
                hit[v] += c > 0
                cnt[v] += c
        print("%-12s" % name, "  ".join("%s %2d/%d (%.1f)" % (v, hit[v], trials, cnt[v] / trials) for v in VARS),
              flush=True)


if __name__ == "__main__":
    main()
