#!/usr/bin/env python3
"""Independent reference for `harness eval`'s per-stride table (the
footprint walks and the vicon trials; docs/results.md): from a trajectory
written by `harness replay --out` and the walk's truth file
(strideIndex, timestamp, x, y), compute with numpy what the row must say,
and compare with the row eval wrote.

The definitions (docs/harness.md, "eval"): the truth's first stride is the
reference, both start there (truth x_i - x_0 against estimate p(k_i) - p(k_0),
horizontal); the statistics count the strides after it; the measured path is
the sum of the distances between consecutive truth footprints up to the last
scored stride; final = the last stride's error, final % = 100 final / path;
the median of an even count is the mean of the two middle values.

usage: eval_stride_ref.py TRAJ.csv TRUTH.csv 'ROW'   (ROW: the table row)
exit 0 when every figure of the row matches within its printed precision.
"""
import sys
import numpy as np


def main():
    traj, truth, row = sys.argv[1], sys.argv[2], sys.argv[3]
    t = np.genfromtxt(traj, delimiter=",", names=True)
    g = np.loadtxt(truth, delimiter=",", skiprows=1)
    idx = np.rint(g[:, 0]).astype(int)
    gx, gy = g[:, 2], g[:, 3]
    px, py = t["x"][idx], t["y"][idx]
    ex = (px - px[0]) - (gx - gx[0])
    ey = (py - py[0]) - (gy - gy[0])
    e = np.hypot(ex, ey)[1:]
    path = np.sum(np.hypot(np.diff(gx), np.diff(gy)))
    want = [len(e), path, np.median(e), np.sqrt(np.mean(e * e)), e[-1], 100.0 * e[-1] / path]
    f = [c.strip() for c in row.strip().strip("|").split("|")]
    got = [float(v) for v in f[1:7]]
    half = [0.0, 0.05, 0.0005, 0.0005, 0.0005, 0.005]  # half a printed digit
    names = ["strides", "path", "median", "rms", "final", "final %"]
    ok = True
    for n, w, v, h in zip(names, want, got, half):
        if abs(w - v) > h + 1e-4:
            print(f"{n}: eval {v}, reference {w:.6f}")
            ok = False
    print(("match: " if ok else "MISMATCH: ") + " ".join(f"{n} {w:.4f}" for n, w in zip(names, want)))
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
