#!/usr/bin/python3
"""Measure the foot's landing transient ("settling") on real walks.

docs/navigation.md, "The landing": the settling state's standard deviation
and time constant (fnav_ukf.h) come from this measurement, not from the
closure of any walk.

For each log:
1. replay it with footnav's default filter without the settling state
   (`--param settle=0`), which gives the attitude, the biases and the lever
   at every sample, and convert the log to CSV for the raw readings;
2. at each stance onset (the stance flag going 0 -> 1), start from the
   filter's velocity at the last swing sample (no ZUPT has touched it yet)
   and integrate the raw specific force freely, v' = v + dt (C_nb (f - b_a)
   + g_n) (trapezoid), for D seconds (default 0.15 s), ignoring the ZUPTs;
3. form the pivot velocity v - C_nb ((w - b_g) x r), the quantity the ZUPT
   measures, and fit on each stance i and axis of n
   v_i(t) = p_i + a_i exp(-t / tau), with tau shared by all stances of the
   log (p_i: an INS velocity error, which persists; a_i: the transient,
   which decays); tau on a grid of 5-500 ms.
Prints, per log and axis (n frame: x, y horizontal, z down), tau, the RMS
of a_i (the settling's standard deviation at the onset), the median a_i and
the number of stances at least 0.8 D long.

Run: /usr/bin/python3 scripts/settle_measure.py [--window D] LOG...
(bin/harness must be built; about a second per log)
"""
import os
import subprocess
import sys
import tempfile

import numpy as np

HARNESS = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "bin", "harness")
TAUS = np.exp(np.linspace(np.log(0.005), np.log(0.5), 60))
GRAVITY = 9.80665


def dcm(roll, pitch, yaw):
    """C_nb = Rz(yaw) Ry(pitch) Rx(roll) (docs/frames.md)."""
    cr, sr, cp, sp, cy, sy = np.cos(roll), np.sin(roll), np.cos(pitch), np.sin(pitch), np.cos(yaw), np.sin(yaw)
    return np.array([[cy * cp, cy * sp * sr - sy * cr, cy * sp * cr + sy * sr],
                     [sy * cp, sy * sp * sr + cy * cr, sy * sp * cr - cy * sr],
                     [-sp, cp * sr, cp * cr]])


def load(log):
    with tempfile.TemporaryDirectory() as td:
        subprocess.run([HARNESS, "replay", log, "--quiet", "--param", "settle=0", "--out", td + "/t.csv"], check=True,
                       stderr=subprocess.DEVNULL)
        subprocess.run([HARNESS, "convert", log, td + "/raw.csv"], check=True, stdout=subprocess.DEVNULL,
                       stderr=subprocess.DEVNULL)
        tr = np.genfromtxt(td + "/t.csv", delimiter=",", names=True)
        raw = np.genfromtxt(td + "/raw.csv", delimiter=",", names=True)
    if len(tr) != len(raw):
        sys.exit("%s: %d frames for %d samples" % (log, len(tr), len(raw)))
    return tr, raw


def onsets(tr, raw, window):
    """Pivot velocity over the first `window` seconds of each stance, freely integrated."""
    n = len(tr)
    st = tr["stance"].astype(int)
    aligned = tr["P_vel_x"] > 0.0  # frames before the alignment carry a zero covariance
    segs = []
    for i0 in np.flatnonzero((st[1:] == 1) & (st[:-1] == 0)) + 1:
        if i0 < 2 or not aligned[i0 - 1]:
            continue
        t0 = tr["t"][i0]
        v = np.array([tr["vx"][i0 - 1], tr["vy"][i0 - 1], tr["vz"][i0 - 1]])
        a_prev = None
        ts, vs = [], []
        k = i0 - 1
        while k + 1 < n and st[k + 1] == 1 and tr["t"][k + 1] - t0 < window:
            k += 1
            dt = tr["t"][k] - tr["t"][k - 1]
            C = dcm(tr["roll"][k], tr["pitch"][k], tr["yaw"][k])
            ba = np.array([tr["bax"][k], tr["bay"][k], tr["baz"][k]])
            f = np.array([raw["ax"][k], raw["ay"][k], raw["az"][k]]) - ba
            acc = C @ f + np.array([0.0, 0.0, GRAVITY])
            if a_prev is None:
                Cp = dcm(tr["roll"][k - 1], tr["pitch"][k - 1], tr["yaw"][k - 1])
                a_prev = Cp @ (np.array([raw["ax"][k - 1], raw["ay"][k - 1], raw["az"][k - 1]]) - ba) + \
                    np.array([0.0, 0.0, GRAVITY])
            v = v + 0.5 * dt * (acc + a_prev)
            a_prev = acc
            w = np.array([raw["gx"][k] - tr["bgx"][k], raw["gy"][k] - tr["bgy"][k], raw["gz"][k] - tr["bgz"][k]])
            r = np.array([tr["lever_x"][k], tr["lever_y"][k], tr["lever_z"][k]])
            ts.append(tr["t"][k] - t0)
            vs.append(v - C @ np.cross(w, r))
        if ts and ts[-1] >= 0.8 * window:
            segs.append((np.array(ts), np.array(vs)))
    return segs


def fit(segs, axis):
    """(tau, amplitudes) of p_i + a_i exp(-t/tau), tau shared, least squares."""
    best = None
    for tau in TAUS:
        sse, amps = 0.0, []
        for t, v in segs:
            A = np.column_stack([np.ones_like(t), np.exp(-t / tau)])
            coef = np.linalg.lstsq(A, v[:, axis], rcond=None)[0]
            sse += float(np.sum((A @ coef - v[:, axis]) ** 2))
            amps.append(coef[1])
        if best is None or sse < best[0]:
            best = (sse, tau, np.array(amps))
    return best[1], best[2]


def main():
    args = sys.argv[1:]
    window = 0.15
    if len(args) >= 2 and args[0] == "--window":
        window = float(args[1])
        args = args[2:]
    if not args:
        sys.exit(__doc__)
    print("log | stances | axis: tau (ms), RMS a (m/s), median a (m/s); n frame, z down")
    for log in args:
        tr, raw = load(log)
        segs = onsets(tr, raw, window)
        if len(segs) < 5:
            print("%s | %d | too few stances of %.0f ms" % (os.path.basename(log), len(segs), 1e3 * window))
            continue
        cols = []
        for ax, name in ((2, "z"), (0, "x"), (1, "y")):
            tau, a = fit(segs, ax)
            cols.append("%s: %.0f, %.4f, %+.4f" % (name, 1e3 * tau, np.sqrt(np.mean(a ** 2)), np.median(a)))
        print("%s | %d | %s" % (os.path.basename(log), len(segs), " | ".join(cols)), flush=True)


main()
