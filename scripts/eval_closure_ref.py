#!/usr/bin/env python3
"""Independent check of `harness eval`'s return-to-start table of the
openshoe_gx2 walks (docs/results.md): from the figures of each row and the
walks' trajectories (`harness replay --out`), recompute with numpy what the
row and the summary line under the table must say.

Definitions (docs/harness.md, "replay" summary; docs/results.md): the error is
that of the last stance mid-point from the first; horizontal = its x-y part,
3-D = sqrt(horizontal^2 + vertical^2); the percentages divide by the
step-to-step path through the stance mid-points (3-D, the "path (m)"
column); vertical is the height change, up positive, i.e. -(z_end - z_start)
in the z-down navigation frame: a foot that ends above its start (z_end < 0
with the start at z = 0) has a positive vertical. The summary line gives
the medians of the rows' horizontal %, 3-D %, vertical and path, and the
worst (largest) 3-D %.

usage: eval_closure_ref.py RESULTS.md [WALK=TRAJ.csv ...]
exit 0 when every figure matches within its printed precision.
"""
import re
import sys
import numpy as np


def main():
    md = open(sys.argv[1]).read().split("## openshoe_gx2", 1)[1].split("\n## ", 1)[0]
    trajs = dict(a.split("=", 1) for a in sys.argv[2:])
    rows = [[c.strip() for c in l.strip().strip("|").split("|")] for l in md.splitlines()
            if l.startswith("| Measurement")]
    bad = []
    v = {k: [] for k in ("path", "h", "hp", "d3", "d3p", "vert")}
    for r in rows:
        name = r[0]
        path, h, hp, d3, d3p, vert = (float(x) for x in r[1:7])
        for k, x in zip(v, (path, h, hp, d3, d3p, vert)):
            v[k].append(x)
        # printed: path %.2f, h %.3f, % %.2f, 3-D %.3f, vertical %+.3f
        if abs(d3 - np.hypot(h, vert)) > 0.0016:
            bad.append(f"{name}: 3-D {d3} m, sqrt(h^2 + v^2) = {np.hypot(h, vert):.4f}")
        for lab, m, p in (("horizontal", h, hp), ("3-D", d3, d3p)):
            want = 100.0 * m / path
            if abs(p - want) > 0.005 + 100.0 * 0.0005 / path + want * 0.005 / path:
                bad.append(f"{name}: {lab} {p} %, 100 x {m} / {path} = {want:.4f}")
        if name in trajs:
            t = np.genfromtxt(trajs[name], delimiter=",", names=True)
            up = -(t["z"][-1] - t["z"][0])
            if abs(vert - up) > 0.02:
                bad.append(f"{name}: vertical {vert:+.3f} m, trajectory's height change -(z_end - z_start) {up:+.4f}")
    m = re.search(r"Median horizontal ([-0-9.]+) %.*?median 3-D ([-0-9.]+) %.*?worst 3-D ([-0-9.]+) %.*?"
                  r"median vertical ([-+0-9.]+) m, median path ([-0-9.]+) m", md, re.S)
    if not rows or m is None:
        print("no gx2 rows or no summary line")
        return 1
    got = [float(x) for x in m.groups()]
    want = [np.median(v["hp"]), np.median(v["d3p"]), max(v["d3p"]), np.median(v["vert"]), np.median(v["path"])]
    tol = [0.0101, 0.0101, 0.0051, 0.0011, 0.056]  # the rows' and the line's rounding (half a digit each)
    for lab, g, w, e in zip(("median horizontal %", "median 3-D %", "worst 3-D %", "median vertical", "median path"),
                            got, want, tol):
        if abs(g - w) > e:
            bad.append(f"summary {lab}: {g}, median of the rows {w:.4f}")
    for b in bad:
        print(b)
    print(f"{len(rows)} rows, {len(trajs)} trajectories: " + ("match" if not bad else "MISMATCH"))
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
