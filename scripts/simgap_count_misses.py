#!/usr/bin/env python3
"""Are the simgap validation's dropout and duplicate parameter misses chance?

docs/simgap.md, "Validation" (the misses of the run of 2026-12-02). The
withheld effect's parameter is a probability per sample tick, p = m * 10 / n
(m the multiple of the threshold, n = duration x rate ticks: 10 expected
events at 1x, harness/hx_simgap_valid.c draw_static). The diagnosis
estimates it from the fit segment alone (the first and last 30 % of the
log, harness/hx_simgap.c sg_timing_analyse): duplicated intervals / fit
intervals, or dropped ticks / (fit intervals + dropped ticks). Its error is
then that of a Poisson count of mean lam = p x 0.6 n, relative sd
1 / sqrt(lam), not the whole log's 1 / sqrt(p n).

Usage:
  /usr/bin/python3 scripts/simgap_count_misses.py
      the committed run's two count misses (figures below, from
      `simgap-validate ... --only 9 --verbose` and `--only 25 --verbose`)
  /usr/bin/python3 scripts/simgap_count_misses.py OUT JSON [OUT JSON ...]
      every dropout / duplicate case of `simgap-validate --verbose` runs
      (OUT its standard output, JSON its --json file): per case the signed
      relative error, the fit count's z against its Poisson mean, then the
      pooled figures (a bias shows as a mean error away from 0 by more
      than its standard error, and as a pooled count off its mean); for
      `jumps` cases, each channel's fitted rate and rms step (the verdict's,
      3 digits) against the truth's amplitude, signed.
Run with Debian's /usr/bin/python3 (scipy).
"""
import json
import math
import re
import sys

from math import lgamma

from scipy.stats import binom, chi2, poisson

FIT = 0.6       # the fit segment's share of the log (simgap's --fit-frac)
TICKS = 720000  # 3600 s at 200 Hz


def tails(lam, n):
    """P(|N - lam| >= |n - lam|) for N ~ Poisson(lam), and each side."""
    d = abs(n - lam)
    lo = poisson.cdf(math.floor(lam - d + 1e-9), lam)
    hi = poisson.sf(math.ceil(lam + d - 1e-9) - 1, lam)
    return lo + hi, lo, hi


def within(lam, tol=0.25):
    """P(|N / lam - 1| <= tol) for N ~ Poisson(lam)."""
    lo = math.ceil(lam * (1.0 - tol) - 1e-9)
    hi = math.floor(lam * (1.0 + tol) + 1e-9)
    return poisson.cdf(hi, lam) - poisson.cdf(lo - 1, lam)


def limit():
    """The ideal count estimator's share within 25 %, m log-uniform on [1, 10]."""
    us = [(i + 0.5) / 2000.0 for i in range(2000)]
    for share, what in ((FIT, "the fit segment (the diagnosis)"), (1.0, "the whole log")):
        v = sum(within(share * 10.0 * 10.0 ** u) for u in us) / len(us)
        print("a count on %s is within 25 %% of p in %.1f %% of cases drawn at 1-10x" % (what, 100.0 * v))
    print("  at 1x, 1.37x, 2x, 3x, 5x, 7.89x, 10x on the fit segment: %s"
          % ", ".join("%.2f" % within(FIT * 10.0 * m) for m in (1.0, 1.37, 2.0, 3.0, 5.0, 7.89, 10.0)))


def committed():
    # (name, multiple, fit count, whole-log count): the multiple from the
    # --only runs' JSON, the counts from their --verbose summary ("timing: 64
    # duplicated"; the fit count is the fitted prob x the fit intervals, e.g.
    # 7.41e-5 x the some 432,000 fit intervals = 32.0)
    for name, mult, n_f, full in (("duplicate case 9", 7.8925, 32, 64), ("dropout case 25", 1.3676, 6, 8)):
        lam_t = mult * 10.0
        lam_f = FIT * lam_t
        both, lo, hi = tails(lam_f, n_f)
        print("%s: expected %.1f events in the log, %.1f in the fit segment (relative sd %.3f);"
              % (name, lam_t, lam_f, 1.0 / math.sqrt(lam_f)))
        print("  fit count %d: error %+.3f = %+.2f sd; P(a count as far from the mean) = %.3f (low %.3f, high %.3f)"
              % (n_f, n_f / lam_f - 1.0, (n_f - lam_f) / math.sqrt(lam_f), both, lo, hi))
        print("  whole log %d of %.1f: %+.2f sd, P(N <= %d) = %.3f; held out %d of %.1f"
              % (full, lam_t, (full - lam_t) / math.sqrt(lam_t), full, poisson.cdf(full, lam_t),
                 full - n_f, lam_t - lam_f))


