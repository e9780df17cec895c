#!/usr/bin/env python3
"""How the age of the initial alignment sets a walk's closure
(docs/navigation.md, "Initial alignment", the renewal before the first stride).

1. The still gyro mean in 1 s windows over the first seconds of the log: the
   power-on drift of the bias (deg/s).
2. The same log replayed with its first 0, 2, ..., N s cut off, with the
   renewal off (--param realign_min_s=0), so that the 5 s alignment ends
   later each time: the return-to-start error (horizontal, 3-D).
3. With --delays, the gyro shifted against the accelerometer by each delay
   (linear interpolation in time; positive: the gyro is taken to lag), with
   the default configuration: the closure and the RMS of the INS velocity
   at the last swing sample before each stance (the onset velocity).

Usage (from the repository root, after `make`):
  /usr/bin/python3 scripts/align_age.py ../shared/data/xio_ngimu_gait/short_walk.csv [--until 14] [--cuts 0,2,4,6,8,10]
      [--delays=-5,-2.5,0,2.5,5]
"""
import argparse
import json
import os
import subprocess
import sys
import tempfile

import numpy as np

H = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "bin", "harness")


def replay(csv, tmp, extra):
    out, js = os.path.join(tmp, "tr.csv"), os.path.join(tmp, "r.json")
    r = subprocess.run([H, "replay", csv, "--out", out, "--json", js] + extra, capture_output=True, text=True)
    if r.returncode != 0:
        sys.exit("replay failed: " + r.stderr.strip())
    with open(js) as f:
        return json.load(f), np.genfromtxt(out, delimiter=",", names=True)


def write(path, t, cols):
    np.savetxt(path, np.column_stack([t] + cols), delimiter=",", header="t,ax,ay,az,gx,gy,gz", comments="",
               fmt="%.9g")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("log")
    ap.add_argument("--until", type=float, default=14.0, help="window means up to this time, s")
    ap.add_argument("--cuts", default="0,2,4,6,8,10")
    ap.add_argument("--delays", default="", help="gyro delays to try, ms (comma-separated)")
    a = ap.parse_args()
    with tempfile.TemporaryDirectory() as tmp:
        base = os.path.join(tmp, "base.csv")
        subprocess.run([H, "convert", a.log, base, "--to", "csv"], check=True, capture_output=True)
        d = np.genfromtxt(base, delimiter=",", names=True)
        t = d["t"] - d["t"][0]
        cols = [d[c] for c in ("ax", "ay", "az", "gx", "gy", "gz")]
        print("gyro mean in 1 s windows (deg/s), x y z:")
        for w in range(int(a.until)):
            m = (t >= w) & (t < w + 1)
            if m.any():
                print("  %3d-%3d s  %8.4f %8.4f %8.4f" % ((w, w + 1) + tuple(np.degrees(c[m].mean()) for c in cols[3:])))
        print("first seconds cut, renewal off (--param realign_min_s=0): return-to-start h / 3-D (m)")
        for c in (float(x) for x in a.cuts.split(",")):
            m = t >= c
            path = os.path.join(tmp, "cut.csv")
            write(path, d["t"][m], [x[m] for x in cols])
            j, _ = replay(path, tmp, ["--param", "realign_min_s=0"])
            print("  cut %5.1f s: %.3f / %.3f" % (c, j["return_error_h_m"], j["return_error_3d_m"]))
        if a.delays:
            print("gyro delayed against the accelerometer (default configuration):")
            tu, iu = np.unique(d["t"], return_index=True)
            for dl_ms in (float(x) for x in a.delays.split(",")):
                g = [np.interp(d["t"] + dl_ms * 1e-3, tu, c[iu]) for c in cols[3:]]
                path = os.path.join(tmp, "delay.csv")
                write(path, d["t"], cols[:3] + g)
                j, tr = replay(path, tmp, [])
                z = tr["zupt"].astype(int)
                on = np.where((z[1:] == 1) & (z[:-1] == 0))[0]
                vh = np.sqrt((tr["vx"][on] ** 2 + tr["vy"][on] ** 2).mean())
                vz = np.sqrt((tr["vz"][on] ** 2).mean())
                print("  %+5.1f ms: 3-D %.3f m, vertical %+.3f m; onset velocity RMS horizontal %.3f, vertical %.3f m/s"
                      % (dl_ms, j["return_error_3d_m"], j["vertical_drift_m"], vh, vz))


if __name__ == "__main__":
    main()
