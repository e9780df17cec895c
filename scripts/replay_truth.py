#!/usr/bin/python3
"""A replay's trajectory against the simulator's truth, in the filter's
frame (docs/simulator.md, "Comparing harness replay with the truth").

  /usr/bin/python3 scripts/replay_truth.py REPLAY.csv TRUTH.csv [--truth-yaw]

REPLAY.csv is `harness replay LOG --out REPLAY.csv`, TRUTH.csv the
`harness sim ... --truth TRUTH.csv` of the same log. The filter's n frame
has its origin where the sensor was at the alignment and x along the
sensor's heading then; the truth is moved there as `montecarlo` does it
(harness/hx_mc.c): at the replay's first aligned row, the truth's position
p0 is subtracted and the truth is turned about z by the heading between the
two frames, psi = yaw of q_est (x) q_true^-1 (q_est from the replay's roll,
pitch, yaw; q_true the truth's qw..qz), so p_filter = Rz(psi) (p - p0).
Rows are paired on t (nominal tick = round(t * rate), so dropped samples
and stamp jitter do no harm). Prints psi and the horizontal and vertical
error of the last row and the largest over the trajectory.

--truth-yaw turns by minus the truth's own ZYX yaw instead (the recipe the
document gave until 2026-12-06): the same up to the alignment's tilt error
for most mountings, wrong where the yaw is undefined (pitch +-90 deg).
"""
import sys

import numpy as np


def quat_mul(a, b):
    return np.array([
        a[0] * b[0] - a[1] * b[1] - a[2] * b[2] - a[3] * b[3],
        a[0] * b[1] + a[1] * b[0] + a[2] * b[3] - a[3] * b[2],
        a[0] * b[2] - a[1] * b[3] + a[2] * b[0] + a[3] * b[1],
        a[0] * b[3] + a[1] * b[2] - a[2] * b[1] + a[3] * b[0],
    ])


def quat_zyx(roll, pitch, yaw):
    """q_nb of ZYX Euler angles: Rz(yaw) Ry(pitch) Rx(roll)."""
    qx = np.array([np.cos(roll / 2), np.sin(roll / 2), 0.0, 0.0])
    qy = np.array([np.cos(pitch / 2), 0.0, np.sin(pitch / 2), 0.0])
    qz = np.array([np.cos(yaw / 2), 0.0, 0.0, np.sin(yaw / 2)])
    return quat_mul(qz, quat_mul(qy, qx))


def main(argv):
    args = [a for a in argv if not a.startswith("--")]
    if len(args) != 2 or any(a not in ("--truth-yaw",) for a in argv if a.startswith("--")):
        sys.exit(__doc__)
    rep = np.genfromtxt(args[0], delimiter=",", names=True)
    tru = np.genfromtxt(args[1], delimiter=",", names=True)
    rate = 1.0 / np.median(np.diff(tru["t"]))
    seq = np.rint(rep["t"] * rate).astype(int)
    keep = (rep["aligned"] == 1) & (seq >= 0) & (seq < len(tru))
    if not keep.any():
        sys.exit("replay_truth: no aligned row in " + args[0])
    rep, seq = rep[keep], seq[keep]
    if not np.array_equal(np.rint(tru["seq"]).astype(int), np.arange(len(tru))):
        sys.exit("replay_truth: the truth's seq is not 0, 1, 2, ...")
    t0 = tru[seq[0]]
    p0 = np.array([t0["px"], t0["py"], t0["pz"]])
    if "--truth-yaw" in argv:
        psi = -t0["yaw"]
    else:
        q_est = quat_zyx(rep["roll"][0], rep["pitch"][0], rep["yaw"][0])
        q_inv = np.array([t0["qw"], -t0["qx"], -t0["qy"], -t0["qz"]])
        d = quat_mul(q_est, q_inv)
        psi = np.arctan2(2 * (d[0] * d[3] + d[1] * d[2]), 1 - 2 * (d[2] ** 2 + d[3] ** 2))
    c, s = np.cos(psi), np.sin(psi)
    dx = tru["px"][seq] - p0[0]
    dy = tru["py"][seq] - p0[1]
    ex = rep["x"] - (c * dx - s * dy)
    ey = rep["y"] - (s * dx + c * dy)
    ez = rep["z"] - (tru["pz"][seq] - p0[2])
    eh = np.hypot(ex, ey)
    print("aligned at %.3f s, heading between the frames %.3f deg" % (t0["t"], np.degrees(psi)))
    print("last row t %.3f s: horizontal error %.4f m, vertical %.4f m" % (rep["t"][-1], eh[-1], abs(ez[-1])))
    print("largest: horizontal %.4f m, vertical %.4f m" % (eh.max(), np.abs(ez).max()))


if __name__ == "__main__":
    main(sys.argv[1:])