def batch(pairs):
    rows = []
    jerr = []
    for out, js in pairs:
        with open(js) as f:
            res = json.load(f)["results"]
        text = open(out).read()
        # each case's block ends with its "case K ..." line
        blocks = re.split(r"^case +\d+ .*$", text, flags=re.M)
        for r, blk in zip(res, blocks):
            if r["truth"] == "jumps" and r["answer"] == "jumps":
                v = re.search(r"^verdict: .*$", blk, re.M).group(0)
                for m in re.finditer(r"jumps \(([0-9.e+-]+) per hour, rms step ([0-9.e+-]+) [^)]*(?:\([^)]*\))?\) "
                                     r"on (\w+)", v):
                    ch = m.group(3)
                    if ch in r["channels"]:
                        amp = r["values"][r["channels"].index(ch)]
                        jerr.append(float(m.group(2)) / amp - 1.0)
                        print("jumps case %d (x%.2f) %s: %s per hour, amplitude error %+.3f"
                              % (r["case"], r["multiple_of_threshold"], ch, m.group(1), jerr[-1]))
            if r["truth"] not in ("dropout", "duplicate") or r["param_rel_error"] is None:
                continue
            p = r["values"][0]
            m = re.search(r"^timing: (\d+) duplicated, (\d+) dropped", blk, re.M)
            full = int(m.group(1) if r["truth"] == "duplicate" else m.group(2))
            m = re.search(r"%s \(prob ([0-9.e+-]+)\)" % r["truth"], blk)
            sign = 1.0 if float(m.group(1)) > p else -1.0
            err = sign * r["param_rel_error"]
            lam_f = p * FIT * TICKS
            rows.append((r["truth"], r["case"], r["multiple_of_threshold"], err, lam_f,
                         lam_f * (1.0 + err), full, p * TICKS))
    if len(jerr) > 1:
        n = len(jerr)
        mean = sum(jerr) / n
        sd = math.sqrt(sum((e - mean) ** 2 for e in jerr) / (n - 1))
        low = sum(1 for e in jerr if e < 0.0)
        # an estimator that saw every step (scripts/jumps_amp_limit.py), n ~
        # Poisson(3.6) given one: amp_hat / amp = sqrt(chi2_n / n)
        lam = 3.6
        w = [poisson.pmf(k, lam) for k in range(1, 60)]
        z = sum(w)
        p_low = sum(wk * chi2.cdf(k, k) for wk, k in zip(w, range(1, 60))) / z
        mi = [math.sqrt(2.0 / k) * math.exp(lgamma((k + 1) / 2.0) - lgamma(k / 2.0)) - 1.0 for k in range(1, 60)]
        m_id = sum(wk * x for wk, x in zip(w, mi)) / z
        sd_id = math.sqrt(sum(wk * (1.0 - (x + 1.0) ** 2 + x * x) for wk, x in zip(w, mi)) / z - m_id * m_id)
        print("jumps: %d channels, amplitude error mean %+.3f (standard error %.3f), sd %.3f; %d low; within 25 %%: %d"
              % (n, mean, sd / math.sqrt(n), sd, low, sum(1 for e in jerr if abs(e) <= 0.25)))
        print("  the ideal estimator: mean %+.3f, sd %.3f (standard error of a mean of %d: %.3f); low with "
              "probability %.3f, so %d or more low of %d: %.3f"
              % (m_id, sd_id, n, sd_id / math.sqrt(n), p_low, low, n, binom.sf(low - 1, n, p_low)))
    for eff in ("duplicate", "dropout"):
        rs = [x for x in rows if x[0] == eff]
        if not rs:
            continue
        print("%s: %d cases" % (eff, len(rs)))
        print("  case  x thr   error  fit count / mean   z   whole log / mean")
        for _, k, mult, err, lam, n, full, lam_t in rs:
            print("  %4d  %5.2f  %+.3f  %6.1f / %6.1f  %+5.2f  %4d / %6.1f"
                  % (k, mult, err, n, lam, (n - lam) / math.sqrt(lam), full, lam_t))
        errs = [x[3] for x in rs]
        mean = sum(errs) / len(errs)
        sd = math.sqrt(sum((e - mean) ** 2 for e in errs) / (len(errs) - 1)) if len(errs) > 1 else float("nan")
        pred = math.sqrt(sum(1.0 / x[4] for x in rs) / len(rs))
        nf, lf = sum(x[5] for x in rs), sum(x[4] for x in rs)
        nt, lt = sum(x[6] for x in rs), sum(x[7] for x in rs)
        zs = [(x[5] - x[4]) / math.sqrt(x[4]) for x in rs]
        print("  mean error %+.3f (standard error %.3f), sd %.3f against the Poisson's rms 1/sqrt(lam) %.3f;"
              % (mean, sd / math.sqrt(len(errs)), sd, pred))
        print("  z: mean %+.2f, sd %.2f; pooled fit count %.0f of %.1f (%+.2f sd); whole log %d of %.1f (%+.2f sd);"
              % (sum(zs) / len(zs), math.sqrt(sum(z * z for z in zs) / len(zs) - (sum(zs) / len(zs)) ** 2),
                 nf, lf, (nf - lf) / math.sqrt(lf), nt, lt, (nt - lt) / math.sqrt(lt)))
        print("  within 25 %%: %d of %d" % (sum(1 for e in errs if abs(e) <= 0.25), len(errs)))


def main():
    if len(sys.argv) == 1:
        committed()
        limit()
    elif len(sys.argv) % 2 == 1:
        batch(list(zip(sys.argv[1::2], sys.argv[2::2])))
    else:
        sys.exit("usage: simgap_count_misses.py [OUT JSON ...]")


if __name__ == "__main__":
    main()
