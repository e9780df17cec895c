#!/usr/bin/env python3
"""Where the x-io vendor's closure comes from (docs/xio-climb.md, "Round 4").

The vendor's published 82 mm / 421 mm on xio_ngimu_gait come from an offline
pipeline (its README and gait_tracking.py, described here in words): an AHRS
gives the earth-frame acceleration; a sample is "moving" when |a| > 3 m/s^2,
dilated by 100 ms on both sides (the leading side looks 100 ms into the
future); velocity is integrated only while moving, its end value removed as a
linear ramp over each moving period; position is the integral.

This script runs that velocity / position step on footnav's own attitude and
accelerometer bias (`bin/harness replay LOG --out CSV`), so it separates the
attitude from the velocity correction. Four stance definitions:
  vendor  the rule above (|a| > 3 m/s^2, 100 ms margins);
  zupt    footnav's own ZUPT samples (the replay CSV's zupt column);
  zupt+100ms  footnav's ZUPT samples, each stance's first 100 ms dropped;
  zupt-100ms  the same, its last 100 ms dropped (a look-ahead).
It prints the final position (3-D and horizontal closure, height change) for
each log given, next to footnav's.

Note that smoothing alone cannot be what the offline method gains: at the
final sample (in stance) a fixed-interval smoother's estimate equals the
forward filter's under the same model. What differs is the model (a linear
velocity ramp between stance samples) and the stance boundaries.

Usage (Debian's /usr/bin/python3, numpy):
  /usr/bin/python3 scripts/xio_ramp_check.py LOG...
with LOG any log bin/harness reads; bin/harness must be built.
"""
import os
import subprocess
import sys
import tempfile

import numpy as np

HARNESS = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "bin", "harness")
G = 9.80665


def replay(log, tmp):
    """Runs footnav on LOG; returns (raw samples t, f, w in SI) and its trajectory."""
    raw_csv = os.path.join(tmp, "raw.csv")
    traj_csv = os.path.join(tmp, "traj.csv")
    subprocess.run([HARNESS, "convert", log, raw_csv], check=True, stdout=subprocess.DEVNULL)
    subprocess.run([HARNESS, "replay", log, "--quiet", "--out", traj_csv], check=True)
    raw = np.genfromtxt(raw_csv, delimiter=",", skip_header=1)
    tr = np.genfromtxt(traj_csv, delimiter=",", names=True)
    if len(raw) != len(tr):
        sys.exit("%s: %d samples but %d trajectory rows" % (log, len(raw), len(tr)))
    return raw[:, 0], raw[:, 1:4], tr


def c_nb(roll, pitch, yaw):
    """Body-to-navigation DCM, ZYX Euler angles (docs/navigation.md, Strapdown)."""
    cr, sr, cp, sp, cy, sy = (np.cos(roll), np.sin(roll), np.cos(pitch), np.sin(pitch),
                              np.cos(yaw), np.sin(yaw))
    return np.array([[cp * cy, sr * sp * cy - cr * sy, cr * sp * cy + sr * sy],
                     [cp * sy, sr * sp * sy + cr * cy, cr * sp * sy - sr * cy],
                     [-sp, sr * cp, cr * cp]])


def earth_acceleration(f, tr):
    """a_n = C_nb (f_b - b_a) + (0, 0, g), NED; before the alignment ends the
    trajectory's attitude is zero, so its first aligned value is used."""
    i0 = int(np.argmax((tr["roll"] != 0) | (tr["pitch"] != 0)))
    acc = np.empty_like(f)
    for i in range(len(f)):
        j = max(i, i0)
        b = np.array([tr["bax"][j], tr["bay"][j], tr["baz"][j]])
        acc[i] = c_nb(tr["roll"][j], tr["pitch"][j], tr["yaw"][j]) @ (f[i] - b) + (0.0, 0.0, G)
    return acc


def dilate(mask, n, forward):
    """True where any of the next (forward) or previous n samples is True."""
    out = mask.copy()
    for i in range(len(mask)):
        lo, hi = (i, i + n) if forward else (max(i - n, 0), i)
        out[i] = out[i] or mask[lo:hi].any()
    return out


def moving_vendor(acc, rate_hz):
    m = np.linalg.norm(acc, axis=1) > 3.0
    n = int(0.1 * rate_hz)
    return dilate(dilate(m, n, True), n, False)


def moving_zupt(tr, drop_s, rate_hz, at_end=False):
    """Not footnav's ZUPT samples; with drop_s, a ZUPT sample also counts as
    moving unless the drop_s before it (at_end: after it) are ZUPTs too."""
    z = tr["zupt"] > 0.5
    n = int(round(drop_s * rate_hz))
    keep = z.copy()
    for i in range(len(z)):
        window = z[i:i + n + 1] if at_end else z[max(i - n, 0):i + 1]
        if z[i] and not window.all():
            keep[i] = False
    return ~keep


def ramp_position(t, acc, moving):
    """Velocity integrated while moving, the end value of each moving period
    removed as a linear ramp over it; returns the final position."""
    dt = np.diff(t, prepend=t[0])
    vel = np.zeros_like(acc)
    for i in range(1, len(t)):
        if moving[i]:
            vel[i] = vel[i - 1] + dt[i] * acc[i]
    i = 0
    n = len(t)
    while i < n:
        if not moving[i]:
            i += 1
            continue
        s = i
        while i < n and moving[i]:
            i += 1
        e = i - 1
        if e > s:
            frac = (t[s:e + 1] - t[s]) / (t[e] - t[s]) if t[e] > t[s] else np.zeros(e - s + 1)
            vel[s:e + 1] -= vel[s] + np.outer(frac, vel[e] - vel[s])
    return np.sum(dt[:, None] * vel, axis=0)


def line(name, p):
    return "%-10s 3-D %.3f m, horizontal %.3f m, height %+.3f m" % (
        name, np.linalg.norm(p), np.linalg.norm(p[:2]), -p[2])


def main():
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    for log in sys.argv[1:]:
        with tempfile.TemporaryDirectory() as tmp:
            t, f, tr = replay(log, tmp)
        rate = 1.0 / np.median(np.diff(t)[np.diff(t) > 0])
        acc = earth_acceleration(f, tr)
        print("%s (%.0f Hz)" % (log, rate))
        print("  " + line("footnav", np.array([tr["x"][-1], tr["y"][-1], tr["z"][-1]])))
        print("  " + line("vendor", ramp_position(t, acc, moving_vendor(acc, rate))))
        print("  " + line("zupt", ramp_position(t, acc, moving_zupt(tr, 0.0, rate))))
        print("  " + line("zupt+100ms", ramp_position(t, acc, moving_zupt(tr, 0.1, rate))))
        print("  " + line("zupt-100ms", ramp_position(t, acc, moving_zupt(tr, 0.1, rate, True))))


if __name__ == "__main__":
    main()
