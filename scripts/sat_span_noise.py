#!/usr/bin/python3
"""The span-to-noise ratio behind hx_sat_t's clipping rule (HX_SAT_SPAN_NOISE).

For each log, `bin/harness convert LOG -` gives the samples (CSV, SI; read
as float32, as replay reads them; a repeated stamp skipped, as hx_sat_push
skips it). Each channel's span (maximum less minimum) is divided by its
noise at rest as hx_sat_t estimates it: the smallest standard deviation of
a block of 64 samples (of all of them when there are fewer), at least the
smallest non-zero change between consecutive samples. Printed: with
--windows, the ratio of every one-second window (half-window steps) where
the flat-top rule alone (two runs of two or more samples at the extremes)
fires; without, each whole log's six ratios and whether that rule fires.
The figures of harness/hx_nav.h and docs/harness.md ("info", saturation)
come from

    /usr/bin/python3 scripts/sat_span_noise.py --windows \\
        ../shared/data/xio_ngimu_gait/*.csv ../shared/data/openshoe_c_820hz/OpenShoeDataSet.txt

(the largest ratio of a window where the flat tops alone fire: a still
stretch's, or a slow swing's at 820 Hz), and without --windows on
tests/cli/test_replay.sh's clipped walk (vectors/walk.bin clipped at
+-2 g and +-250 deg/s, made as that test makes it).
"""
import argparse
import io
import subprocess

import numpy as np

BLOCK = 64


def load(harness, path):
    out = subprocess.run([harness, "convert", path, "-"], capture_output=True, check=True).stdout
    a = np.loadtxt(io.BytesIO(out), delimiter=",", skiprows=1, ndmin=2)
    keep = np.concatenate(([True], np.diff(a[:, 0]) != 0))
    return a[keep, 0], a[keep, 1:7].astype(np.float32).astype(np.float64)


def flat_tops(v):
    runs = 0
    for m in (v.max(), v.min()):
        run = 0
        for x in v:
            run = run + 1 if x == m else 0
            runs += run == 2
    return v.max() != v.min() and runs >= 2


def noise(v):
    n = len(v) // BLOCK
    sd = min(np.std(v[i * BLOCK:(i + 1) * BLOCK]) for i in range(n)) if n else np.std(v)
    d = np.abs(np.diff(v))
    step = d[d > 0].min() if (d > 0).any() else 0.0
    return max(sd, step)


def ratio(v):
    nz = noise(v)
    return (v.max() - v.min()) / nz if nz > 0 else float("inf")


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--harness", default="bin/harness")
    ap.add_argument("--windows", action="store_true")
    ap.add_argument("logs", nargs="+")
    a = ap.parse_args()
    for path in a.logs:
        t, x = load(a.harness, path)
        if not a.windows:
            print(path, " ".join("%s %.1f" % ("flat" if flat_tops(x[:, c]) else "-", ratio(x[:, c])) for c in range(6)))
            continue
        w = int(round(1.0 / np.median(np.diff(t))))
        r = [ratio(x[s:s + w, c]) for s in range(0, len(t) - w, w // 2) for c in range(6) if flat_tops(x[s:s + w, c])]
        print(path, len(r), "windows with flat tops; largest span/noise %.1f" % max(r) if r else "")


if __name__ == "__main__":
    main()
