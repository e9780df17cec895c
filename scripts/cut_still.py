#!/usr/bin/python3
"""Logs that start just before the walk: the shared closed-loop walks with
their still start cut to KEEP seconds before the first motion, replayed.

A recording started a moment before the first step gives the alignment a
still period of a fraction of a second, whose mean rate holds the foot's
rotation before the step as well as the gyro bias (docs/navigation.md,
"Short start"). This cuts each walk's start so that KEEP s remain before
the first sample whose gyro exceeds 0.15 rad/s, replays the cut log with
each harness given, and prints the 3-D return-to-start error, the heading
change and the alignment period.

  /usr/bin/python3 scripts/cut_still.py [HARNESS ...]   (default bin/harness)

Two harness binaries (an old build and this one) print their columns side
by side, then how many cut logs the last one changes, how many it makes
worse, and the median 3-D closure of the changed ones before and after.
About 12 s per harness. Needs the shared data
($FNAV_DATA_DIR, ../shared/data or /work/shared/data).
"""
import json
import os
import subprocess
import sys
import tempfile

import re
import statistics

import numpy as np

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), ".."))
WALKS = [
    "openshoe_gx2/Measurement_100521_2_data_inert.txt",
    "openshoe_gx2/Measurement_100521_3_data_inert.txt",
    "openshoe_gx2/Measurement_100521_30_data_inert.txt",
    "openshoe_gx2/Measurement_100521_31_data_inert.txt",
    "openshoe_gx2/Measurement_100521_32_data_inert.txt",
    "openshoe_gx2/Measurement_100521_33_data_inert.txt",
    "xio_ngimu_gait/short_walk.csv",
    "xio_ngimu_gait/long_walk.csv",
    "openshoe_c_820hz/OpenShoeDataSet.txt",
    "openshoe_square2/square2_u.csv",
]
KEEP = (None, 0.0, 0.2, 0.35, 0.5, 0.8)  # None: the walk as recorded


def data_dir():
    for d in (os.environ.get("FNAV_DATA_DIR", ""), os.path.join(ROOT, "..", "shared", "data"), "/work/shared/data"):
        if d and os.path.isfile(os.path.join(d, "MANIFEST.md")):
            return d
    sys.exit("cut_still.py: no shared data directory (set FNAV_DATA_DIR)")


def replay(h, path):
    r = subprocess.run([h, "replay", path, "--quiet", "--json", "-"], capture_output=True, text=True)
    try:
        j = json.loads(r.stdout)
    except ValueError:
        return "none"
    if not j.get("aligned"):
        return "not aligned"
    return "%6.3f m %+7.1f deg @%.2f s" % (j["return_error_3d_m"], j["heading_change_deg"], j["aligned_at_s"])


def main():
    hs = sys.argv[1:] or [os.path.join(ROOT, "bin", "harness")]
    d = data_dir()
    pairs = []
    with tempfile.TemporaryDirectory() as tmp:
        print("%-40s %5s  %s" % ("walk", "keep", "  |  ".join(hs)))
        for w in WALKS:
            conv = os.path.join(tmp, "w.csv")
            subprocess.run([hs[-1], "convert", os.path.join(d, w), conv], check=True, capture_output=True)
            a = np.loadtxt(conv, delimiter=",", skiprows=1)
            t = a[:, 0]
            ie = int(np.argmax(np.linalg.norm(a[:, 4:7], axis=1) > 0.15))
            for keep in KEEP:
                p = conv
                if keep is not None:
                    i0 = int(np.searchsorted(t, t[ie] - keep))
                    cut = a[i0:].copy()
                    cut[:, 0] -= cut[0, 0]
                    p = os.path.join(tmp, "cut.csv")
                    np.savetxt(p, cut, delimiter=",", fmt="%.9g", header="t,ax,ay,az,gx,gy,gz", comments="")
                res = [replay(h, p) for h in hs]
                print("%-40s %5s  %s" % (w[-40:], "orig" if keep is None else "%.2f" % keep, "  |  ".join(res)),
                      flush=True)
                m = [re.match(r"\s*([0-9.]+) m", x) for x in res]
                if keep is not None and len(hs) == 2 and all(m):
                    pairs.append((float(m[0].group(1)), float(m[1].group(1))))
    ch = [(a, b) for a, b in pairs if a != b]
    if ch:
        print("%d cut logs: %d changed, %d of them worse; median 3-D closure of the changed %.2f -> %.2f m" %
              (len(pairs), len(ch), sum(b > a for a, b in ch), statistics.median(a for a, _ in ch),
               statistics.median(b for _, b in ch)))


if __name__ == "__main__":
    main()
