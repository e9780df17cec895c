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
+-2 g and +-250 deg/s, made as that test makes it). Only blocks at rest
give the noise (standard deviation at most REST_SD, HX_SAT_REST_SD_*):
--rest prints each log's smallest block standard deviation, at most
0.063 m/s^2 and 0.0103 rad/s over the shared walks

    /usr/bin/python3 scripts/sat_span_noise.py --rest ../shared/data/xio_ngimu_gait/*.csv \
        ../shared/data/openshoe_c_820hz/OpenShoeDataSet.txt ../shared/data/openshoe_square2/square2_u.csv \
        ../shared/data/openshoe_gx2/*_data_inert.txt ../shared/data/pyshoe_vicon_llio/*/*_imu.csv \
        ../shared/data/ipol_gait_xsens/1-*_lf.txt ../shared/data/ipol_gait_xsens/2-*_lf.txt

and at least 0.21 m/s^2 and 0.062 rad/s per channel (the smallest of the
six) on vectors/walk.bin's moving part at 100 Hz (`bin/harness convert
vectors/walk.bin w.csv`, rows 5775 to 13429, every 4th), which has no
block at rest.
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


REST_SD = (0.12, 0.025)  # HX_SAT_REST_SD_ACCEL (m/s^2), HX_SAT_REST_SD_GYRO (rad/s)


def block_sds(v):
    n = len(v) // BLOCK
    return [np.std(v[i * BLOCK:(i + 1) * BLOCK]) for i in range(n)] if n else [np.std(v)]


def noise(v, c):
    rest = [sd for sd in block_sds(v) if sd <= REST_SD[c // 3]]
    if not rest:
        return 0.0  # no block at rest: the flat tops alone
    d = np.abs(np.diff(v))
    step = d[d > 0].min() if (d > 0).any() else 0.0
    return max(min(rest), step)


def ratio(v, c):
    nz = noise(v, c)
    return (v.max() - v.min()) / nz if nz > 0 else float("inf")


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--harness", default="bin/harness")
    ap.add_argument("--windows", action="store_true")
    ap.add_argument("--rest", action="store_true",
                    help="per log, the smallest block standard deviation of each channel (a block at rest's) "
                         "and the largest of them per sensor, against HX_SAT_REST_SD_*")
    ap.add_argument("logs", nargs="+")
    a = ap.parse_args()
    for path in a.logs:
        t, x = load(a.harness, path)
        if a.rest:
            m = [min(block_sds(x[:, c])) for c in range(6)]
            print(path, "smallest block sd: accel %.4f m/s^2 (ceiling %.3g), gyro %.5f rad/s (ceiling %.3g)"
                  % (max(m[:3]), REST_SD[0], max(m[3:]), REST_SD[1]))
            continue
        if not a.windows:
            print(path, " ".join("%s %.1f" % ("flat" if flat_tops(x[:, c]) else "-", ratio(x[:, c], c)) for c in range(6)))
            continue
        w = int(round(1.0 / np.median(np.diff(t))))
        r = [ratio(x[s:s + w, c], c) for s in range(0, len(t) - w, w // 2) for c in range(6) if flat_tops(x[s:s + w, c])]
        print(path, len(r), "windows with flat tops; largest span/noise %.1f" % max(r) if r else "")


if __name__ == "__main__":
    main()
