#!/usr/bin/python3
"""The spread of `harness info`'s stillest second, recomputed from the samples.

For each log: `bin/harness convert LOG -` gives the samples (CSV, SI) and
`bin/harness info LOG` the rate its search uses; the stillest one-second
window (rate samples, half-window steps, least mean |w|^2 plus the
accelerometer's summed per-axis variance: cmd_info.c's analyse) is found
again and its spread printed: the root of the summed per-axis variances of
f over its mean |f|, which info compares with INFO_STILL_SPREAD (0.1).
The figures of docs/harness.md, "info" (the rest rule), come from

    /usr/bin/python3 scripts/info_still_spread.py --data ../shared/data $(cat /tmp/logs.txt)

(the largest spread over the shared logs) and from the simulated walks
without a rest (`bin/harness sim --motion walk:20 --out x.bin`, then this
script on x.bin). Files that do not read as a log are skipped.
"""
import argparse
import io
import os
import re
import subprocess
import sys

import numpy as np


def spread(harness, path):
    info = subprocess.run([harness, "info", path], capture_output=True, text=True)
    m = re.search(r"^rate +([0-9.]+) Hz", info.stdout, re.M)
    if info.returncode != 0 or m is None:
        return None
    conv = subprocess.run([harness, "convert", path, "-"], capture_output=True, text=True)
    if conv.returncode != 0:
        return None
    d = np.loadtxt(io.StringIO(conv.stdout), delimiter=",", skiprows=1, usecols=range(7), ndmin=2)
    a, g = d[:, 1:4], d[:, 4:7]
    n = len(d)
    w = min(max(int(float(m.group(1))), 2), n)
    best, cost_best = 0, np.inf
    step = max(w // 2, 1)
    for s in range(0, n - w + 1, step):
        aw, gw = a[s:s + w], g[s:s + w]
        cost = np.sum(gw * gw) / w + (np.sum(aw * aw) - np.sum(np.sum(aw, axis=0) ** 2) / w) / w
        if cost < cost_best:
            best, cost_best = s, cost
    aw = a[best:best + w]
    mean = aw.mean(axis=0)
    return np.sqrt(np.sum(((aw - mean) ** 2).mean(axis=0))) / np.linalg.norm(mean)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("logs", nargs="+")
    ap.add_argument("--data", default="", help="directory the log paths are relative to")
    ap.add_argument("--harness", default=os.path.abspath("bin/harness"))
    args = ap.parse_args()
    worst = None
    for p in args.logs:
        path = os.path.join(args.data, p) if args.data else p
        r = spread(args.harness, path)
        if r is None:
            continue
        print("%-72s %.4f" % (p, r))
        if worst is None or r > worst[1]:
            worst = (p, r)
    if worst is not None:
        print("largest: %.4f (%s)" % (worst[1], worst[0]))
    return 0


if __name__ == "__main__":
    sys.exit(main())
