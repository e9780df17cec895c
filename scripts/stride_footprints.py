#!/usr/bin/env python3
"""Stride lengths of `harness replay --strides` against the measured
footprints of the pyshoe footprint walks (docs/harness.md, "replay",
"Stride CSV").

Each walk is replayed with the default configuration; each row of the stride
CSV is matched to the footprints whose stride sample (`*_strides_gcp.csv`:
stride index = sample index, its time in `timestamp`) lies in the stance
before its swing and in the stance after it: from the previous row's
swing_end_s to the row's foot_off_s, and from its swing_end_s to the next
row's foot_off_s (pyshoe's stride sample is the end of its own stance, up to
some 40 ms after the detector's swing_start_s, its first sample in motion,
and before the foot leaves the ground); a row with exactly one footprint in
each is compared when the two footprints are consecutive (a row between two that
are not spans strides the detector missed: counted, not compared): length_m
against the horizontal distance between the two footprints measured with a
ruler (`*_gcp_wcf_measured.csv`; a distance, so the frame does not matter).
Prints per walk the footprints, the rows, those spanning, those compared,
the median of length_m - measured, the median, 90th percentile and RMS of
its magnitude, and the same over all walks (STRIDE_DEBUG=1: every error).

Usage (from the repository root, after `make`):
  /usr/bin/python3 scripts/stride_footprints.py [DATA_DIR]
  (DATA_DIR: ../shared/data/pyshoe_vicon_llio/own_3dmgx5_footprints by default)
"""
import csv
import glob
import os
import subprocess
import sys
import tempfile

import numpy as np


def main():
    d = sys.argv[1] if len(sys.argv) > 1 else "../shared/data/pyshoe_vicon_llio/own_3dmgx5_footprints"
    logs = sorted(glob.glob(os.path.join(d, "*_imu.csv")))
    if not logs:
        sys.exit("no *_imu.csv in " + d)
    allerr = []
    print("walk  footprints  rows  spanning  compared  median_err_m  median_abs_err_m  p90_abs_err_m  rms_err_m  "
          "median_measured_m")
    with tempfile.TemporaryDirectory() as tmp:
        for log in logs:
            base = log[: -len("_imu.csv")]
            out = os.path.join(tmp, "s.csv")
            subprocess.run(["bin/harness", "replay", log, "--strides", out, "--quiet"], check=True)
            rows = list(csv.DictReader(open(out)))
            idx_t = {}
            for r in csv.DictReader(open(base + "_strides_gcp.csv")):
                idx_t[int(float(r["strideIndex"]))] = float(r["timestamp"])
            fp = []
            for r in csv.DictReader(open(base + "_gcp_wcf_measured.csv")):
                i = int(float(r["strideIndex"]))
                fp.append((idx_t[i], float(r["gcp_wcf_x_m"]), float(r["gcp_wcf_y_m"])))
            fp.sort()
            ft = np.array([p[0] for p in fp])
            err, meas, span = [], [], 0
            for k, r in enumerate(rows):
                if r["length_m"] == "":
                    continue
                lo = float(rows[k - 1]["swing_end_s"]) if k > 0 else -np.inf
                hi = float(rows[k + 1]["foot_off_s"]) if k + 1 < len(rows) else np.inf
                before = np.nonzero((ft >= lo) & (ft < float(r["foot_off_s"])))[0]
                after = np.nonzero((ft >= float(r["swing_end_s"])) & (ft < hi))[0]
                if len(before) != 1 or len(after) != 1:
                    continue
                if after[0] != before[0] + 1:
                    span += 1  # the row spans footprints the detector took for one stride
                    continue
                a, b = fp[before[0]], fp[after[0]]
                m = float(np.hypot(b[1] - a[1], b[2] - a[2]))
                err.append(float(r["length_m"]) - m)
                meas.append(m)
            if os.environ.get("STRIDE_DEBUG"):
                print(np.round(err, 3).tolist())
            e = np.array(err)
            allerr += err
            name = os.path.basename(base).replace("SensorConnectData_", "")
            print("%4s  %10d  %4d  %8d  %8d  %12.3f  %16.3f  %13.3f  %9.3f  %17.3f" % (
                name, len(fp), len(rows), span, len(e), np.median(e), np.median(np.abs(e)),
                np.percentile(np.abs(e), 90), np.sqrt(np.mean(e ** 2)), np.median(meas)))
    e = np.array(allerr)
    print("all                             %8d  %12.3f  %16.3f  %13.3f  %9.3f" % (
        len(e), np.median(e), np.median(np.abs(e)), np.percentile(np.abs(e), 90), np.sqrt(np.mean(e ** 2))))


if __name__ == "__main__":
    main()
