#!/usr/bin/python3
"""Compare `harness allan --out` tables with a Stable32 result file.

Stable32 writes one table per statistic ("# Sigma Type: Overlapping Allan"
or "Allan", the non-overlapping one, "Modified Allan", "Time", "Hadamard",
"Overlapping Hadamard", "Total"): averaging factor, tau, term count, alpha,
min sigma, sigma, max sigma. This script reads such a file, takes the column
of the harness CSV that matches its sigma type (oadev or adev, with their
interval and term counts; the others from `--deviation`: mdev, tdev, hdev,
ohdev, totdev), and prints, over the averaging factors both have:
- the largest relative difference of the deviation, and where;
- how many term counts differ;
- where the noise exponent alpha differs (Stable32's against the harness's
  `alpha` column), and, where it agrees and Stable32 printed limits, the
  largest relative difference of the interval limits.

Usage: /usr/bin/python3 scripts/stable32_check.py TABLE.csv [TABLE2.csv ...] STABLE32.txt
       [--channel NAME] [--tol REL] [--ci-tol REL]
Several tables are read as one (e.g. two `--m` runs of at most 160 tau).
Exit status 1 when the deviation or a term count is off by more than --tol
(default 1e-4, what Stable32's 5 printed digits allow), or a limit with the
same alpha by more than --ci-tol (default 5e-4: above 100 degrees of freedom
Stable32's limits are those of confidence 0.68, up to 4.2e-4 from the
harness's one-sigma ones; docs/allan.md, "Confidence intervals").

Example (the run quoted in docs/allan.md, allantools' tests/ocxo files):
  bin/harness allan --series ocxo_frequency.txt --rate 1 --fractional 1e7 --no-sim --quiet --out t.csv
  /usr/bin/python3 scripts/stable32_check.py t.csv stable32_oadev_alltau.txt
"""
import argparse
import sys


def read_stable32(path):
    kind, rows = None, {}
    with open(path) as f:
        for line in f:
            if line.startswith("#"):
                if "Sigma Type:" in line:
                    kind = line.split("Sigma Type:")[1].strip()
                continue
            c = line.split()
            if len(c) < 7:
                continue
            rows[int(c[0])] = dict(n=int(c[2]), alpha=int(c[3]), lo=float(c[4]), dev=float(c[5]), hi=float(c[6]))
    return kind, rows


def read_harness(path, channel):
    rows, head = {}, None
    with open(path) as f:
        for line in f:
            if line.startswith("#"):
                continue
            c = line.strip().split(",")
            if head is None:
                head = c
                continue
            r = dict(zip(head, c))
            if channel is None or r["channel"] == channel:
                rows[int(r["m"])] = r
    return rows


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("table", nargs="+")
    ap.add_argument("stable32")
    ap.add_argument("--channel", default=None, help="channel of the harness table (default: all rows)")
    ap.add_argument("--tol", type=float, default=1e-4)
    ap.add_argument("--ci-tol", type=float, default=5e-4)
    a = ap.parse_args()
    kind, ref = read_stable32(a.stable32)
    if kind is None or not ref:
        sys.exit("%s: no Stable32 sigma type or table found" % a.stable32)
    other = {"Modified Allan": "mdev", "Time": "tdev", "Hadamard": "hdev", "Overlapping Hadamard": "ohdev",
             "Total": "totdev"}
    if kind.startswith("Overlapping Allan"):
        dev, lo, hi, terms = "oadev", "oadev_lo", "oadev_hi", "terms"
    elif kind == "Allan" or kind.startswith("Normal Allan"):
        dev, lo, hi, terms = "adev", "adev_lo", "adev_hi", "terms_n"
    elif kind in other:
        d = other[kind]
        dev, lo, hi, terms = d, d + "_lo", d + "_hi", d + "_terms"
    else:
        sys.exit("%s: sigma type '%s' is not one harness allan computes" % (a.stable32, kind))
    got = {}
    for t in a.table:
        got.update(read_harness(t, a.channel))
    if got and dev not in next(iter(got.values())):
        sys.exit("%s: no '%s' column (run harness allan with --deviation %s)" % (" ".join(a.table), dev, dev))
    got = {m: g for m, g in got.items() if g[dev] not in ("", "null") and int(g[terms]) > 0}
    common = sorted(m for m in ref if m in got)
    if not common:
        sys.exit("no averaging factor in common")
    worst, worst_m, nbad, ci_worst, ci_m, alpha_diff = 0.0, None, 0, 0.0, None, []
    for m in common:
        r, g = ref[m], got[m]
        e = abs(float(g[dev]) / r["dev"] - 1.0)
        if e > worst:
            worst, worst_m = e, m
        if int(g[terms]) != r["n"]:
            nbad += 1
        if int(g["alpha"]) != r["alpha"]:
            alpha_diff.append((m, r["alpha"], int(g["alpha"])))
        elif r["lo"] > 0.0 and g[lo] != "null":
            # the limits relative to each one's own deviation (a difference in the deviation is counted above)
            for s32, ours in ((r["lo"], float(g[lo])), (r["hi"], float(g[hi]))):
                ce = abs((ours / float(g[dev])) / (s32 / r["dev"]) - 1.0)
                if ce > ci_worst:
                    ci_worst, ci_m = ce, m
    print("%s (%s): %d of %d averaging factors in common" % (a.stable32, kind, len(common), len(ref)))
    print("  deviation: largest relative difference %.2e (m = %s); term counts differing: %d" % (worst, worst_m, nbad))
    print("  alpha differs at %d: %s" % (len(alpha_diff), ", ".join("m %d: %d vs %d" % t for t in alpha_diff) or "-"))
    if ci_m is not None:
        print("  limits (same alpha): largest relative difference %.2e (m = %d)" % (ci_worst, ci_m))
    ok = worst <= a.tol and nbad == 0 and ci_worst <= a.ci_tol
    print("  %s" % ("ok" if ok else "DIFFERS"))
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
